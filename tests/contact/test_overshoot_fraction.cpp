// ContactProblem::overshoot_fraction (solver/newton.cpp's limit_overshoot for augmented
// Lagrange): the fraction of a Newton correction that takes no node that was open deeper into
// the master than the deepest node of its pair was, by hand on the 2D patch of
// change_surface_behavior_2d.inp in its augmented-Lagrange step (slave nodes 101 … 105 on the
// lower block's top y = 1; a node moved down by d penetrates d).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "parser/read_deck.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/contact_problem.hpp"
#include "solver/dof_map.hpp"
#include "solver/step_conditions.hpp"

namespace inpact::test {
namespace {

constexpr std::size_t kAugmentedStep = 3;

/// The patch deck's augmented-Lagrange step, with slave nodes placed by their y displacement.
struct AugmentedPatch {
  AugmentedPatch()
      : deck(parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/contact/change_surface_behavior_2d.inp")),
        am(solver::build_analysis_model(deck.model)),
        conditions(am, deck.model.steps[kAugmentedStep], solver::initial_history(am), 0.0),
        dofs(solver::DofMap::build(am, conditions.prescribed())),
        assembler(am, dofs),
        contact(am, kAugmentedStep) {
    contact.begin_attempt(state, static_cast<int>(kAugmentedStep) + 1, 1, std::vector<double>(am.n_dof(), 0.0));
  }

  /// The contact update with each listed slave node moved by `uy` (the others at rest).
  void place(const std::map<int, double>& uy) {
    std::vector<double> u(am.n_dof(), 0.0);
    const auto& labels = am.model->mesh.nodes.labels;
    for (const auto& [label, v] : uy) {
      const auto row = std::find(labels.begin(), labels.end(), label) - labels.begin();
      u[static_cast<std::size_t>(row) * am.dim + 1] = v;
    }
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

TEST(OvershootFraction, AnOpenNodeStopsAtTheDeepestClosedOne) {
  AugmentedPatch patch;
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

}  // namespace
}  // namespace inpact::test
