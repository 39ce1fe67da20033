// Contact stabilization (contact/contact_stabilization.hpp): the damping kernel against central
// finite differences and hand values, the scale factors (ramp, per increment, gap), and the rule
// each interaction resolves to in each step (which form wins, what carries over).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "contact/contact_stabilization.hpp"
#include "contact/initial_adjustment.hpp"
#include "contact/patch_test.hpp"
#include "contact/resolved_interaction.hpp"
#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

/// A slave node over a 3-node master facet in 3D: ∇g = [n; −N_a n], Σ N_a = 1.
struct NodeOnFacet {
  contact::Vec3 n{0.0, 0.6, 0.8}, t1{1.0, 0.0, 0.0}, t2{0.0, 0.8, -0.6};
  std::vector<double> gradient;
  NodeOnFacet() {
    const double shape[3] = {0.2, 0.5, 0.3};
    for (int c = 0; c < 3; ++c) gradient.push_back(n[c]);
    for (double na : shape)
      for (int c = 0; c < 3; ++c) gradient.push_back(-na * n[c]);
  }
};

/// The kernel at local displacements u (u_start = 0), the gap moving with them: g = g0 + ∇g·u.
contact::DampingContribution damping_at(const NodeOnFacet& k, const std::vector<double>& u, double g0, double range) {
  double g = g0;
  for (std::size_t i = 0; i < u.size(); ++i) g += k.gradient[i] * u[i];
  contact::DampingInput in{.gradient = k.gradient, .normal = k.n, .t1 = k.t1, .t2 = k.t2, .dim = 3, .du = u,
                           .area = 0.7, .gap = g, .range = range, .stiffness = 40.0, .tangent_fraction = 0.3};
  contact::DampingContribution out;
  contact::damping_contribution(in, out);
  return out;
}

TEST(ContactStabilization, DampingTangentMatchesCentralDifferences) {
  const NodeOnFacet k;
  std::vector<double> u(12);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-3 * std::sin(1.7 * static_cast<double>(i) + 0.3);
  for (double g0 : {0.02, -0.01}) {  // open within the range (the s_gap slope acts), and closed
    const auto at = damping_at(k, u, g0, 0.1);
    const double h = 1e-7;
    double worst = 0.0, largest = 0.0;
    for (std::size_t j = 0; j < u.size(); ++j) {
      auto up = u, um = u;
      up[j] += h;
      um[j] -= h;
      const auto fp = damping_at(k, up, g0, 0.1).force, fm = damping_at(k, um, g0, 0.1).force;
      for (std::size_t i = 0; i < u.size(); ++i) {
        const double fd = (fp[i] - fm[i]) / (2.0 * h);
        worst = std::max(worst, std::abs(fd - at.tangent[i * u.size() + j]));
        largest = std::max(largest, std::abs(fd));
      }
    }
    EXPECT_LT(worst, 1e-6 * largest) << "g0 = " << g0;
    double work = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) work += at.force[i] * u[i];
    EXPECT_NEAR(at.dissipated, work, 1e-14);
    EXPECT_GT(at.dissipated, 0.0);
  }
}

TEST(ContactStabilization, NormalDampingIsTheStiffnessOnTheGapChange) {
  const NodeOnFacet k;
  // The slave node moves by d along n, the facet stays: Δg = d; closed, so s_gap = 1; no tangential motion.
  const double d = 2e-3;
  std::vector<double> u(12, 0.0);
  for (int c = 0; c < 3; ++c) u[static_cast<std::size_t>(c)] = d * k.n[c];
  const auto at = damping_at(k, u, -0.05, 0.1);
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(at.force[i], 0.7 * 40.0 * d * k.gradient[i], 1e-15);
  EXPECT_NEAR(at.dissipated, 0.7 * 40.0 * d * d, 1e-15);
  // A tangential slide t1 of the slave: the tangential part only, s_tang k.
  std::vector<double> slide(12, 0.0);
  for (int c = 0; c < 3; ++c) slide[static_cast<std::size_t>(c)] = d * k.t1[c];
  EXPECT_NEAR(damping_at(k, slide, -0.05, 0.1).dissipated, 0.3 * 0.7 * 40.0 * d * d, 1e-15);
}

TEST(ContactStabilization, ARigidTranslationIsNotDamped) {
  const NodeOnFacet k;
  std::vector<double> u(12);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = (i % 3 == 0 ? 1e-3 : i % 3 == 1 ? -2e-3 : 5e-4);
  const auto at = damping_at(k, u, 0.0, 0.1);
  for (double f : at.force) EXPECT_NEAR(f, 0.0, 1e-15);
}

TEST(ContactStabilization, GapFactorFallsLinearlyToTheRange) {
  EXPECT_EQ(contact::gap_factor(-1.0, 0.5), 1.0);
  EXPECT_EQ(contact::gap_factor(0.0, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(contact::gap_factor(0.125, 0.5), 0.75);
  EXPECT_EQ(contact::gap_factor(0.5, 0.5), 0.0);
  EXPECT_EQ(contact::gap_factor(2.0, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(contact::gap_factor_slope(0.125, 0.5), -2.0);
  EXPECT_EQ(contact::gap_factor_slope(-0.1, 0.5), 0.0);
}

TEST(ContactStabilization, RampAndReductionPerIncrement) {
  contact::StabilizationRule general;  // *CONTACT STABILIZATION, SCALE FACTOR=2 (defaults otherwise)
  general.scale = 2.0;
  general.reduction_per_increment = 0.1;
  EXPECT_DOUBLE_EQ(general.scale_at(0.0, 2.0, 1, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(general.scale_at(0.5, 2.0, 1, 0.0), 2.0 * 0.75);
  EXPECT_NEAR(general.scale_at(0.5, 2.0, 3, 0.0), 2.0 * 0.75 * 0.01, 1e-15);
  EXPECT_EQ(general.scale_at(2.0, 2.0, 1, 0.0), 0.0);  // the converged end of the step is undamped
  general.amplitude = "A";  // a named amplitude replaces the ramp
  EXPECT_DOUBLE_EQ(general.scale_at(2.0, 2.0, 2, 0.4), 2.0 * 0.4 * 0.1);
  contact::StabilizationRule pairwise;  // *CONTACT CONTROLS, STABILIZE with an end factor 0.2
  pairwise.end_factor = 0.2;
  EXPECT_DOUBLE_EQ(pairwise.scale_at(0.5, 1.0, 7, 0.0), 0.6);
  EXPECT_DOUBLE_EQ(pairwise.scale_at(1.0, 1.0, 9, 0.0), 0.2);
}

/// The patch deck with `steps` appended and `first` inserted in its step; the rules of each step.
std::vector<std::optional<contact::StabilizationRule>> rules(const std::string& first, const std::string& steps) {
  std::string text = read_text(contact_deck("patch_2d_direct.inp"));
  text.insert(text.find("*STEP"), "*AMPLITUDE, NAME=DOWN\n0, 1, 1, 0.5\n");
  text.insert(text.find("*END STEP"), first);
  text += steps;
  const DeckDir dir;
  auto deck = dir.read(text);
  EXPECT_TRUE(deck.ok()) << deck.report();
  contact::apply_adjust(deck.model);
  std::vector<std::optional<contact::StabilizationRule>> out;
  for (const auto& step : solver::build_analysis_model(deck.model).interactions) out.push_back(step.at(0).stabilization);
  return out;
}

TEST(ContactStabilization, PairwiseControlsWinAndOnlyAnAmplitudeCarriesOver) {
  const std::string step = "*STEP\n*STATIC\n0.5, 1.0\n{}*END STEP\n";
  auto with = [&](const std::string& body) {
    std::string s = step;
    return s.replace(s.find("{}"), 2, body);
  };
  const auto r = rules("*CONTACT STABILIZATION, AMPLITUDE=DOWN, TANGENT FRACTION=0.5\nSLAVE_S, MASTER_S\n"
                       "*CONTACT CONTROLS, STABILIZE=2\n,0.25, 0.1\n",
                       with("") + with("*CONTACT STABILIZATION, RESET\n") + with("*CONTACT STABILIZATION, RANGE=0.3\n") +
                           with(""));
  ASSERT_EQ(r.size(), 5u);
  ASSERT_TRUE(r[0]);  // step 1: *CONTACT CONTROLS, STABILIZE over *CONTACT STABILIZATION
  EXPECT_TRUE(r[0]->pairwise);
  EXPECT_EQ(r[0]->scale, 2.0);
  EXPECT_EQ(r[0]->tangent_fraction, 1.0);
  EXPECT_EQ(r[0]->end_factor, 0.25);
  EXPECT_EQ(r[0]->range, 0.1);
  EXPECT_FALSE(r[0]->coefficient_given);
  // The automatic coefficient φ k_e T (k_e = M/0.5 of the patch decks, T = 1).
  EXPECT_NEAR(r[0]->coefficient, contact::kContactDampingFraction * kM / kSlaveElementHeight, 1e-12);
  ASSERT_TRUE(r[1]);  // step 2: STABILIZE is for its step only; the amplitude carries over
  EXPECT_FALSE(r[1]->pairwise);
  EXPECT_EQ(r[1]->amplitude, "DOWN");
  EXPECT_EQ(r[1]->tangent_fraction, 0.5);
  EXPECT_EQ(r[1]->range, kSlaveFacet);  // the default range: l_char
  EXPECT_EQ(r[1]->reduction_per_increment, 0.1);
  EXPECT_FALSE(r[2]);  // RESET
  ASSERT_TRUE(r[3]);
  EXPECT_EQ(r[3]->range, 0.3);
  EXPECT_FALSE(r[4]);  // a ramp to zero does not carry over
}

}  // namespace
}  // namespace inpact::test
