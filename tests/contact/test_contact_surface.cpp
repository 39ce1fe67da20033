// Contact surfaces from the model: facets of first- and second-order faces and edges, unique
// slave nodes, and nodal areas that are all positive and add up to the exact area (flat, curved,
// plane and axisymmetric), i.e. a uniform pressure gives the right total force.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "contact/contact_surface.hpp"
#include "contact_test_util.hpp"
#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using contact::ContactSurface;
using contact::FacetShape;
using contact::Vec3;

namespace {

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double a : v) s += a;
  return s;
}

/// Nodes and connectivity of an nx × ny × 1 grid of C3D8 bricks of size 1 (rows = labels − 1).
std::string brick_deck(int nx, int ny, const std::string& surface) {
  std::string d = "*NODE\n";
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) d += std::to_string(id(i, j, k)) + ", " + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + "\n";
  d += "*ELEMENT, TYPE=C3D8, ELSET=B\n";
  int e = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      d += std::to_string(e++);
      for (int n : {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0), id(i, j, 1), id(i + 1, j, 1),
                    id(i + 1, j + 1, 1), id(i, j + 1, 1)})
        d += ", " + std::to_string(n);
      d += "\n";
    }
  d += "*SOLID SECTION, ELSET=B, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n" + surface;
  return d;
}

}  // namespace

TEST(ContactSurface, TopFacesOfABrickGridFromADeck) {
  test::DeckDir dir;
  const auto r = dir.read(brick_deck(2, 2, "*SURFACE, NAME=TOP\nB, S2\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model;
  const auto s = ContactSurface::build(m, m.mesh.surfaces.at("TOP"));
  EXPECT_EQ(s.dim(), 3);
  EXPECT_FALSE(s.node_based());
  ASSERT_EQ(s.facets().size(), 4u);
  for (const auto& f : s.facets()) EXPECT_EQ(f.shape, FacetShape::Quad4);
  EXPECT_EQ(s.nodes().size(), 9u);  // shared nodes once
  const auto x = contact::reference_coordinates(m.mesh.nodes);
  // Outward normal of S2 (the top, z = 1) is +z.
  EXPECT_NEAR(contact::facet_geometry(s.facets()[0], x, 0, 0).n[2], 1.0, 1e-14);
  const auto areas = s.nodal_areas(x);
  EXPECT_NEAR(sum(areas), 4.0, 1e-13);
  for (std::size_t i = 0; i < areas.size(); ++i) {
    const Vec3& p = x[static_cast<std::size_t>(s.nodes()[i])];
    const int on_boundary = (p[0] == 0 || p[0] == 2) + (p[1] == 0 || p[1] == 2);
    EXPECT_NEAR(areas[i], on_boundary == 2 ? 0.25 : on_boundary == 1 ? 0.5 : 1.0, 1e-14);
    EXPECT_EQ(s.facets_of_node(i).size(), on_boundary == 2 ? 1u : on_boundary == 1 ? 2u : 4u);
  }
  // Current coordinates: stretch in x by 2 → areas double.
  std::vector<double> u(3 * m.mesh.nodes.size(), 0.0);
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) u[3 * i] = m.mesh.nodes.coords[i][0];
  EXPECT_NEAR(s.area(contact::current_coordinates(m.mesh.nodes, u, 3)), 8.0, 1e-13);
}

TEST(ContactSurface, SecondOrderFacesGetPositiveLumpedAreasThatSumToTheArea) {
  // One C3D20 2 × 3 × 1 brick: top face S2 is a flat Quad8 of area 6.
  const double a = 2, b = 3, c = 1;
  std::vector<Vec3> X = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, c}, {a, 0, c}, {a, b, c},
                         {0, b, c}, {a / 2, 0, 0}, {a, b / 2, 0}, {a / 2, b, 0}, {0, b / 2, 0}, {a / 2, 0, c},
                         {a, b / 2, c}, {a / 2, b, c}, {0, b / 2, c}, {0, 0, c / 2}, {a, 0, c / 2}, {a, b, c / 2},
                         {0, b, c / 2}};
  std::vector<std::int32_t> conn(20);
  for (int i = 0; i < 20; ++i) conn[i] = i;
  const auto m = test::elements_model("C3D20", X, {conn}, {{0, 1}});
  const auto s = ContactSurface::build(m, m.mesh.surfaces.at("S"));
  ASSERT_EQ(s.facets()[0].shape, FacetShape::Quad8);
  const auto x = contact::reference_coordinates(m.mesh.nodes);
  const auto w = s.nodal_areas(x);
  ASSERT_EQ(w.size(), 8u);
  EXPECT_NEAR(sum(w), a * b, 1e-13);  // p Σ w = p A: the total force of a uniform pressure
  for (std::size_t i = 0; i < w.size(); ++i) {
    const bool corner = s.nodes()[i] < 8;
    EXPECT_NEAR(w[i], a * b * (corner ? 3.0 / 76 : 16.0 / 76), 1e-13);  // HRZ on a flat Quad8
    EXPECT_GT(w[i], 0);
  }

  // C3D10: face S1 (nodes 1 2 3 + 5 6 7) is a flat Tri6 of area 1/2 in z = 0.
  std::vector<Vec3> T = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},     {0.5, 0, 0},
                         {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<std::int32_t> tconn(10);
  for (int i = 0; i < 10; ++i) tconn[i] = i;
  const auto mt = test::elements_model("C3D10", T, {tconn}, {{0, 0}});
  const auto st = ContactSurface::build(mt, mt.mesh.surfaces.at("S"));
  ASSERT_EQ(st.facets()[0].shape, FacetShape::Tri6);
  const auto wt = st.nodal_areas(contact::reference_coordinates(mt.mesh.nodes));
  EXPECT_NEAR(sum(wt), 0.5, 1e-14);
  for (std::size_t i = 0; i < wt.size(); ++i) {
    const bool corner = st.nodes()[i] < 3;
    EXPECT_NEAR(wt[i], 0.5 * (corner ? 1.0 / 19 : 16.0 / 57), 1e-14);
    EXPECT_GT(wt[i], 0);
  }
  // S1 of C3D10 faces −z (out of the tet, which lies above).
  EXPECT_NEAR(contact::facet_geometry(st.facets()[0], contact::reference_coordinates(mt.mesh.nodes), 0.2, 0.2).n[2],
              -1.0, 1e-14);
}

TEST(ContactSurface, CurvedQuad8AreasSumToTheExactArea) {
  // The parabolic cylinder z = κ x², x ∈ [−1, 1], y ∈ [0, 2] is represented exactly by one
  // Quad8 (serendipity functions reproduce ξ² and ξ² η). Area = 2 ∫ √(1 + 4κ²x²) dx.
  const double kappa = 0.4;
  const auto x = test::place(FacetShape::Quad8, [&](double xi, double eta) {
    return Vec3{xi, 1 + eta, kappa * xi * xi};
  });
  const auto f = test::make_facet(FacetShape::Quad8);
  const double k2 = 2 * kappa;
  const double exact = 2 * (std::sqrt(1 + k2 * k2) + std::asinh(k2) / k2);  // 2 ∫_{-1}^{1} √(1+(2κx)²) dx
  // Σ HRZ shares on the facet = its area, by construction; the area itself is a 6-point Gauss rule.
  double area = 0.0;
  std::array<double, 8> share{};
  for (const auto& q : contact::facet_rule(FacetShape::Quad8, 6)) {
    const auto g = contact::facet_geometry(f, x, q.xi, q.eta);
    const auto e = contact::eval_shape(FacetShape::Quad8, q.xi, q.eta);
    area += q.weight * g.jacobian;
    for (int a = 0; a < 8; ++a) share[a] += q.weight * g.jacobian * e.N[a] * e.N[a];
  }
  EXPECT_NEAR(area, exact, 1e-6 * exact);
  for (double v : share) EXPECT_GT(v, 0);
}

TEST(ContactSurface, CurvedC3D20TopFaceAreasSumToTheExactArea) {
  // The same parabolic cylinder as the top face S2 of a C3D20, through ContactSurface.
  const double kappa = 0.4;
  auto zf = [&](double x) { return 1 + kappa * x * x; };
  std::vector<Vec3> X = {{-1, 0, 0}, {1, 0, 0}, {1, 2, 0}, {-1, 2, 0}, {-1, 0, zf(-1)}, {1, 0, zf(1)},
                         {1, 2, zf(1)}, {-1, 2, zf(-1)}, {0, 0, 0}, {1, 1, 0}, {0, 2, 0}, {-1, 1, 0},
                         {0, 0, zf(0)}, {1, 1, zf(1)}, {0, 2, zf(0)}, {-1, 1, zf(-1)}, {-1, 0, 0.5}, {1, 0, 0.5},
                         {1, 2, 0.5}, {-1, 2, 0.5}};
  std::vector<std::int32_t> conn(20);
  for (int i = 0; i < 20; ++i) conn[i] = i;
  const auto m = test::elements_model("C3D20", X, {conn}, {{0, 1}});
  const auto s = ContactSurface::build(m, m.mesh.surfaces.at("S"));
  const auto x = contact::reference_coordinates(m.mesh.nodes);
  const double k2 = 2 * kappa, exact = 2 * (std::sqrt(1 + k2 * k2) + std::asinh(k2) / k2);
  const auto w = s.nodal_areas(x);
  EXPECT_NEAR(sum(w), exact, 1e-6 * exact);
  EXPECT_NEAR(sum(w), s.area(x), 1e-13);
  for (double v : w) EXPECT_GT(v, 0);
}

TEST(ContactSurface, PlaneAndAxisymmetricEdgeAreas) {
  // A 1 × 1 square at r ∈ [1, 2], z ∈ [0, 1]: bottom edge S1 and outer edge S2.
  const std::vector<Vec3> X = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  {
    const auto m = test::elements_model("CAX4", X, {{0, 1, 2, 3}}, {{0, 0}, {0, 1}});
    const auto s = ContactSurface::build(m, m.mesh.surfaces.at("S"));
    EXPECT_TRUE(s.axisymmetric());
    const auto x = contact::reference_coordinates(m.mesh.nodes);
    const double annulus = std::numbers::pi * (4 - 1), cylinder = 2 * std::numbers::pi * 2 * 1;
    EXPECT_NEAR(s.area(x), annulus + cylinder, 1e-12);
    const auto w = s.nodal_areas(x);
    EXPECT_NEAR(sum(w), annulus + cylinder, 1e-12);
    for (double v : w) EXPECT_GT(v, 0);
    // Node 1 (r = 1) carries 2π ∫ (1 − s)(1 + s) ds = 2π · 2/3 on the bottom edge.
    EXPECT_NEAR(w[0], 2 * std::numbers::pi * 2.0 / 3, 1e-12);
  }
  {
    const auto m = test::elements_model("CPE4", X, {{0, 1, 2, 3}}, {{0, 0}, {0, 1}});
    const auto s = ContactSurface::build(m, m.mesh.surfaces.at("S"), {2.5});
    EXPECT_FALSE(s.axisymmetric());
    const auto x = contact::reference_coordinates(m.mesh.nodes);
    const auto w = s.nodal_areas(x);
    EXPECT_NEAR(sum(w), 2 * 2.5, 1e-14);
    EXPECT_NEAR(w[1], 2.5, 1e-14);  // the shared corner node (2, 0)
  }
  {
    // CPE8 edge: consistent shares 1/6, 2/3, 1/6 (what HRZ gives on a straight Line3).
    const std::vector<Vec3> Q = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0.5, 0}, {1, 1, 0}, {0, 0.5, 0}};
    const auto m = test::elements_model("CPE8", Q, {{0, 1, 2, 3, 4, 5, 6, 7}}, {{0, 0}});
    const auto s = ContactSurface::build(m, m.mesh.surfaces.at("S"));
    ASSERT_EQ(s.facets()[0].shape, FacetShape::Line3);
    const auto w = s.nodal_areas(contact::reference_coordinates(m.mesh.nodes));
    ASSERT_EQ(w.size(), 3u);  // rows 0, 1, 4
    EXPECT_NEAR(w[0], 2.0 / 6, 1e-14);
    EXPECT_NEAR(w[1], 2.0 / 6, 1e-14);
    EXPECT_NEAR(w[2], 2.0 * 2 / 3, 1e-14);
  }
}

TEST(ContactSurface, NodeBasedSurfaceIsASlaveOnlyPointSet) {
  test::DeckDir dir;
  const auto r = dir.read(test::one_cube_deck("*SURFACE, TYPE=NODE, NAME=PTS\n5, 2.0\n6\n7, 0.5\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto s = ContactSurface::build(r.model, r.model.mesh.surfaces.at("PTS"));
  EXPECT_TRUE(s.node_based());
  EXPECT_TRUE(s.facets().empty());
  ASSERT_EQ(s.nodes().size(), 3u);
  const auto x = contact::reference_coordinates(r.model.mesh.nodes);
  const auto w = s.nodal_areas(x);
  EXPECT_NEAR(sum(w), s.area(x), 1e-15);
  for (double v : w) EXPECT_GT(v, 0);
}

TEST(ContactSurface, MixedDimensionsAreRejected) {
  auto m = test::elements_model("CPE4", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}, {{0, 0}});
  m.mesh.elements.type.push_back(model::element_type_index(*model::find_element_type("CAX4")));
  for (int i = 0; i < 4; ++i) m.mesh.elements.conn.push_back(i);
  m.mesh.elements.offsets.push_back(8);
  m.mesh.elements.labels.push_back(2);
  m.mesh.elements.instance.push_back(0);
  m.mesh.surfaces["S"].faces.push_back({1, 0});
  EXPECT_THROW(ContactSurface::build(m, m.mesh.surfaces.at("S")), std::invalid_argument);
}
