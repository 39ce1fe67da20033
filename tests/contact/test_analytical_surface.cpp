// Analytical rigid surfaces (contact/analytical_profile.hpp, analytical_shape.hpp,
// analytical_pair.hpp): the closest point and gap against closed forms (a circle's distance
// |p − c| − R, a line's, a fillet's circle), the normal and the curvature of the distance field
// against central differences of the gap, the profile errors, and the pair's gap gradient over
// [x_s; u_R; θ] against central differences of the measured gap.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/analytical_pair.hpp"
#include "contact_test_util.hpp"

namespace inpact::contact {
namespace {

using model::AnalyticalSurface;
using model::ProfileSegment;

ProfileSegment line_to(double x, double y) { return {ProfileSegment::Kind::Line, {x, y}, {}, {}}; }
ProfileSegment arc_to(double x, double y, double cx, double cy) { return {ProfileSegment::Kind::Arc, {x, y}, {cx, cy}, {}}; }

AnalyticalSurface surface(AnalyticalSurface::Type type, Vec2 start, std::vector<ProfileSegment> segments,
                          double fillet = 0.0) {
  AnalyticalSurface s;
  s.type = type;
  s.start = start;
  s.segments = std::move(segments);
  s.fillet_radius = fillet;
  return s;
}

// A lower half circle of radius 2 about (0, 3), travelled clockwise: convex, normal outward.
AnalyticalSurface lower_arc(AnalyticalSurface::Type type) {
  return surface(type, {1.6, 3.0 - 1.2}, {arc_to(-1.6, 3.0 - 1.2, 0.0, 3.0)});
}

TEST(AnalyticalProfile, ArcGapIsTheDistanceToTheCircleAndItsNormalPointsAway) {
  const AnalyticalShape shape = AnalyticalShape::build(lower_arc(AnalyticalSurface::Type::Segments), 2);
  for (const Vec3& p : {Vec3{0.3, 0.4, 0}, Vec3{-0.5, 1.1, 0}, Vec3{0.2, 1.5, 0}}) {  // outside, inside
    const ShapePoint sp = shape.closest(p);
    const double r = std::hypot(p[0], p[1] - 3.0);
    EXPECT_NEAR(sp.gap, r - 2.0, 1e-14);
    EXPECT_NEAR(sp.n[0], p[0] / r, 1e-14);
    EXPECT_NEAR(sp.n[1], (p[1] - 3.0) / r, 1e-14);
    EXPECT_FALSE(sp.corner);
    // ∇²g of |p − c|: (I − n nᵀ)/r in the plane.
    EXPECT_NEAR(sp.hessian[0], (1 - sp.n[0] * sp.n[0]) / r, 1e-13);
    EXPECT_NEAR(sp.hessian[1], -sp.n[0] * sp.n[1] / r, 1e-13);
    EXPECT_NEAR(sp.hessian[4], (1 - sp.n[1] * sp.n[1]) / r, 1e-13);
  }
}

TEST(AnalyticalProfile, LineNormalIsItsDirectionTurnedCounterClockwise) {
  const Profile p = Profile::build({2, 2}, std::vector{line_to(0, 2)}, 0.0);  // travelled in −x: normal −y
  const ProfilePoint below = p.closest({1.3, 1.5});
  EXPECT_NEAR(below.gap, 0.5, 1e-15);
  EXPECT_NEAR(below.n[1], -1.0, 1e-15);
  EXPECT_EQ(below.kappa, 0.0);
  // Beyond the free end x = 0: the distance to the end point, signed by the normal's side.
  const ProfilePoint beyond = p.closest({-0.3, 1.6});
  EXPECT_TRUE(beyond.corner);
  EXPECT_NEAR(beyond.gap, 0.5, 1e-15);
  EXPECT_NEAR(beyond.n[0], -0.6, 1e-15);
}

// EXTENSION ZONE 0.1 of the 2-long line: up to 0.2 beyond its free end a point meets the line
// extended (the gap across it, the line's normal), farther out the end point as before; a
// point beside an interior corner is not affected (no free end there).
TEST(AnalyticalProfile, ExtensionZoneContinuesTheLineBeyondAFreeEnd) {
  const Profile p = Profile::build({2, 2}, std::vector{line_to(0, 2)}, 0.0);
  const ProfilePoint near = p.closest({-0.15, 2.01}, 0.1);  // 0.01 inside the punch
  EXPECT_FALSE(near.corner);
  EXPECT_NEAR(near.gap, -0.01, 1e-15);
  EXPECT_NEAR(near.distance, 0.01, 1e-15);
  EXPECT_NEAR(near.n[1], -1.0, 1e-15);
  EXPECT_NEAR(near.x[0], -0.15, 1e-15);
  EXPECT_NEAR(near.x[1], 2.0, 1e-15);
  EXPECT_TRUE(p.closest({-0.15, 2.01}).corner);  // no zone: the end point
  const ProfilePoint far = p.closest({-0.3, 1.6}, 0.1);
  EXPECT_TRUE(far.corner);
  EXPECT_NEAR(far.gap, 0.5, 1e-15);
  const Profile bent = Profile::build({0, 2}, std::vector{line_to(0, 0), line_to(2, 0)}, 0.0);
  EXPECT_TRUE(bent.closest({-0.1, -0.1}, 0.1).corner);  // the corner at (0, 0) joins two lines
}

TEST(AnalyticalProfile, FilletRoundsARightAngleCornerWithItsCircle) {
  // Down the line x = 0 from y = 2, then along y = 0 to x = 2: a left turn; the fillet's centre
  // is (r, r), and the profile near the corner is that circle, concave seen from its normal.
  const double r = 0.5;
  const Profile p = Profile::build({0, 2}, std::vector{line_to(0, 0), line_to(2, 0)}, r);
  ASSERT_EQ(p.pieces().size(), 3u);
  EXPECT_NEAR(p.pieces()[0].b[1], r, 1e-15);
  EXPECT_NEAR(p.pieces()[2].a[0], r, 1e-15);
  for (const Vec2& q : {Vec2{0.2, 0.1}, Vec2{-0.1, -0.3}}) {
    const ProfilePoint pp = p.closest(q);
    const double d = std::hypot(q[0] - r, q[1] - r);
    EXPECT_EQ(pp.piece, 1);
    // The normal of a path turning left points to its left: into the corner, at the centre.
    EXPECT_NEAR(pp.gap, r - d, 1e-14);
    EXPECT_NEAR(pp.kappa, -1.0 / r, 1e-14);
  }
}

TEST(AnalyticalProfile, BadProfilesNameTheirSegment) {
  auto segment_of = [](Vec2 start, std::vector<ProfileSegment> s, double fillet) {
    try {
      (void)Profile::build(start, s, fillet);
    } catch (const ProfileError& e) {
      return static_cast<int>(e.segment);
    }
    return -1;
  };
  EXPECT_EQ(segment_of({1, 0}, {line_to(2, 0), arc_to(-2, 0, 0, 0)}, 0.0), 1);    // a half circle
  EXPECT_EQ(segment_of({1, 0}, {arc_to(0, 1.1, 0, 0)}, 0.0), 0);                 // end off the circle
  EXPECT_EQ(segment_of({0, 1}, {line_to(0, 0), line_to(1, 0)}, 2.0), 1);        // fillet too large
  EXPECT_EQ(segment_of({0, 1}, {line_to(0, 1)}, 0.0), 0);                        // zero length
}

/// Central differences of the gap against the normal (its gradient) and of the normal against
/// the Hessian, at points around each shape.
void expect_consistent(const AnalyticalShape& shape, std::span<const Vec3> points, int dim) {
  const double h = 1e-6;
  for (const Vec3& p : points) {
    const ShapePoint sp = shape.closest(p);
    for (int j = 0; j < dim; ++j) {
      Vec3 a = p, b = p;
      a[j] += h;
      b[j] -= h;
      const ShapePoint pa = shape.closest(a), pb = shape.closest(b);
      EXPECT_NEAR((pa.gap - pb.gap) / (2 * h), sp.n[j], 1e-8) << "at " << p[0] << ", " << p[1] << ", " << p[2];
      for (int i = 0; i < dim; ++i)
        EXPECT_NEAR((pa.n[i] - pb.n[i]) / (2 * h), sp.hessian[3 * i + j], 1e-6)
            << "H(" << i << ", " << j << ") at " << p[0] << ", " << p[1] << ", " << p[2];
    }
  }
}

TEST(AnalyticalShape, CylinderAndRevolutionGapsAreConsistentToSecondOrder) {
  // A cylinder: the arc in local (x, y) with x along (1, 1, 0)/√2, generator along z.
  AnalyticalSurface cyl = lower_arc(AnalyticalSurface::Type::Cylinder);
  const double s = std::sqrt(0.5);
  cyl.origin = {0.5, -0.2, 1.0};
  cyl.axes = {{{s, s, 0}, {-s, s, 0}, {0, 0, 1}}};
  const AnalyticalShape c = AnalyticalShape::build(cyl, 3);
  const Vec3 cp[] = {{0.4, 1.1, -3.0}, {-0.3, 1.9, 0.4}, {0.9, 1.4, 2.0}};
  expect_consistent(c, cp, 3);
  // A sphere cap: the arc in (r, z) about the local origin, axis along z; with a fillet-free
  // corner turned into a cone where a LINE follows.
  AnalyticalSurface rev = surface(AnalyticalSurface::Type::Revolution, {1.6, -1.2},
                                  {arc_to(0.0, -2.0, 0.0, 0.0), line_to(-0.5, -2.0)});
  rev.origin = {0.1, 0.2, 3.0};
  const AnalyticalShape r = AnalyticalShape::build(rev, 3);
  const Vec3 rp[] = {{0.5, 0.9, 0.7}, {-0.6, 0.1, 1.4}, {1.2, -0.4, 1.6}, {0.3, 0.4, 1.2}};
  expect_consistent(r, rp, 3);
  // The sphere's gap is |p − c| − 2.
  for (const Vec3& p : rp) EXPECT_NEAR(r.closest(p).gap, test::dist(p, rev.origin) - 2.0, 1e-13);
}

TEST(AnalyticalShape, TypeMustFitTheModelDimension) {
  EXPECT_THROW((void)AnalyticalShape::build(lower_arc(AnalyticalSurface::Type::Segments), 3), std::invalid_argument);
  EXPECT_THROW((void)AnalyticalShape::build(lower_arc(AnalyticalSurface::Type::Revolution), 2), std::invalid_argument);
}

/// One C3D8 below an analytical cylinder carried by reference node 9 (rotation node 10), the
/// element's top face the slave.
model::Model cube_under_cylinder() {
  std::vector<Vec3> x = {{0, 0, 0}, {0.3, 0, 0}, {0.3, 0.3, 0}, {0, 0.3, 0}, {0, 0, 0.3}, {0.32, 0, 0.3}, {0.3, 0.31, 0.29}, {0, 0.3, 0.3}};
  x.push_back({0.1, 0.2, 0.9});  // reference node
  x.push_back({0.1, 0.2, 0.9});  // rotation node
  model::Model m = test::elements_model("C3D8", x, {{0, 1, 2, 3, 4, 5, 6, 7}}, {{0, 1}});
  AnalyticalSurface cyl = lower_arc(AnalyticalSurface::Type::Cylinder);
  cyl.origin = {0.0, 0.0, -0.6};  // its lowest line at z = 0.4, over the face at z ≈ 0.3
  cyl.axes = {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};  // profile (x, z), generator −y
  m.analytical_surfaces.push_back(cyl);
  model::Surface master;
  master.name = "M";
  master.kind = model::Surface::Kind::Analytical;
  master.analytical = 0;
  m.mesh.surfaces["M"] = master;
  model::RigidBody b;
  b.ref_node = 8;
  b.rot_node = 9;
  b.analytical_surface = 0;
  m.rigid_bodies.push_back(b);
  return m;
}

/// Every slave node's gap gradient against central differences over each unknown it lists
/// (`slave_entries` false: the reference and rotation nodes' alone).
void expect_gradients(bool surface_to_surface, bool slave_entries) {
  const model::Model m = cube_under_cylinder();
  AnalyticalPair pair(m, m.mesh.surfaces.at("S"), m.mesh.surfaces.at("M"), 3, 1.0, surface_to_surface);
  std::vector<Vec3> x = reference_coordinates(m.mesh.nodes);
  x[8] = {0.12, 0.18, 0.87};                   // the body moved
  x[9] = {0.1 + 0.2, 0.2 - 0.1, 0.9 + 0.15};  // and turned by θ = (0.2, −0.1, 0.15)
  std::vector<SlaveKinematics> kin;
  pair.update(x, kin);
  const double h = 1e-7;
  for (std::size_t i = 0; i < kin.size(); ++i) {
    ASSERT_TRUE(kin[i].found);
    pair.linearize(x, kin[i], true);
    const GapLinearization& lin = kin[i].lin;
    for (std::size_t a = 0; a < lin.nodes.size(); ++a)
      for (int c = 0; c < 3; ++c) {
        if (!slave_entries && lin.nodes[a] < 8) continue;
        std::vector<Vec3> xp = x, xm = x;
        xp[lin.nodes[a]][c] += h;
        xm[lin.nodes[a]][c] -= h;
        std::vector<SlaveKinematics> kp, km;
        pair.update(xp, kp);
        pair.update(xm, km);
        EXPECT_NEAR((kp[i].projection.gap - km[i].projection.gap) / (2 * h), lin.gradient[3 * a + c], 1e-7)
            << "slave " << i << ", node row " << lin.nodes[a] << ", component " << c;
      }
  }
}

TEST(AnalyticalPair, NodeGapGradientOverSlaveReferenceAndRotationMatchesDifferences) { expect_gradients(false, true); }

// The weights' change with the slave face's shape is left out of the weighted gap's slave
// entries (analytical_pair.hpp; it vanishes with the gap): the rigid body's entries are exact.
TEST(AnalyticalPair, WeightedGapGradientOverTheRigidBodyMatchesDifferences) { expect_gradients(true, false); }

}  // namespace
}  // namespace inpact::contact
