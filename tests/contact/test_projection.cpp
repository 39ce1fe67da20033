// Closest-point projection, gap, normal and the gap's first and second derivatives, against
// hand geometry (flat facets of every type, a C3D20 face curved as a cylinder, CAX and plane
// edges), clamping outside the facet, the choice among neighbours and a finite-difference check
// of the linearisation.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "contact/contact_surface.hpp"
#include "contact/projection.hpp"
#include "contact_test_util.hpp"

using namespace inpact;
using contact::closest_projection;
using contact::FacetShape;
using contact::linearize_gap;
using contact::project_to_facet;
using contact::ProjectionRegion;
using contact::Vec3;
using test::make_facet;
using test::place;

namespace {

constexpr FacetShape kAll[] = {FacetShape::Line2, FacetShape::Line3, FacetShape::Tri3,
                               FacetShape::Tri6,  FacetShape::Quad4, FacetShape::Quad8};

bool is_line(FacetShape s) { return contact::facet_param_dim(s) == 1; }

/// An affine map of the parametric plane onto a tilted plane in 3D (lines: onto a 2D line).
Vec3 flat_map(FacetShape s, double xi, double eta) {
  if (is_line(s)) return {1.0 + 2.0 * xi, 0.5 + 1.0 * xi, 0.0};
  return {0.3 + 2.0 * xi + 0.5 * eta, -0.1 + 0.2 * xi + 1.5 * eta, 0.4 + 0.3 * xi - 0.2 * eta};
}

/// A curved (non-affine) map; quadratic shapes reproduce it only approximately, which is fine:
/// the tests using it compare with finite differences of the same discrete facet.
Vec3 curved_map(FacetShape s, double xi, double eta) {
  if (is_line(s)) return {xi, 0.3 * xi * xi + 0.1 * xi, 0.0};
  return {xi + 0.1 * eta * eta, eta + 0.05 * xi * eta, 0.2 * xi * xi - 0.15 * eta * eta + 0.1 * xi * eta};
}

/// A parametric point well inside the domain.
std::array<double, 2> inner_point(FacetShape s) {
  if (is_line(s)) return {0.3, 0.0};
  if (s == FacetShape::Tri3 || s == FacetShape::Tri6) return {0.2, 0.3};
  return {0.3, -0.4};
}

}  // namespace

TEST(FacetShapes, PartitionOfUnityKroneckerAndDerivatives) {
  for (FacetShape s : kAll) {
    const int n = contact::facet_n_nodes(s);
    for (int a = 0; a < n; ++a) {
      const auto p = contact::facet_node_param(s, a);
      const auto e = contact::eval_shape(s, p[0], p[1]);
      for (int b = 0; b < n; ++b) EXPECT_NEAR(e.N[b], a == b ? 1.0 : 0.0, 1e-14) << int(s);
    }
    const double xi = 0.21, eta = is_line(s) ? 0.0 : 0.17, h = 1e-6;
    const auto e = contact::eval_shape(s, xi, eta);
    double sum = 0;
    for (int a = 0; a < n; ++a) sum += e.N[a];
    EXPECT_NEAR(sum, 1.0, 1e-14);
    const auto ep = contact::eval_shape(s, xi + h, eta), em = contact::eval_shape(s, xi - h, eta);
    const auto fp = contact::eval_shape(s, xi, eta + h), fm = contact::eval_shape(s, xi, eta - h);
    for (int a = 0; a < n; ++a) {
      EXPECT_NEAR(e.dN[a][0], (ep.N[a] - em.N[a]) / (2 * h), 1e-8);
      EXPECT_NEAR(e.d2N[a][0], (ep.dN[a][0] - em.dN[a][0]) / (2 * h), 1e-8);
      if (is_line(s)) continue;
      EXPECT_NEAR(e.dN[a][1], (fp.N[a] - fm.N[a]) / (2 * h), 1e-8);
      EXPECT_NEAR(e.d2N[a][1], (fp.dN[a][0] - fm.dN[a][0]) / (2 * h), 1e-8);
      EXPECT_NEAR(e.d2N[a][2], (fp.dN[a][1] - fm.dN[a][1]) / (2 * h), 1e-8);
    }
  }
}

TEST(Projection, FlatFacetOfEveryTypeGivesExactGapNormalAndPoint) {
  for (FacetShape s : kAll) {
    const auto x = place(s, [s](double xi, double eta) { return flat_map(s, xi, eta); });
    const auto f = make_facet(s);
    const auto q = inner_point(s);
    const auto geo = contact::facet_geometry(f, x, q[0], q[1]);
    // The expected outward normal by hand: 2D: edge direction (2, 1) rotated clockwise;
    // 3D: −(a_ξ × a_η) of the affine map.
    Vec3 n_hand;
    if (is_line(s)) {
      n_hand = {1 / std::sqrt(5.0), -2 / std::sqrt(5.0), 0};
    } else {
      const Vec3 a0{2.0, 0.2, 0.3}, a1{0.5, 1.5, -0.2};
      Vec3 c{a1[1] * a0[2] - a1[2] * a0[1], a1[2] * a0[0] - a1[0] * a0[2], a1[0] * a0[1] - a1[1] * a0[0]};
      const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      n_hand = {c[0] / l, c[1] / l, c[2] / l};
    }
    for (double h : {0.37, -0.21, 0.0}) {
      const Vec3 xs{geo.x[0] + h * n_hand[0], geo.x[1] + h * n_hand[1], geo.x[2] + h * n_hand[2]};
      const auto p = project_to_facet(f, x, xs);
      EXPECT_EQ(p.region, ProjectionRegion::Interior) << int(s);
      EXPECT_NEAR(p.gap, h, 1e-12) << int(s);
      EXPECT_NEAR(p.xi[0], q[0], 1e-12) << int(s);
      EXPECT_NEAR(p.xi[1], q[1], 1e-12) << int(s);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.normal[k], n_hand[k], 1e-12) << int(s);
      // Tangent basis: orthonormal and right-handed with n.
      const Vec3& t1 = p.t1;
      EXPECT_NEAR(t1[0] * p.normal[0] + t1[1] * p.normal[1] + t1[2] * p.normal[2], 0.0, 1e-14);
      if (!is_line(s)) {
        const Vec3& t2 = p.t2;
        const Vec3 c{t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2], t1[0] * t2[1] - t1[1] * t2[0]};
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], p.normal[k], 1e-14);
      }
    }
  }
}

// Far from the origin (the facet 1e4 of its sizes away) ξ is known only to ε |x| / |∂x/∂ξ|: the
// Newton step's test scales with it, so a point on a flat facet still converges (it stopped on
// an absolute 1e-14 and returned converged = false with the facet's edge: the *TIE helper's
// 40×40-on-30×30 interface left 23 nodes untied).
TEST(Projection, FlatFacetFarFromTheOriginConverges) {
  for (FacetShape s : kAll) {
    if (is_line(s) || s == FacetShape::Tri3) continue;  // (edges and Tri3: no iteration)
    auto x = place(s, [s](double xi, double eta) { return flat_map(s, xi, eta); });
    for (auto& p : x) p = {p[0] + 1e4, p[1] - 2e4, p[2] + 3e4};
    const auto f = make_facet(s);
    const auto q = inner_point(s);
    const auto geo = contact::facet_geometry(f, x, q[0], q[1]);
    const auto p = project_to_facet(f, x, geo.x);
    EXPECT_TRUE(p.converged) << int(s);
    EXPECT_EQ(p.region, ProjectionRegion::Interior) << int(s);
    EXPECT_NEAR(p.xi[0], q[0], 1e-10) << int(s);
    EXPECT_NEAR(p.xi[1], q[1], 1e-10) << int(s);
    EXPECT_NEAR(p.gap, 0.0, 1e-10) << int(s);
  }
}

TEST(Projection, C3D20FaceCurvedAsACylinderMatchesTheExactQuadraticSurface) {
  // One C3D20 whose top face S2 has its nodes on a cylinder of radius R about the y axis:
  // corners at x = ±R sin α, z = R cos α, the midside nodes across the face at x = 0, z = R.
  // The serendipity face is then exactly the parabolic cylinder
  //   x = s η, y = L ξ, z(η) = R c + R (1 − c)(1 − η²)   (s = R sin α, c = cos α),
  // whose closest point is the root of the cubic (x_m − p)·∂x_m/∂η = 0, solved here directly.
  const double R = 1.0, alpha = std::numbers::pi / 6, L = 0.5;
  const double s = R * std::sin(alpha), c = std::cos(alpha), zc = R * c;
  std::vector<Vec3> X = {{-s, -L, 0}, {s, -L, 0}, {s, L, 0}, {-s, L, 0},  {-s, -L, zc}, {s, -L, zc},
                         {s, L, zc},  {-s, L, zc}, {0, -L, 0}, {s, 0, 0}, {0, L, 0},    {-s, 0, 0},
                         {0, -L, R},  {s, 0, zc}, {0, L, R},  {-s, 0, zc}, {-s, -L, zc / 2}, {s, -L, zc / 2},
                         {s, L, zc / 2}, {-s, L, zc / 2}};
  std::vector<std::int32_t> conn(20);
  for (int i = 0; i < 20; ++i) conn[i] = i;
  const auto m = test::elements_model("C3D20", X, {conn}, {{0, 1}});
  const auto surf = contact::ContactSurface::build(m, m.mesh.surfaces.at("S"));
  ASSERT_EQ(surf.facets().size(), 1u);
  ASSERT_EQ(surf.facets()[0].shape, FacetShape::Quad8);
  const auto x = contact::reference_coordinates(m.mesh.nodes);

  auto z = [&](double eta) { return R * c + R * (1 - c) * (1 - eta * eta); };
  auto dz = [&](double eta) { return -2 * R * (1 - c) * eta; };
  for (const Vec3 P : {Vec3{0.2, 0.1, 1.3}, Vec3{-0.35, -0.3, 1.05}, Vec3{0.1, 0.2, 0.8}}) {
    long double eta = P[0] / s;  // Newton on f(η) = (x_m − P)·(s, 0, z'(η)) in long double
    for (int it = 0; it < 50; ++it) {
      const long double zz = R * c + R * (1 - c) * (1 - eta * eta), d = -2 * R * (1 - c) * eta, dd = -2 * R * (1 - c);
      const long double fv = (s * eta - P[0]) * s + (zz - P[2]) * d;
      const long double fd = s * s + d * d + (zz - P[2]) * dd;
      eta -= fv / fd;
    }
    const double e = static_cast<double>(eta);
    const Vec3 xm{s * e, P[1], z(e)};
    const double ln = std::sqrt(dz(e) * dz(e) + s * s);
    const Vec3 n{-dz(e) / ln, 0, s / ln};  // outward: up, out of the brick
    const double gap = (P[0] - xm[0]) * n[0] + (P[2] - xm[2]) * n[2];

    const auto p = contact::closest_projection(surf.facets(), std::vector<std::int32_t>{0}, x, P);
    EXPECT_EQ(p.region, ProjectionRegion::Interior);
    EXPECT_NEAR(p.gap, gap, 1e-10);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(p.x_master[k], xm[k], 1e-10);
      EXPECT_NEAR(p.normal[k], n[k], 1e-10);
    }
    EXPECT_NEAR(p.xi[0], P[1] / L, 1e-10);  // face ξ runs along y (corner 5 → 8)
    EXPECT_NEAR(p.xi[1], e, 1e-10);
  }
  // The point above is open, the one inside the brick penetrates.
  EXPECT_GT(contact::closest_projection(surf.facets(), std::vector<std::int32_t>{0}, x, {0.2, 0.1, 1.3}).gap, 0);
  EXPECT_LT(contact::closest_projection(surf.facets(), std::vector<std::int32_t>{0}, x, {0.1, 0.2, 0.8}).gap, 0);
}

TEST(Projection, CurvedLine3EdgeMatchesTheExactParabola) {
  // A CPE8-type edge on y = 1 − κ x² (x ∈ [−1, 1]); the element lies below, outward is +y.
  // Edge nodes from corner (1, 1−κ) to corner (−1, 1−κ) (clockwise rotation of the edge
  // direction (−1, 0) gives (0, +1)), midside (0, 1).
  const double kappa = 0.3;
  const std::vector<Vec3> x = {{1, 1 - kappa, 0}, {-1, 1 - kappa, 0}, {0, 1, 0}};
  const auto f = make_facet(FacetShape::Line3);
  for (const Vec3 P : {Vec3{0.3, 1.4, 0}, Vec3{-0.5, 0.6, 0}}) {
    long double xm = P[0];  // minimise (x − P_x)² + (1 − κx² − P_y)²
    for (int it = 0; it < 60; ++it) {
      const long double y = 1 - kappa * xm * xm, dy = -2 * kappa * xm;
      const long double fv = (xm - P[0]) + (y - P[1]) * dy, fd = 1 + dy * dy + (y - P[1]) * (-2 * kappa);
      xm -= fv / fd;
    }
    const double xx = static_cast<double>(xm), yy = 1 - kappa * xx * xx, dy = -2 * kappa * xx;
    const double ln = std::sqrt(1 + dy * dy);
    const Vec3 n{-dy / ln, 1 / ln, 0};
    const auto p = project_to_facet(f, x, P);
    EXPECT_NEAR(p.x_master[0], xx, 1e-12);
    EXPECT_NEAR(p.x_master[1], yy, 1e-12);
    EXPECT_NEAR(p.normal[0], n[0], 1e-12);
    EXPECT_NEAR(p.normal[1], n[1], 1e-12);
    EXPECT_NEAR(p.gap, (P[0] - xx) * n[0] + (P[1] - yy) * n[1], 1e-12);
    // 2D tangent: the edge direction, n rotated counter-clockwise.
    EXPECT_NEAR(p.t1[0], -n[1], 1e-14);
    EXPECT_NEAR(p.t1[1], n[0], 1e-14);
  }
}

// A minimum exactly at one of the edge search's sample points (φ' = 0 there): a slave node on
// a straight Line3 edge's midside node, just under or over it. It was missed once (the sign
// change test wanted φ' > 0 strictly) and the node projected to a corner 0.5 away.
TEST(Projection, PointOverALine3MidsideNodeProjectsThere) {
  const std::vector<Vec3> x = {{1, 1, 0}, {0, 1, 0}, {0.5, 1, 0}};
  const auto f = make_facet(FacetShape::Line3);
  for (const double dy : {0.0, -1e-3, 1e-3}) {
    const auto p = project_to_facet(f, x, Vec3{0.5, 1 + dy, 0});
    EXPECT_NEAR(p.xi[0], 0.0, 1e-12) << dy;
    EXPECT_NEAR(p.gap, dy, 1e-15) << dy;
  }
}

TEST(Projection, AxisymmetricAndPlaneEdgesFromADeck) {
  // CAX4 ring section r ∈ [1, 2], z ∈ [0, 1]; surface on the top edge S3 (nodes 3 → 4), outward +z.
  for (const char* type : {"CAX4", "CPE4"}) {
    const auto m = test::elements_model(type, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}, {{0, 1, 2, 3}}, {{0, 2}});
    const auto surf = contact::ContactSurface::build(m, m.mesh.surfaces.at("S"));
    EXPECT_EQ(surf.dim(), 2);
    EXPECT_EQ(surf.axisymmetric(), std::string(type) == "CAX4");
    const auto x = contact::reference_coordinates(m.mesh.nodes);
    const auto p = closest_projection(surf.facets(), std::vector<std::int32_t>{0}, x, {1.25, 1.1, 0});
    EXPECT_NEAR(p.gap, 0.1, 1e-14);
    EXPECT_NEAR(p.normal[0], 0.0, 1e-14);
    EXPECT_NEAR(p.normal[1], 1.0, 1e-14);
    EXPECT_NEAR(p.x_master[0], 1.25, 1e-14);
    const auto q = closest_projection(surf.facets(), std::vector<std::int32_t>{0}, x, {1.5, 0.97, 0});
    EXPECT_NEAR(q.gap, -0.03, 1e-14);
  }
}

TEST(Projection, PointOutsideAFacetIsClampedToItsEdgeOrVertex) {
  // Unit square Quad4 in z = 0, corners counter-clockwise seen from +z: outward normal is −z.
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const auto f = make_facet(FacetShape::Quad4);
  // Beyond the edge x = 1, below the facet (outside the body): closest point on the edge.
  auto p = project_to_facet(f, x, {1.3, 0.4, -0.4});
  EXPECT_EQ(p.region, ProjectionRegion::Edge);
  EXPECT_NEAR(p.x_master[0], 1.0, 1e-14);
  EXPECT_NEAR(p.x_master[1], 0.4, 1e-14);
  EXPECT_NEAR(p.distance, 0.5, 1e-14);
  EXPECT_NEAR(p.gap, 0.5, 1e-14);  // open, measured along the distance
  EXPECT_NEAR(p.normal[0], 0.6, 1e-14);
  EXPECT_NEAR(p.normal[2], -0.8, 1e-14);
  // Beyond the corner (0, 0): a vertex.
  p = project_to_facet(f, x, {-0.2, -0.3, 0.5});
  EXPECT_EQ(p.region, ProjectionRegion::Vertex);
  EXPECT_NEAR(p.x_master[0], 0.0, 1e-14);
  EXPECT_NEAR(p.x_master[1], 0.0, 1e-14);
  EXPECT_NEAR(p.gap, -std::sqrt(0.04 + 0.09 + 0.25), 1e-14);  // on the body side: negative
  // The same for a curved Quad8 and a Tri6: the clamped point is the closest point of the edge.
  for (FacetShape s : {FacetShape::Quad8, FacetShape::Tri6}) {
    const auto xc = place(s, [s](double xi, double eta) { return curved_map(s, xi, eta); });
    const auto fc = make_facet(s);
    const Vec3 xs{-1.4, 0.1, -0.3};
    const auto pc = project_to_facet(fc, xc, xs);
    EXPECT_NE(pc.region, ProjectionRegion::Interior) << int(s);
    // Brute force over a fine sampling of the facet: nothing is closer.
    double best = 1e300;
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j <= 400; ++j) {
        double xi = -1 + i / 200.0, eta = -1 + j / 200.0;
        if (s == FacetShape::Tri6) {
          xi = i / 400.0, eta = j / 400.0;
          if (xi + eta > 1) continue;
        }
        best = std::min(best, test::dist(contact::facet_geometry(fc, xc, xi, eta).x, xs));
      }
    EXPECT_LE(pc.distance, best + 1e-12) << int(s);
    EXPECT_GT(pc.distance, best - 1e-4) << int(s);
  }
}

TEST(Projection, ClosestOfSeveralFacetsIsChosen) {
  // Two coplanar quads side by side (x ∈ [0,1] and [1,2]); outward −z.
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  auto a = make_facet(FacetShape::Quad4);
  auto b = make_facet(FacetShape::Quad4);
  b.nodes = {1, 4, 5, 2};
  const std::vector<contact::Facet> facets{a, b};
  const std::vector<std::int32_t> both{0, 1};
  auto p = closest_projection(facets, both, x, {1.2, 0.5, -0.1});
  EXPECT_EQ(p.facet, 1);
  EXPECT_EQ(p.region, ProjectionRegion::Interior);
  EXPECT_NEAR(p.gap, 0.1, 1e-14);
  p = closest_projection(facets, both, x, {0.7, 0.5, 0.2});
  EXPECT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, -0.2, 1e-14);
  // Exactly above the shared edge: one facet reported, normal −z either way.
  p = closest_projection(facets, both, x, {1.0, 0.5, -0.1});
  EXPECT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, 0.1, 1e-14);
  EXPECT_NEAR(p.normal[2], -1.0, 1e-14);
}

TEST(Projection, NormalIsContinuousAroundAConvexEdge) {
  // A V-shaped body z ≥ |x| seen from below: facet A in z = −x (x < 0), facet B in z = x
  // (x > 0), a convex ridge along y at x = z = 0; outward normals point down-left (A) and
  // down-right (B).
  const std::vector<Vec3> x = {{-1, 0, 1}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 1}, {1, 0, 1}, {1, 1, 1}};
  auto a = make_facet(FacetShape::Quad4);
  auto b = make_facet(FacetShape::Quad4);
  b.nodes = {1, 4, 5, 2};
  const std::vector<contact::Facet> facets{a, b};
  const std::vector<std::int32_t> both{0, 1};
  const auto na = contact::facet_geometry(a, x, 0, 0).n, nb = contact::facet_geometry(b, x, 0, 0).n;
  ASSERT_LT(na[2], 0);
  ASSERT_LT(nb[2], 0);
  ASSERT_LT(na[0], 0);
  ASSERT_GT(nb[0], 0);
  // Sweep the slave point on a circle of radius 0.3 around the ridge line (below it): the
  // normal must turn without jumps from n_A to n_B, and the gap stay 0.3.
  Vec3 prev{};
  for (int i = 0; i <= 200; ++i) {
    const double angle = -std::numbers::pi / 2 + (i / 200.0 - 0.5) * 2.6;
    const Vec3 xs{0.3 * std::cos(angle), 0.5, 0.3 * std::sin(angle)};
    const auto p = closest_projection(facets, both, x, xs);
    EXPECT_GT(p.gap, 0) << i;  // below the roof: outside the body
    EXPECT_LE(p.gap, 0.3 + 1e-14) << i;
    if (i > 0) {
      EXPECT_LT(test::dist(p.normal, prev), 0.05) << i;
    }
    prev = p.normal;
  }
  EXPECT_NEAR(test::dist(prev, nb), 0.0, 1e-12);  // ends inside B's normal band: B's normal
  // Straight below the ridge: the bisector, from the edge region of both facets.
  const auto p = closest_projection(facets, both, x, {0, 0.5, -0.3});
  EXPECT_NE(p.region, ProjectionRegion::Interior);
  EXPECT_NEAR(p.gap, 0.3, 1e-14);
  EXPECT_NEAR(p.normal[0], 0.0, 1e-14);
  EXPECT_NEAR(p.normal[2], -1.0, 1e-14);
}

TEST(Projection, SlaveExactlyOnASharedVertexGetsOneFacetAndTheAverageNormal) {
  // Four quads around the apex (0,0,0.2) of a shallow pyramid; outward normals point up (+z).
  const std::vector<Vec3> x = {{0, 0, 0.2}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0},
                               {-1, 0, 0},  {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}};
  std::vector<contact::Facet> facets;
  // Corners turning clockwise seen from +z (into the body below), so outward is +z.
  for (auto nodes : {std::array<int, 4>{0, 3, 2, 1}, {0, 5, 4, 3}, {0, 7, 6, 5}, {0, 1, 8, 7}}) {
    auto f = make_facet(FacetShape::Quad4);
    for (int a = 0; a < 4; ++a) f.nodes[a] = nodes[a];
    facets.push_back(f);
  }
  for (const auto& f : facets) ASSERT_GT(contact::facet_geometry(f, x, 0, 0).n[2], 0);
  const std::vector<std::int32_t> all{0, 1, 2, 3};
  const auto p = closest_projection(facets, all, x, {0, 0, 0.2});
  EXPECT_EQ(p.facet, 0);
  EXPECT_EQ(p.gap, 0.0);
  EXPECT_NEAR(p.normal[0], 0.0, 1e-14);
  EXPECT_NEAR(p.normal[1], 0.0, 1e-14);
  EXPECT_NEAR(p.normal[2], 1.0, 1e-14);
  // Just above the apex: the same normal (continuity), gap = the height.
  const auto q = closest_projection(facets, all, x, {0, 0, 0.2 + 1e-3});
  EXPECT_NEAR(q.gap, 1e-3, 1e-15);
  EXPECT_NEAR(q.normal[2], 1.0, 1e-12);
  // On a shared edge (between facets 0 and 1, the segment apex → (0,1,0)): one facet, and a
  // normal halfway between the two.
  const Vec3 on_edge{0, 0.5, 0.1};
  const auto e = closest_projection(facets, all, x, on_edge);
  EXPECT_EQ(e.gap, 0.0);
  // (The quads are warped: their normals at the shared point, not at their centres.)
  const auto n0 = project_to_facet(facets[0], x, on_edge).facet_normal;
  const auto n1 = project_to_facet(facets[1], x, on_edge).facet_normal;
  Vec3 avg{n0[0] + n1[0], n0[1] + n1[1], n0[2] + n1[2]};
  const double l = std::sqrt(avg[0] * avg[0] + avg[1] * avg[1] + avg[2] * avg[2]);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.normal[k], avg[k] / l, 1e-12) << "n0 " << n0[0] << " " << n0[1] << " " << n0[2] << " n1 " << n1[0] << " " << n1[1] << " " << n1[2];
}

namespace {

/// Central differences of the gap (and of its analytic gradient) over every coordinate of the
/// slave and the facet nodes.
void check_linearization(const contact::Facet& f, std::vector<Vec3> x, Vec3 xs, ProjectionRegion expected,
                         bool check_hessian = true) {
  const int dim = is_line(f.shape) ? 2 : 3;
  const auto p = project_to_facet(f, x, xs);
  ASSERT_EQ(p.region, expected) << int(f.shape);
  const auto L = linearize_gap(f, x, xs, p, dim);
  const double h = 1e-6;
  const int k = f.n_nodes;
  auto coord = [&](int node, int c) -> double& { return node == 0 ? xs[c] : x[static_cast<std::size_t>(f.nodes[node - 1])][c]; };
  double gmax = 0, hmax = 0;
  for (double v : L.gradient) gmax = std::max(gmax, std::abs(v));
  for (double v : L.hessian) hmax = std::max(hmax, std::abs(v));
  for (int node = 0; node <= k; ++node)
    for (int c = 0; c < dim; ++c) {
      const std::size_t i = static_cast<std::size_t>(node * dim + c);
      double& v = coord(node, c);
      const double v0 = v;
      v = v0 + h;
      const auto pp = project_to_facet(f, x, xs);
      const auto Lp = linearize_gap(f, x, xs, pp, dim);
      v = v0 - h;
      const auto pm = project_to_facet(f, x, xs);
      const auto Lm = linearize_gap(f, x, xs, pm, dim);
      v = v0;
      EXPECT_NEAR(L.gradient[i], (pp.gap - pm.gap) / (2 * h), 1e-6 * std::max(1.0, gmax)) << int(f.shape) << " dof " << i;
      if (!check_hessian) continue;
      for (std::size_t j = 0; j < static_cast<std::size_t>(L.n_dof); ++j)
        EXPECT_NEAR(L.hessian[j * static_cast<std::size_t>(L.n_dof) + i], (Lp.gradient[j] - Lm.gradient[j]) / (2 * h),
                    1e-6 * std::max(1.0, hmax))
            << int(f.shape) << " dof " << i << "," << j;
      for (int al = 0; al < contact::facet_param_dim(f.shape); ++al)
        EXPECT_NEAR(L.dxi[al][i], (pp.xi[al] - pm.xi[al]) / (2 * h), 1e-6) << int(f.shape) << " dof " << i;
    }
}

}  // namespace

TEST(GapLinearization, GradientAndSecondVariationMatchFiniteDifferencesInside) {
  for (FacetShape s : kAll) {
    const auto x = place(s, [s](double xi, double eta) { return curved_map(s, xi, eta); });
    const auto f = make_facet(s);
    const auto q = inner_point(s);
    const auto g = contact::facet_geometry(f, x, q[0], q[1]);
    for (double h : {0.15, -0.05, 0.0}) {
      const Vec3 xs{g.x[0] + h * g.n[0] + 0.01, g.x[1] + h * g.n[1], g.x[2] + h * g.n[2]};
      check_linearization(f, x, xs, ProjectionRegion::Interior);
    }
  }
}

TEST(GapLinearization, GradientAndSecondVariationMatchFiniteDifferencesOnEdgesAndVertices) {
  for (FacetShape s : {FacetShape::Quad4, FacetShape::Quad8, FacetShape::Tri3, FacetShape::Tri6}) {
    const auto x = place(s, [s](double xi, double eta) { return curved_map(s, xi, eta); });
    const auto f = make_facet(s);
    const bool tri = s == FacetShape::Tri3 || s == FacetShape::Tri6;
    // Beyond the edge η = −1 (tri: η = 0) on the outward side, then beyond the corner (−1,−1).
    const auto ge = contact::facet_geometry(f, x, tri ? 0.4 : 0.2, tri ? 0.0 : -1.0);
    check_linearization(f, x, {ge.x[0] + 0.1 * ge.n[0], ge.x[1] - 0.3 + 0.1 * ge.n[1], ge.x[2] + 0.1 * ge.n[2]},
                        ProjectionRegion::Edge);
    const auto gv = contact::facet_geometry(f, x, tri ? 0.0 : -1.0, tri ? 0.0 : -1.0);
    check_linearization(f, x, {gv.x[0] - 0.3, gv.x[1] - 0.25, gv.x[2] + 0.2}, ProjectionRegion::Vertex);
  }
  for (FacetShape s : {FacetShape::Line2, FacetShape::Line3}) {
    const auto x = place(s, [s](double xi, double eta) { return curved_map(s, xi, eta); });
    check_linearization(make_facet(s), x, {1.3, 0.2, 0}, ProjectionRegion::Vertex);
  }
}
