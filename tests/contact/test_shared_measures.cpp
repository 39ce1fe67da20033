// Contact's work shared out, over ranks and over threads, must not change a bit.
//
// A distributed run measures each slave node on one rank only (PairKinematics::set_measured_nodes,
// solver/slave_node_share.hpp) and gathers the measures: that is right only if a node's measure
// does not depend on which other nodes are measured, the set staying the same from update to
// update (the points' memos warm start the later ones). Checked here on one process: a pair that
// measures every other node gives those nodes the bits of a pair that measures them all (gap,
// area, overlap, projection, friction's own projection, linearisations) over successive
// updates, and leaves the others unfound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include "contact/geometric_correction.hpp"
#include "contact/node_to_surface.hpp"
#include "contact/surface_to_surface.hpp"
#include "parser/read_deck.hpp"

namespace inpact::test {
namespace {

model::Model read_model(const std::string& name) {
  parser::ReadResult r = parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/contact_verification/" + name);
  EXPECT_TRUE(r.ok()) << r.report();
  return std::move(r.model);
}

/// The reference coordinates moved by a smooth non-uniform field of amplitude `a` (facets turn
/// and stretch, points slide over the master).
std::vector<contact::Vec3> moved(const model::Model& m, double a) {
  std::vector<contact::Vec3> x(m.mesh.nodes.size());
  for (std::size_t n = 0; n < x.size(); ++n) {
    const auto& X = m.mesh.nodes.coords[n];
    x[n] = X;
    x[n][0] += a * std::sin(7.0 * X[1] + 3.0 * X[2]);
    x[n][1] += a * std::cos(5.0 * X[0] - 2.0 * X[2]);
    x[n][2] += a * std::sin(4.0 * X[0] + 6.0 * X[1]);
  }
  return x;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every measured node of `part` as `whole` has it, to the bit; the others unfound.
void expect_same_measures(contact::PairKinematics& whole, contact::PairKinematics& part, const std::vector<char>& mask,
                          std::span<const contact::Vec3> x) {
  std::vector<contact::SlaveKinematics> all, some;
  whole.update(x, all);
  part.update(x, some);
  ASSERT_EQ(all.size(), some.size());
  int found = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    SCOPED_TRACE("slave node " + std::to_string(i));
    EXPECT_EQ(all[i].node, some[i].node);
    if (!mask[i]) {
      EXPECT_FALSE(some[i].found);
      continue;
    }
    ASSERT_EQ(all[i].found, some[i].found);
    if (!all[i].found) continue;
    ++found;
    EXPECT_TRUE(same_bits(all[i].projection.gap, some[i].projection.gap));
    EXPECT_TRUE(same_bits(all[i].area, some[i].area));
    EXPECT_TRUE(same_bits(all[i].overlap, some[i].overlap));
    EXPECT_EQ(all[i].friction_found, some[i].friction_found);
    const contact::Projection &pa = all[i].projection, &pb = some[i].projection;
    EXPECT_EQ(pa.facet, pb.facet);
    EXPECT_EQ(pa.region, pb.region);
    for (int c = 0; c < 2; ++c) EXPECT_TRUE(same_bits(pa.xi[c], pb.xi[c]));
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(same_bits(pa.normal[c], pb.normal[c]));
      EXPECT_TRUE(same_bits(pa.x_master[c], pb.x_master[c]));
      EXPECT_TRUE(same_bits(pa.t1[c], pb.t1[c]));
      EXPECT_TRUE(same_bits(pa.t2[c], pb.t2[c]));
    }
    whole.linearize(x, all[i], true);
    part.linearize(x, some[i], true);
    EXPECT_EQ(all[i].lin.nodes, some[i].lin.nodes);
    ASSERT_EQ(all[i].lin.gradient.size(), some[i].lin.gradient.size());
    for (std::size_t a = 0; a < all[i].lin.gradient.size(); ++a)
      EXPECT_TRUE(same_bits(all[i].lin.gradient[a], some[i].lin.gradient[a]));
    EXPECT_EQ(all[i].friction_lin.nodes, some[i].friction_lin.nodes);
    ASSERT_EQ(all[i].friction_lin.gradient.size(), some[i].friction_lin.gradient.size());
    for (std::size_t a = 0; a < all[i].friction_lin.gradient.size(); ++a)
      EXPECT_TRUE(same_bits(all[i].friction_lin.gradient[a], some[i].friction_lin.gradient[a]));
  }
  EXPECT_GT(found, 0);  // (the test measures something)
}

template <class PairType>
void check_deck(const std::string& deck, bool smoothed) {
  const model::Model m = read_model(deck);
  const model::ContactPair& pair = m.contact_pairs.at(0);
  const auto& slave = m.mesh.surfaces.at(pair.slave);
  const auto& master = m.mesh.surfaces.at(pair.master);
  PairType whole(m, slave, master, 3, 1.0), part(m, slave, master, 3, 1.0);
  if (smoothed)
    for (PairType* p : {&whole, &part})
      p->set_geometric_correction(contact::build_corrections(m, pair.master, &pair),
                                  contact::build_corrections(m, pair.slave, &pair));
  std::vector<char> mask(whole.slave().nodes().size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = i % 2 == 0 ? 1 : 0;
  part.set_measured_nodes(mask);
  // Three configurations in turn: the later updates start from the points' memos.
  const double facet = whole.search_radius();
  for (double a : {0.0, 0.02 * facet, 0.05 * facet}) {
    SCOPED_TRACE("wobble " + std::to_string(a));
    expect_same_measures(whole, part, mask, moved(m, a));
  }
}

TEST(MeasuredNodes, SurfaceToSurfaceSmoothedGivesTheWholePairsBits) {
  check_deck<contact::SurfaceToSurfacePair>("spherical_seat_3d_smoothed.inp", true);
}

TEST(MeasuredNodes, SurfaceToSurfaceGivesTheWholePairsBits) {
  check_deck<contact::SurfaceToSurfacePair>("sphere_3d.inp", false);
}

TEST(MeasuredNodes, NodeToSurfaceGivesTheWholePairsBits) {
  check_deck<contact::NodeToSurfacePair>("sphere_3d.inp", false);
}

TEST(MeasuredNodes, NodeToSurfaceSmoothedGivesTheWholePairsBits) {
  check_deck<contact::NodeToSurfacePair>("spherical_seat_3d_smoothed.inp", true);
}

/// linearize_nodes() on 2 threads (the points' caches filled first, facet by facet) against
/// linearize() node after node on one: the same bits for every found node.
template <class PairType>
void check_threads(const std::string& deck, bool smoothed) {
  const model::Model m = read_model(deck);
  const model::ContactPair& pair = m.contact_pairs.at(0);
  PairType one(m, m.mesh.surfaces.at(pair.slave), m.mesh.surfaces.at(pair.master), 3, 1.0);
  PairType two(m, m.mesh.surfaces.at(pair.slave), m.mesh.surfaces.at(pair.master), 3, 1.0);
  if (smoothed)
    for (PairType* p : {&one, &two})
      p->set_geometric_correction(contact::build_corrections(m, pair.master, &pair),
                                  contact::build_corrections(m, pair.slave, &pair));
  two.set_threads(2);
  const auto x = moved(m, 0.02 * one.search_radius());
  std::vector<contact::SlaveKinematics> a, b;
  one.update(x, a);
  two.update(x, b);
  std::vector<std::size_t> nodes;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].found) nodes.push_back(i);
  ASSERT_GT(nodes.size(), 16u);  // (enough for two threads)
  for (std::size_t i : nodes) one.linearize(x, a[i], true);
  two.linearize_nodes(x, b, nodes, true);
  for (std::size_t i : nodes) {
    SCOPED_TRACE("slave node " + std::to_string(i));
    EXPECT_EQ(a[i].lin.nodes, b[i].lin.nodes);
    ASSERT_EQ(a[i].lin.gradient.size(), b[i].lin.gradient.size());
    for (std::size_t k = 0; k < a[i].lin.gradient.size(); ++k) EXPECT_TRUE(same_bits(a[i].lin.gradient[k], b[i].lin.gradient[k]));
    ASSERT_EQ(a[i].lin.hessian.size(), b[i].lin.hessian.size());
    for (std::size_t k = 0; k < a[i].lin.hessian.size(); ++k) EXPECT_TRUE(same_bits(a[i].lin.hessian[k], b[i].lin.hessian[k]));
  }
}

TEST(LinearizeNodes, TwoThreadsGiveOneThreadsBitsSmoothed) {
  check_threads<contact::SurfaceToSurfacePair>("spherical_seat_3d_smoothed.inp", true);
}

TEST(LinearizeNodes, TwoThreadsGiveOneThreadsBits) {
  check_threads<contact::SurfaceToSurfacePair>("sphere_3d.inp", false);
}

}  // namespace
}  // namespace inpact::test
