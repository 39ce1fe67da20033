// Node to surface beside a free end of the master (contact/node_to_surface.hpp): within the
// EXTENSION ZONE (a fraction of the facet's size) a slave node meets the facet's plane extended;
// farther beside the end it does not face the master and is not found. A convex corner, where
// two facets meet, keeps the distance to the corner. The master here is the
// top edge of one CPE4, from (1, 1) to (0, 1), outward normal +y; both its ends are free.
#include <gtest/gtest.h>

#include "contact/node_to_surface.hpp"
#include "contact_test_util.hpp"

using namespace inpact;
using inpact::test::elements_model;

namespace {

constexpr double kTol = 1e-12;

/// The block, the master "S" (its top face), and a node-based slave "SLAVE" at `points`.
model::Model block_and_points(const std::vector<contact::Vec3>& points) {
  std::vector<contact::Vec3> coords{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  coords.insert(coords.end(), points.begin(), points.end());
  model::Model m = elements_model("CPE4", coords, {{0, 1, 2, 3}}, {{0, 2}});
  model::Surface slave;
  slave.name = "SLAVE";
  slave.kind = model::Surface::Kind::Node;
  for (std::size_t i = 0; i < points.size(); ++i) {
    slave.nodes.push_back(static_cast<std::int32_t>(4 + i));
    slave.node_areas.push_back(1.0);
  }
  m.mesh.surfaces["SLAVE"] = slave;
  return m;
}

std::vector<contact::SlaveKinematics> project(const model::Model& m, double zone) {
  contact::NodeToSurfacePair nts(m, m.mesh.surfaces.at("SLAVE"), m.mesh.surfaces.at("S"), 2, 1.0);
  nts.set_extension_zone(zone);
  std::vector<contact::SlaveKinematics> out;
  nts.update(m.mesh.nodes.coords, out);
  return out;
}

}  // namespace

TEST(NodeToSurface, ANodeBesideAFreeEndMeetsTheExtendedPlaneWithinTheZone) {
  const model::Model m = block_and_points({{1.05, 0.999, 0}, {1.5, 0.999, 0}, {1.5, 1.0, 0}, {0.5, 0.99, 0}, {1.05, 1.2, 0}});
  const auto k = project(m, 0.1);
  ASSERT_EQ(k.size(), 5u);
  // 0.05 beside the end (zone 0.1 of the unit edge), 0.001 below the plane: a penetration along +y.
  ASSERT_TRUE(k[0].found);
  EXPECT_TRUE(k[0].projection.extended);
  EXPECT_NEAR(k[0].projection.gap, -0.001, kTol);
  EXPECT_NEAR(k[0].projection.normal[1], 1.0, kTol);
  // 0.5 beside it: not facing the master, whatever side of the plane (the gap's sign would be
  // round-off of a sideways distance).
  EXPECT_FALSE(k[1].found);
  EXPECT_FALSE(k[2].found);
  // Over the edge: the ordinary projection.
  ASSERT_TRUE(k[3].found);
  EXPECT_FALSE(k[3].projection.extended);
  EXPECT_NEAR(k[3].projection.gap, -0.01, kTol);
  // Above the end, within the zone: open by its height over the plane, not its distance to the end.
  ASSERT_TRUE(k[4].found);
  EXPECT_TRUE(k[4].projection.extended);
  EXPECT_NEAR(k[4].projection.gap, 0.2, kTol);
}

TEST(NodeToSurface, AConvexCornerKeepsTheDistanceToTheCorner) {
  // The block's top and right faces as master: (1.2, 1.1) lies beyond the top face's end, in
  // the corner's wedge: its gap is its distance to the corner, along that direction.
  model::Model m = block_and_points({{1.2, 1.1, 0}});
  m.mesh.surfaces["S"].faces.push_back({0, 1});
  const auto k = project(m, 0.1);
  ASSERT_TRUE(k[0].found);
  EXPECT_FALSE(k[0].projection.extended);
  EXPECT_NEAR(k[0].projection.gap, std::hypot(0.2, 0.1), kTol);
  EXPECT_NEAR(k[0].projection.normal[0], 0.2 / std::hypot(0.2, 0.1), kTol);
}

TEST(NodeToSurface, NoExtensionZoneDropsTheNodeBesideTheEnd) {
  const auto k = project(block_and_points({{1.05, 0.999, 0}}), 0.0);
  EXPECT_FALSE(k[0].found);
}

TEST(NodeToSurface, TheExtendedPlaneHasTheFacetsGradientAndNoCurvature) {
  const model::Model m = block_and_points({{1.05, 0.999, 0}});
  contact::NodeToSurfacePair nts(m, m.mesh.surfaces.at("SLAVE"), m.mesh.surfaces.at("S"), 2, 1.0);
  std::vector<contact::SlaveKinematics> k;
  nts.update(m.mesh.nodes.coords, k);
  ASSERT_TRUE(k[0].found);
  nts.linearize(m.mesh.nodes.coords, k[0], true);
  // u = [x_s; x_end; x_other]: ∂g/∂x_s = n, the end vertex carries −n (N = 1 there).
  EXPECT_NEAR(k[0].lin.gradient[1], 1.0, kTol);
  EXPECT_NEAR(k[0].lin.gradient[0], 0.0, kTol);
  double master_sum = 0.0;
  for (std::size_t a = 2; a < k[0].lin.gradient.size(); a += 2) master_sum += k[0].lin.gradient[a + 1];
  EXPECT_NEAR(master_sum, -1.0, kTol);
  for (double h : k[0].lin.hessian) EXPECT_EQ(h, 0.0);
}
