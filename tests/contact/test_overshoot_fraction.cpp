// The limits solver/newton.cpp's limit_correction puts on a Newton correction, by hand:
//  - ContactProblem::overshoot_fraction (augmented Lagrange): the fraction of a correction that
//    takes no node that was open deeper into the master than the deepest node of its pair was,
//    on the 2D patch of change_surface_behavior_2d.inp in its augmented-Lagrange step (slave
//    nodes 101 … 105 on the lower block's top y = 1; a node moved down by d penetrates d);
//  - ContactProblem::slip_reversal_fraction (friction): the fraction at which no slipping node
//    has turned its slip around, on friction_slide_2d_penalty.inp (slave nodes 101 … 103 on
//    the base's top y = 0.5, penalty k = 2.692e4, μ = 0.3, elastic slip 0.0025: a node moved
//    down by 1e-3 slips beyond 0.0025 of x motion from where it first touched).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures/deck_fixture.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/contact_problem.hpp"
#include "solver/dof_map.hpp"
#include "solver/step_conditions.hpp"

namespace inpact::test {
namespace {

/// A contact deck's step (its index), with slave nodes placed by their displacement.
struct Patch {
  Patch(const std::string& deck_name, std::size_t step)
      : Patch(parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + deck_name), step) {}
  Patch(parser::ReadResult read, std::size_t step)
      : deck(std::move(read)),
        am(solver::build_analysis_model(deck.model)),
        conditions(am, deck.model.steps[step], solver::initial_history(am), 0.0),
        dofs(solver::DofMap::build(am, conditions.prescribed())),
        assembler(am, dofs),
        contact(am, step) {
    contact.begin_attempt(state, static_cast<int>(step) + 1, 1, std::vector<double>(am.n_dof(), 0.0));
  }

  /// The contact update with each listed slave node moved by `uy` (the others at rest).
  void place(const std::map<int, double>& uy) { place({}, uy); }
  /// The same with x displacements `ux` too.
  void place(const std::map<int, double>& ux, const std::map<int, double>& uy) {
    std::vector<double> u(am.n_dof(), 0.0);
    const auto& labels = am.model->mesh.nodes.labels;
    const auto row = [&](int label) { return static_cast<std::size_t>(std::find(labels.begin(), labels.end(), label) - labels.begin()); };
    for (const auto& [label, v] : ux) u[row(label) * am.dim] = v;
    for (const auto& [label, v] : uy) u[row(label) * am.dim + 1] = v;
    contact.update(u, state, assembler);
  }

  parser::ReadResult deck;
  solver::AnalysisModel am;
  solver::StepConditions conditions;
  solver::DofMap dofs;
  solver::Assembler assembler;
  solver::ContactProblem contact;
  solver::ContactState state;
};

/// A penalty pair of the block's top against the base, open by the block's height throughout.
const std::string kOpenPenaltyPair =
    "*SURFACE INTERACTION, NAME=OTHER\n*SURFACE BEHAVIOR, PENALTY\n"
    "*CONTACT PAIR, INTERACTION=OTHER, TYPE=NODE TO SURFACE\nTOP_S, MASTER_S\n";

/// A deck of decks/contact with kOpenPenaltyPair inserted before its line `anchor` (listed before
/// the deck's own pair); empty when the deck has no such line.
std::string with_an_open_pair_before(const std::string& deck_name, const std::string& anchor) {
  std::ifstream in(std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + deck_name);
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const auto at = deck.find(anchor);
  if (at == std::string::npos) return {};
  return deck.insert(at, kOpenPenaltyPair);
}

TEST(OvershootFraction, AnOpenNodeStopsAtTheDeepestClosedOne) {
  Patch patch("change_surface_behavior_2d.inp", 3);  // its augmented-Lagrange step
  ASSERT_TRUE(patch.contact.has_augmented_lagrange());
  // Before: 103 penetrates 0.002 (the deepest), the others are open by 0.001.
  patch.place({{101, 0.001}, {102, 0.001}, {103, -0.002}, {104, 0.001}, {105, 0.001}});
  const solver::AugmentedPenetrations before = patch.contact.augmented_penetrations();
  // After: 102 penetrates 0.005; it reaches 0.002 at (0.002 + 0.001) / (0.005 + 0.001) = 1/2 of
  // the correction. 104 stops short of 0.002 and 103, closed before, may go deeper.
  patch.place({{101, 0.001}, {102, -0.005}, {103, -0.01}, {104, -0.001}, {105, 0.001}});
  EXPECT_NEAR(patch.contact.overshoot_fraction(before), 0.5, 1e-12);
  // No open node beyond the deepest: the whole correction.
  patch.place({{101, 0.001}, {102, -0.0015}, {103, -0.01}, {104, -0.001}, {105, 0.001}});
  EXPECT_EQ(patch.contact.overshoot_fraction(before), 1.0);
  // Far beyond: at least 1 % of the correction, so that Newton still moves.
  patch.place({{101, 0.001}, {102, -0.4}, {103, -0.01}, {104, 0.001}, {105, 0.001}});
  EXPECT_EQ(patch.contact.overshoot_fraction(before), 1e-2);
}

// The fraction reads each augmented pair's penetrations, whatever pairs come before it: the
// same figures with a penalty pair listed first.
TEST(OvershootFraction, APenaltyPairBeforeTheAugmentedOneChangesNothing) {
  const std::string deck = with_an_open_pair_before("change_surface_behavior_2d.inp", "*CONTACT PAIR, INTERACTION=SMOOTH");
  ASSERT_FALSE(deck.empty());
  parser::ReadResult read = DeckDir().read(deck);
  ASSERT_TRUE(read.ok());
  Patch patch(std::move(read), 3);  // its augmented-Lagrange step
  ASSERT_EQ(patch.contact.describe().size(), 2u);  // both pairs in force
  patch.place({{101, 0.001}, {102, 0.001}, {103, -0.002}, {104, 0.001}, {105, 0.001}});
  const solver::AugmentedPenetrations before = patch.contact.augmented_penetrations();
  ASSERT_EQ(before.pairs.size(), 1u);  // the augmented pair's penetrations only
  patch.place({{101, 0.001}, {102, -0.005}, {103, -0.01}, {104, -0.001}, {105, 0.001}});
  EXPECT_NEAR(patch.contact.overshoot_fraction(before), 0.5, 1e-12);
  patch.place({{101, 0.001}, {102, -0.0015}, {103, -0.01}, {104, -0.001}, {105, 0.001}});
  EXPECT_EQ(patch.contact.overshoot_fraction(before), 1.0);
}

TEST(SlipReversalFraction, ASlippingNodeStopsWhereItsSlipTurns) {
  Patch patch("friction_slide_2d_penalty.inp", 0);
  ASSERT_TRUE(patch.contact.has_friction());
  const std::map<int, double> pressed{{101, -1e-3}, {102, -1e-3}, {103, -1e-3}};
  patch.place({}, pressed);  // where each node touched: its zero-shear point
  // Before: 101 and 102 slip to +x (e_tr = 0.01), 103 sticks (0.001 < 0.0025).
  patch.place({{101, 0.01}, {102, 0.01}, {103, 0.001}}, pressed);
  const solver::SlippingTrials before = patch.contact.slipping_trials(patch.state);
  // After: 101 slips to −x, e_tr = −0.03: e_tr(f) = 0.01 − 0.04 f turns at f = 1/4. 102 slips on
  // (+0.02), 103 now slips to −x but did not slip before: neither limits.
  patch.place({{101, -0.03}, {102, 0.02}, {103, -0.05}}, pressed);
  EXPECT_NEAR(patch.contact.slip_reversal_fraction(before, patch.state), 0.25, 1e-12);
  // 101 back to a stick (|e_tr| = 0.001 on the other side): no slip turned around.
  patch.place({{101, -0.001}, {102, 0.02}, {103, -0.05}}, pressed);
  EXPECT_EQ(patch.contact.slip_reversal_fraction(before, patch.state), 1.0);
  // Far beyond, turning within 1 % of the correction (f = 1e-4 / (1e-4 + 1e-2)): at 1 %, e_tr =
  // −1e-4 lies in the stick zone, so the cut stops there.
  patch.place({{101, -1.0}, {102, 0.02}, {103, -0.05}}, pressed);
  EXPECT_EQ(patch.contact.slip_reversal_fraction(before, patch.state), 1e-2);
  // A node that turns later than another does not change the fraction: 102 turns at 1/3.
  patch.place({{101, -0.03}, {102, -0.02}, {103, -0.05}}, pressed);
  EXPECT_NEAR(patch.contact.slip_reversal_fraction(before, patch.state), 0.25, 1e-12);
  // A node that slipped barely beyond its stick zone (0.003 > 0.0025) and turns to −1: at 1 % of
  // the correction e_tr = −0.00703 slips the other way already, so it does not limit.
  patch.place({{101, 0.003}, {102, 0.0}, {103, 0.0}}, pressed);
  const solver::SlippingTrials barely = patch.contact.slipping_trials(patch.state);
  patch.place({{101, -1.0}, {102, 0.0}, {103, 0.0}}, pressed);
  EXPECT_EQ(patch.contact.slip_reversal_fraction(barely, patch.state), 1.0);
}

// The fraction reads each frictional pair's trials, whatever pairs come before it: the same
// figures as above with a frictionless pair listed first.
TEST(SlipReversalFraction, AFrictionlessPairBeforeTheFrictionalOneChangesNothing) {
  const std::string deck = with_an_open_pair_before("friction_slide_2d_penalty.inp", "*CONTACT PAIR, INTERACTION=ROUGHISH");
  ASSERT_FALSE(deck.empty());
  parser::ReadResult read = DeckDir().read(deck);
  ASSERT_TRUE(read.ok());
  Patch patch(std::move(read), 0);
  ASSERT_TRUE(patch.contact.has_friction());
  ASSERT_EQ(patch.contact.describe().size(), 2u);  // both pairs in force
  const std::map<int, double> pressed{{101, -1e-3}, {102, -1e-3}, {103, -1e-3}};
  patch.place({}, pressed);
  patch.place({{101, 0.01}, {102, 0.01}, {103, 0.001}}, pressed);
  const solver::SlippingTrials before = patch.contact.slipping_trials(patch.state);
  ASSERT_EQ(before.size(), 1u);  // the frictional pair's trials only
  patch.place({{101, -0.03}, {102, 0.02}, {103, -0.05}}, pressed);
  EXPECT_NEAR(patch.contact.slip_reversal_fraction(before, patch.state), 0.25, 1e-12);
  patch.place({{101, -0.001}, {102, 0.02}, {103, -0.05}}, pressed);
  EXPECT_EQ(patch.contact.slip_reversal_fraction(before, patch.state), 1.0);
}

}  // namespace
}  // namespace inpact::test
