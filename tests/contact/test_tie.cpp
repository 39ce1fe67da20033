// *TIE resolution (contact/tie.hpp, contact/tie_mortar.hpp) on two unit cubes meeting at x = 1:
// closest-point weights against the bilinear shape functions by hand, the dual-mortar weights
// of matching faces (the identity), and the mortar rows' linear-field reproduction
// Σ_l W_jl x_l = x_j on a non-matching 2 × 2 slave face over a 1 × 1 master face.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/tie.hpp"
#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;

namespace {

/// Cube A = [0,1]³ (one C3D8, nodes 1-8); block B = [1,2]×[0,1]² as n × n × 1 C3D8 (nodes from
/// 101), its x = 1 nodes moved to `x_face`; `tie` is the *TIE block.
std::string two_blocks(int n, double x_face, const std::string& tie, double y0 = 0.0) {
  std::string d = "*NODE\n";
  for (int a = 0; a < 8; ++a)
    d += std::to_string(a + 1) + "," + std::to_string((a % 4 == 1 || a % 4 == 2) ? 1 : 0) + "," +
         std::to_string(y0 + ((a % 4 >= 2) ? 1 : 0)) + "," + std::to_string(a >= 4 ? 1 : 0) + "\n";
  auto lab = [&](int i, int j, int k) { return 101 + i + 2 * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= 1; ++i)
        d += std::to_string(lab(i, j, k)) + "," + std::to_string(i == 0 ? x_face : 2.0) + "," +
             std::to_string(y0 + double(j) / n) + "," + std::to_string(double(k) / n) + "\n";
  d += "*ELEMENT, TYPE=C3D8, ELSET=A\n1,1,2,3,4,5,6,7,8\n*ELEMENT, TYPE=C3D8, ELSET=B\n";
  int e = 101;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      d += std::to_string(e++) + "," + std::to_string(lab(0, j, k)) + "," + std::to_string(lab(1, j, k)) + "," +
           std::to_string(lab(1, j + 1, k)) + "," + std::to_string(lab(0, j + 1, k)) + "," + std::to_string(lab(0, j, k + 1)) +
           "," + std::to_string(lab(1, j, k + 1)) + "," + std::to_string(lab(1, j + 1, k + 1)) + "," +
           std::to_string(lab(0, j + 1, k + 1)) + "\n";
  d += "*SURFACE, NAME=A_RIGHT\nA, S4\n*SURFACE, NAME=B_LEFT\nB, S6\n*SOLID SECTION, ELSET=A, MATERIAL=M\n"
       "*SOLID SECTION, ELSET=B, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n" + tie + "*STEP\n*STATIC\n*END STEP\n";
  return d;
}

const contact::TiedNode& tied(const model::Model& m, const contact::ResolvedTie& r, int label) {
  for (const auto& n : r.tied)
    if (m.mesh.nodes.labels[n.slave] == label) return n;
  throw std::runtime_error("node not tied");
}

double weight_of(const model::Model& m, const contact::TiedNode& n, int label) {
  for (std::size_t k = 0; k < n.masters.size(); ++k)
    if (m.mesh.nodes.labels[n.masters[k]] == label) return n.weights[k];
  return 0.0;
}

}  // namespace

TEST(Tie, ClosestPointWeightsAreTheMasterShapeFunctions) {
  DeckDir dir;
  // 2 × 2 slave face on A's x = 1 face: the middle node (1, 0.5, 0.5) and the edge node (1, 0.5, 0).
  auto r = dir.read(two_blocks(2, 1.0, "*TIE, NAME=T, TYPE=NODE TO SURFACE\nB_LEFT, A_RIGHT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto ties = contact::resolve_ties(r.model);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].tied.size(), 9u);
  EXPECT_NEAR(ties[0].tolerance, 0.05 * std::sqrt(2.0), 1e-15);  // 5 % of the master facet diagonal
  const auto& m = r.model;
  const int middle = 101 + 0 + 2 * (1 + 3 * 1), edge = 101 + 0 + 2 * (1 + 3 * 0);
  for (int a : {2, 3, 6, 7}) EXPECT_NEAR(weight_of(m, tied(m, ties[0], middle), a), 0.25, 1e-14) << a;
  // (y, z) = (0.5, 0): half each to nodes 2 (0, 0) and 3 (1, 0).
  EXPECT_NEAR(weight_of(m, tied(m, ties[0], edge), 2), 0.5, 1e-14);
  EXPECT_NEAR(weight_of(m, tied(m, ties[0], edge), 3), 0.5, 1e-14);
  EXPECT_EQ(tied(m, ties[0], edge).masters.size(), 2u);
}

TEST(Tie, MortarWeightsOfMatchingFacesAreTheIdentity) {
  DeckDir dir;
  auto r = dir.read(two_blocks(1, 1.0, "*TIE, NAME=T\nB_LEFT, A_RIGHT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto ties = contact::resolve_ties(r.model);
  ASSERT_EQ(ties[0].n_mortar, 4u);
  const auto& m = r.model;
  for (const auto& n : ties[0].tied) {
    double off = 0.0, on = 0.0;
    for (std::size_t k = 0; k < n.masters.size(); ++k) {
      const bool same = m.mesh.nodes.coords[n.masters[k]] == m.mesh.nodes.coords[n.slave];
      (same ? on : off) += std::abs(n.weights[k]);
    }
    EXPECT_NEAR(on, 1.0, 1e-13);
    EXPECT_LE(off, 1e-13);
  }
}

TEST(Tie, MortarRowsReproduceALinearField) {
  DeckDir dir;
  auto r = dir.read(two_blocks(3, 1.0, "*TIE, NAME=T\nB_LEFT, A_RIGHT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto ties = contact::resolve_ties(r.model);
  const auto& m = r.model;
  ASSERT_EQ(ties[0].n_mortar, 16u);
  double worst = 0.0;
  for (const auto& n : ties[0].tied) {
    double sum = 0.0;
    std::array<double, 3> x{0, 0, 0};
    for (std::size_t k = 0; k < n.masters.size(); ++k) {
      sum += n.weights[k];
      for (int c = 0; c < 3; ++c) x[c] += n.weights[k] * m.mesh.nodes.coords[n.masters[k]][c];
    }
    worst = std::max(worst, std::abs(sum - 1.0));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(x[c] - m.mesh.nodes.coords[n.slave][c]));
  }
  EXPECT_LE(worst, 1e-13);
}

TEST(Tie, AdjustNoKeepsTheGapAndTiedNsetTiesAtAnyDistance) {
  DeckDir dir;
  auto r = dir.read(two_blocks(1, 1.3, "*NSET, NSET=FEW\n101, 103\n*TIE, NAME=T, TIED NSET=FEW, ADJUST=NO\nB_LEFT, A_RIGHT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto ties = contact::resolve_ties(r.model);
  ASSERT_EQ(ties[0].tied.size(), 2u);
  EXPECT_NEAR(ties[0].largest_distance, 0.3, 1e-12);
  EXPECT_FALSE(r.model.ties[0].adjust);
}

// Far from the origin (|x| / facet size = 300), the facet projection's round-off exceeds its
// absolute Newton tolerance; the tie projects on coordinates relative to each facet and still
// finds every slave node on the master (distance 0, interior weights).
TEST(Tie, SlaveNodesOnAFacetFarFromTheOriginAreTied) {
  DeckDir dir;
  auto r = dir.read(two_blocks(3, 1.0, "*TIE, NAME=T, TYPE=NODE TO SURFACE\nB_LEFT, A_RIGHT\n", 300.0));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto ties = contact::resolve_ties(r.model);
  EXPECT_EQ(ties[0].tied.size(), 16u);
  EXPECT_TRUE(ties[0].untied.empty());
  EXPECT_LE(ties[0].largest_distance, 1e-12);
}
