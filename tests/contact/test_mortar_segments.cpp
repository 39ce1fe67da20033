// Segment-based integration points of a slave facet (contact/mortar_segments.hpp): the pieces tile
// the facet, and their rules integrate the mortar integrands (polynomials on each piece, kinked
// at the master nodes) exactly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "contact/mortar_segments.hpp"
#include "contact/patch_test.hpp"
#include "contact/surface_to_surface.hpp"
#include "fixtures/deck_fixture.hpp"

namespace inpact::test {
namespace {

using contact::Facet;
using contact::FacetShape;
using contact::Polygon;
using contact::QuadPoint;
using contact::Vec3;

Facet make_facet(FacetShape shape, std::initializer_list<std::int32_t> nodes) {
  Facet f;
  f.shape = shape;
  f.n_nodes = static_cast<std::uint8_t>(nodes.size());
  std::size_t i = 0;
  for (std::int32_t n : nodes) f.nodes[i++] = n;
  return f;
}

double weight_sum(const std::vector<QuadPoint>& rule) {
  double s = 0.0;
  for (const QuadPoint& q : rule) s += q.weight;
  return s;
}

TEST(MortarSegments, SegmentRuleIntegratesAKinkedFunctionExactly) {
  // A hat function with its kink at ξ = 0.3 (a master node over the slave edge): ∫_{−1}^{1} =
  // ½ (1.3 + 0.7) × 1 = 1; a plain 6-point Gauss rule is off by 1e-3 here.
  auto hat = [](double xi) { return xi < 0.3 ? (xi + 1) / 1.3 : (1 - xi) / 0.7; };
  std::vector<double> breaks{0.3, -1.0 + 1e-9, 1.0};  // the near-end breaks are dropped
  std::vector<QuadPoint> rule;
  EXPECT_EQ(contact::segment_rule(breaks, 2, 6, rule), 2);
  EXPECT_EQ(rule.size(), 6u);  // 3 points per segment: the plain rule's work
  double integral = 0.0, cubic = 0.0;
  for (const QuadPoint& q : rule) {
    integral += q.weight * hat(q.xi);
    cubic += q.weight * (q.xi < 0.3 ? q.xi * q.xi * q.xi : 1 - q.xi);
  }
  EXPECT_NEAR(integral, 1.0, 1e-15);
  EXPECT_NEAR(cubic, (std::pow(0.3, 4) - 1) / 4 + (0.7 - (1 - 0.09) / 2), 1e-15);
  double plain = 0.0;
  for (const QuadPoint& q : contact::facet_rule(FacetShape::Line2, 6)) plain += q.weight * hat(q.xi);
  EXPECT_GT(std::abs(plain - 1.0), 1e-4);
}

TEST(MortarSegments, ClippedMasterCellsTileTheSlaveFace) {
  // A 3 × 3 grid of cells over [−1.3, 1.7]² covers the square [−1, 1]² (area 4) and the unit
  // triangle (area ½) in pieces whose areas sum to the domain's.
  for (FacetShape shape : {FacetShape::Quad4, FacetShape::Tri3}) {
    double sum = 0.0, weights = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double x0 = -1.3 + i, y0 = -1.3 + j;
        const Polygon cell = contact::clip_to_domain({{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}}, shape);
        if (cell.size() < 3) continue;
        sum += contact::polygon_area(cell);
        std::vector<QuadPoint> rule;
        ASSERT_TRUE(contact::polygon_rule(cell, 3, rule));
        weights += weight_sum(rule);
      }
    const double area = shape == FacetShape::Quad4 ? 4.0 : 0.5;
    EXPECT_NEAR(sum, area, 1e-14);
    EXPECT_NEAR(weights, area, 1e-14);
  }
  // A cell outside the domain clips to nothing.
  EXPECT_TRUE(contact::clip_to_domain({{2, 2}, {3, 2}, {3, 3}}, FacetShape::Quad4).empty());
}

TEST(MortarSegments, PolygonRuleIsExactForDegreeFour) {
  // ∫ ξ² η² over [a, b] × [c, d] clipped from a larger rectangle: (b³ − a³)(d³ − c³)/9.
  const Polygon cell = contact::clip_to_domain({{-0.4, -2}, {3, -2}, {3, 0.5}, {-0.4, 0.5}}, FacetShape::Quad4);
  std::vector<QuadPoint> rule;
  ASSERT_TRUE(contact::polygon_rule(cell, 3, rule));
  double integral = 0.0;
  for (const QuadPoint& q : rule) integral += q.weight * q.xi * q.xi * q.eta * q.eta;
  const double a = -0.4, b = 1, c = -1, d = 0.5;
  EXPECT_NEAR(integral, (b * b * b - a * a * a) * (d * d * d - c * c * c) / 9, 1e-15);
}

// The symmetric triangle rules integrate every monomial ξ^i η^j of their degree over the unit
// triangle exactly (i! j! / (i + j + 2)!), with points inside and positive weights, in fewer
// points than the collapsed rule of the same degree.
TEST(MortarSegments, SymmetricTriangleRulesAreExactToTheirDegree) {
  const std::array<std::pair<int, std::size_t>, 3> expected{{{2, 3}, {4, 6}, {6, 12}}};  // degree, points
  for (const auto& [degree, points] : expected) {
    const auto rule = contact::symmetric_triangle_rule(degree);
    ASSERT_EQ(rule.size(), points) << "degree " << degree;
    EXPECT_LT(rule.size(), contact::facet_rule(FacetShape::Tri3, degree / 2 + 1).size());
    for (const QuadPoint& q : rule) {
      EXPECT_GT(q.weight, 0.0);
      EXPECT_GT(q.xi, 0.0);
      EXPECT_GT(q.eta, 0.0);
      EXPECT_LT(q.xi + q.eta, 1.0);
    }
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j) {
        double sum = 0.0;
        for (const QuadPoint& q : rule) sum += q.weight * std::pow(q.xi, i) * std::pow(q.eta, j);
        const double exact = std::tgamma(i + 1.0) * std::tgamma(j + 1.0) / std::tgamma(i + j + 3.0);
        EXPECT_NEAR(sum, exact, 4e-16) << "degree " << degree << ": xi^" << i << " eta^" << j;
      }
  }
  EXPECT_EQ(contact::symmetric_triangle_rule(1).size(), 3u);
  EXPECT_TRUE(contact::symmetric_triangle_rule(8).empty());
}

// A pentagonal cell's fan: 6 points a triangle for n = 3 (the collapsed rule's 9), the same
// integral of a degree-4 polynomial as the collapsed rule's fan.
TEST(MortarSegments, PolygonRuleFansWithTheSymmetricRule) {
  const Polygon pentagon{{-0.9, -0.8}, {0.7, -0.6}, {0.9, 0.3}, {0.4, 0.9}, {-0.5, 0.6}};
  std::vector<QuadPoint> fan;
  ASSERT_TRUE(contact::polygon_rule(pentagon, 3, fan));
  EXPECT_EQ(fan.size(), 3u * 6u);
  double by_symmetric = 0.0, by_collapsed = 0.0;
  auto f = [](double x, double y) { return x * x * y * y - 3 * x * x * x * y + 2 * y * y * y - x + 0.5; };
  for (const QuadPoint& q : fan) by_symmetric += q.weight * f(q.xi, q.eta);
  const auto collapsed = contact::facet_rule(FacetShape::Tri3, 3);
  for (std::size_t i = 1; i + 1 < pentagon.size(); ++i) {
    const double e1x = pentagon[i][0] - pentagon[0][0], e1y = pentagon[i][1] - pentagon[0][1];
    const double e2x = pentagon[i + 1][0] - pentagon[0][0], e2y = pentagon[i + 1][1] - pentagon[0][1];
    const double twice = e1x * e2y - e1y * e2x;
    for (const QuadPoint& q : collapsed)
      by_collapsed += q.weight * twice *
                      f(pentagon[0][0] + q.xi * e1x + q.eta * e2x, pentagon[0][1] + q.xi * e1y + q.eta * e2y);
  }
  EXPECT_NEAR(by_symmetric, by_collapsed, 1e-14);
}

TEST(MortarSegments, QuadRuleIsExactOnAGeneralQuadrilateral) {
  // A trapezoid (not a parallelogram): the mapped 3 × 3 rule is exact to total degree 4, like
  // the fan of two triangles with the 6-point symmetric rule; both against each other.
  const Polygon trapezoid{{-0.9, -0.8}, {0.7, -0.6}, {0.4, 0.9}, {-0.5, 0.6}};
  std::vector<QuadPoint> quad, fan;
  ASSERT_TRUE(contact::quad_rule(trapezoid, 3, quad));
  ASSERT_TRUE(contact::polygon_rule(trapezoid, 3, fan));
  EXPECT_EQ(quad.size(), 9u);
  auto integrate = [](const std::vector<QuadPoint>& r, auto&& f) {
    double s = 0.0;
    for (const QuadPoint& q : r) s += q.weight * f(q.xi, q.eta);
    return s;
  };
  auto f = [](double x, double y) { return x * x * y * y + x * x * x - 2 * x * y + 1; };
  EXPECT_NEAR(integrate(quad, f), integrate(fan, f), 1e-14);
  EXPECT_NEAR(weight_sum(quad), contact::polygon_area(trapezoid), 1e-14);
  // A folded quadrilateral (a non-convex corner) is refused.
  EXPECT_FALSE(contact::quad_rule({{-1, -1}, {1, -1}, {-0.5, -0.5}, {-1, 1}}, 3, quad));
}

TEST(MortarSegments, ExtendedParamReachesBeyondTheDomain) {
  // A bilinear, non-parallelogram planar quad; points off its plane, just outside its domain
  // (the closest point to round-off) and far outside (a bounded, finite estimate).
  const std::vector<Vec3> x{{0, 0, 0}, {2, 0, 0}, {2.3, 1.8, 0}, {0, 1.5, 0}, {2.2, -0.2, 0.3}, {30, -40, 1}};
  const Facet f = make_facet(FacetShape::Quad4, {0, 1, 2, 3});
  std::array<double, 2> xi{};
  ASSERT_TRUE(contact::extended_param(f, x, x[4], xi));
  const auto g = contact::facet_geometry(f, x, xi[0], xi[1]);
  EXPECT_NEAR(g.x[0], 2.2, 1e-12);
  EXPECT_NEAR(g.x[1], -0.2, 1e-12);
  EXPECT_GT(xi[0], 1.0);
  EXPECT_LT(xi[1], -1.0);
  ASSERT_TRUE(contact::extended_param(f, x, x[5], xi));
  EXPECT_TRUE(std::isfinite(xi[0]) && std::isfinite(xi[1]));
  // A parallelogram is affine: exact in the first step, however far.
  const std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {2.5, 1.5, 0}, {0.5, 1.5, 0}, {30, -40, 1}};
  ASSERT_TRUE(contact::extended_param(f, p, p[4], xi));
  const auto gp = contact::facet_geometry(f, p, xi[0], xi[1]);
  EXPECT_NEAR(gp.x[0], 30, 1e-12);
  EXPECT_NEAR(gp.x[1], -40, 1e-12);
}

// A coarse slave edge (x from 0 to 2, facing down) over two master edges (0–0.8–2, facing up):
// the mortar rule cuts at the master node, ξ = −0.2, and integrates the master's hat function
// N_m of that node times the slave's W_0 = N_0 = 1 − x/2 exactly.
TEST(MortarSegments, EdgeOverTwoMasterEdgesIsCutAtTheMasterNode) {
  const std::vector<Vec3> x{{0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {0.8, 0, 0}, {2, 0, 0}};
  const Facet slave = make_facet(FacetShape::Line2, {0, 1});  // normal (a_y, −a_x) = (0, −1)
  // right to left: normals (0, 1)
  const std::vector<Facet> masters{make_facet(FacetShape::Line2, {3, 2}), make_facet(FacetShape::Line2, {4, 3})};
  const std::vector<std::int32_t> candidates{0, 1};
  std::vector<QuadPoint> rule;
  ASSERT_TRUE(contact::mortar_rule(slave, masters, candidates, x, 6, rule));
  EXPECT_EQ(rule.size(), 6u);
  double integral = 0.0;  // ∫ N_0(slave) N_m dx, x = 1 + ξ on the slave
  for (const QuadPoint& q : rule) {
    const double xs = 1 + q.xi, w0 = 0.5 * (1 - q.xi);
    const double hat = xs < 0.8 ? xs / 0.8 : (2 - xs) / 1.2;
    integral += q.weight * w0 * hat;  // dx = dξ
  }
  // ∫_0^0.8 (1 − x/2) x/0.8 dx + ∫_0.8^2 (1 − x/2)(2 − x)/1.2 dx = (0.4 − 0.512/4.8) + 0.288/1.2
  const double exact = (0.4 - 0.512 / 4.8) + 0.288 / 1.2;
  EXPECT_NEAR(integral, exact, 1e-15);
  // One master edge under the whole slave edge: the plain rule stays.
  const std::vector<Facet> one{make_facet(FacetShape::Line2, {4, 2})};
  const std::vector<std::int32_t> first{0};
  EXPECT_FALSE(contact::mortar_rule(slave, one, first, x, 6, rule));
}

// A slave quad [0, 2]² facing down over a 3 × 3 grid of master quads (facing up) offset by 0.3:
// the cells tile the slave face, and ∫ W_a N_m dA is exact (compared with a fine plain rule on
// each master cell's part computed in closed form: here the sum over m of ∫ W_a N_m = ∫ W_a).
TEST(MortarSegments, FaceOverAGridOfMasterFacesIsTiledByTheClippedCells) {
  std::vector<Vec3> x{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};  // normal a_2 × a_1 = −z
  const Facet slave = make_facet(FacetShape::Quad4, {0, 1, 2, 3});
  ASSERT_LT(contact::facet_geometry(slave, x, 0, 0).n[2], -0.99);
  std::vector<Facet> masters;
  std::vector<std::int32_t> candidates;
  auto node = [&](int i, int j) { return static_cast<std::int32_t>(4 + j * 4 + i); };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) x.push_back({-0.3 + 0.9 * i, -0.3 + 0.9 * j, 0.0});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      masters.push_back(make_facet(FacetShape::Quad4, {node(i, j), node(i, j + 1), node(i + 1, j + 1), node(i + 1, j)}));
      candidates.push_back(static_cast<std::int32_t>(masters.size() - 1));
    }
  std::vector<QuadPoint> rule;
  const int base = contact::plain_rule_points(FacetShape::Quad4);
  ASSERT_TRUE(contact::mortar_rule(slave, masters, candidates, x, base, rule));
  EXPECT_EQ(rule.size(), 9u * 9u);  // 9 quadrilateral cells, 3 × 3 points each
  EXPECT_NEAR(weight_sum(rule), 4.0, 1e-13);  // the slave's parametric area
  // ∫ x² y² dA = (2³/3)² = 64/9 (degree 4 in ξ, η: exact on every triangle).
  double integral = 0.0;
  for (const QuadPoint& q : rule) {
    const auto g = contact::facet_geometry(slave, x, q.xi, q.eta);
    integral += q.weight * g.jacobian * g.x[0] * g.x[0] * g.x[1] * g.x[1];
  }
  EXPECT_NEAR(integral, 64.0 / 9.0, 1e-12);
  // A second layer facing the slave (a copy of the grid 0.5 lower): the cells overlap, plain rule.
  const std::size_t n_nodes = x.size();
  for (std::size_t i = 4; i < n_nodes; ++i) x.push_back({x[i][0], x[i][1], -0.5});
  const std::size_t n_masters = masters.size();
  for (std::size_t m = 0; m < n_masters; ++m) {
    Facet copy = masters[m];
    for (int a = 0; a < 4; ++a) copy.nodes[static_cast<std::size_t>(a)] += static_cast<std::int32_t>(n_nodes - 4);
    masters.push_back(copy);
    candidates.push_back(static_cast<std::int32_t>(masters.size() - 1));
  }
  bool ambiguous = false;
  EXPECT_FALSE(contact::mortar_rule(slave, masters, candidates, x, base, rule, {}, &ambiguous));
  EXPECT_TRUE(ambiguous);  // (the caller's plain rule then takes kAmbiguousRulePoints)
}

// The point budget of surface-to-surface slave faces: on linear faces 3 × 3 where no master edge
// crosses the face, in a lone cell that covers part of it (a master's free edge) and in each of
// two cells; 4 × 4 on quadratic faces; 6 on 2D edges. A face entirely inside one master facet is
// not cut (not ambiguous).
TEST(MortarSegments, FacePointBudgetFollowsTheCellCount) {
  EXPECT_EQ(contact::plain_rule_points(FacetShape::Line2), 6);
  EXPECT_EQ(contact::plain_rule_points(FacetShape::Quad4), 3);
  EXPECT_EQ(contact::plain_rule_points(FacetShape::Tri3), 3);
  EXPECT_EQ(contact::plain_rule_points(FacetShape::Quad8), 4);
  EXPECT_EQ(contact::plain_rule_points(FacetShape::Tri6), 4);
  const int base = contact::plain_rule_points(FacetShape::Quad4);
  // The slave [0, 2]² facing down; masters facing up, 0.1 below.
  std::vector<Vec3> x{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const Facet slave = make_facet(FacetShape::Quad4, {0, 1, 2, 3});
  auto master = [&](double x0, double x1) {  // covering x0 ≤ x ≤ x1, −1 ≤ y ≤ 3
    const auto n = static_cast<std::int32_t>(x.size());
    for (const auto& [px, py] : {std::pair{x0, -1.0}, {x0, 3.0}, {x1, 3.0}, {x1, -1.0}}) x.push_back({px, py, -0.1});
    return make_facet(FacetShape::Quad4, {n, n + 1, n + 2, n + 3});
  };
  std::vector<QuadPoint> rule;
  bool ambiguous = true;
  const std::vector<Facet> whole{master(-1.0, 3.0)};
  EXPECT_FALSE(contact::mortar_rule(slave, whole, std::vector<std::int32_t>{0}, x, base, rule, {}, &ambiguous));
  EXPECT_FALSE(ambiguous);
  const std::vector<Facet> part{master(-1.0, 1.2)};  // its free edge at x = 1.2
  ASSERT_TRUE(contact::mortar_rule(slave, part, std::vector<std::int32_t>{0}, x, base, rule));
  EXPECT_EQ(rule.size(), 9u);
  EXPECT_NEAR(weight_sum(rule), 4.0 * 1.2 / 2.0, 1e-13);
  const std::vector<Facet> two{master(-1.0, 1.2), master(1.2, 3.0)};
  ASSERT_TRUE(contact::mortar_rule(slave, two, std::vector<std::int32_t>{0, 1}, x, base, rule));
  EXPECT_EQ(rule.size(), 2u * 9u);
  EXPECT_NEAR(weight_sum(rule), 4.0, 1e-13);
}

// The points depend on the configuration now; the slave facets are still laid out and projected
// one per thread and summed in facet order: one thread or two give the same bits.
TEST(MortarSegments, SurfaceToSurfaceUpdateDoesNotDependOnTheThreadCount) {
  const DeckDir dir;
  const auto r = dir.read(read_text(contact_deck("patch_3d_coarse_offset_s2s_penalty.inp")));
  ASSERT_TRUE(r.ok());
  const model::Model& m = r.model;
  // Every node moved by a smooth field: the master's facet edges cross the slave facets anywhere.
  std::vector<Vec3> x(m.mesh.nodes.coords.begin(), m.mesh.nodes.coords.end());
  for (Vec3& p : x) {
    p[0] += 0.02 * std::sin(2 * p[1] + p[2]);
    p[1] += 0.015 * std::cos(3 * p[0]);
    p[2] -= 1e-3 * p[2];
  }
  const auto& slave = m.mesh.surfaces.at("SLAVE_S");
  const auto& master = m.mesh.surfaces.at("MASTER_S");
  contact::SurfaceToSurfacePair one(m, slave, master, 3, 1.0), two(m, slave, master, 3, 1.0);
  two.set_threads(2);
  std::vector<contact::SlaveKinematics> a, b;
  one.update(x, a);
  two.update(x, b);
  ASSERT_EQ(a.size(), b.size());
  double area = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].area, b[i].area);
    EXPECT_EQ(a[i].projection.gap, b[i].projection.gap);
    EXPECT_EQ(a[i].projection.normal, b[i].projection.normal);
    one.linearize(x, a[i], true);
    two.linearize(x, b[i], true);
    EXPECT_EQ(a[i].lin.gradient, b[i].lin.gradient);
    area += a[i].area;
  }
  EXPECT_NEAR(area, 4.0, 0.05);  // the 2 × 2 interface, sheared a little
}

}  // namespace
}  // namespace inpact::test
