// `--solver petsc` (CG or GMRES with GAMG; MUMPS for multipliers) solves the same Newton
// iterations as the direct solvers: on a representative subset of the contact decks — one per
// linear system the PETSc path meets — every field of every frame equals the direct run's to
// 1e-6 of the field's largest value over the step (for the lengths COPEN and CSLIP: of the
// step's largest |U|, a closed contact's COPEN being round-off), with the same iterations.
// The Krylov tolerance (solver/linear_solve.hpp, krylov_tolerance) holds the linear residual at
// 1e-8 of Newton's force measure, so 1e-6 is a bound with a margin of 100 the rule is built for;
// bench/petsc_solver/compare_solvers.py runs every deck and method.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "contact/initial_adjustment.hpp"
#include "fixtures/deck_fixture.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis.hpp"
#include "solver/linear/petsc_module.hpp"
#include "verification/verification_fixture.hpp"

namespace inpact {
namespace {

struct SolvedRun {
  parser::ReadResult deck;
  verification::Capture capture;
  solver::AnalysisOutcome outcome;
};

std::unique_ptr<SolvedRun> solve(const std::string& path, const std::map<std::string, std::string>& params,
                                 solver::SolverKind kind) {
  auto r = std::make_unique<SolvedRun>();
  parser::ReadOptions options;
  options.parameters = params;
  r->deck = parser::read_deck(path, options);
  EXPECT_TRUE(r->deck.ok()) << r->deck.report();
  contact::apply_adjust(r->deck.model);  // as `inpact run` does after reading
  solver::AnalysisOptions analysis;
  analysis.linear_solver = kind;
  r->outcome = solver::run_analysis(r->deck.model, r->capture, analysis);
  return r;
}

constexpr double kRoundOffFloor = 1e-12;

bool is_length(const std::string& key) { return key == "COPEN" || key == "CSLIP1" || key == "CSLIP2"; }

/// The largest |value| of each field over the frames of each step.
std::map<std::pair<int, std::string>, double> field_scales(const verification::Capture& c) {
  std::map<std::pair<int, std::string>, double> out;
  for (const auto& f : c.frames)
    for (const auto& field : f.frame.fields)
      for (double v : field.values) out[{f.step, field.key}] = std::max(out[{f.step, field.key}], std::abs(v));
  return out;
}

void expect_same_results(const std::string& deck, const std::map<std::string, std::string>& params) {
  if (!solver::petsc_built()) GTEST_SKIP() << "built without PETSc";
  const auto direct = solve(deck, params, solver::SolverKind::Direct);
  const auto petsc = solve(deck, params, solver::SolverKind::Petsc);
  ASSERT_TRUE(direct->outcome.completed) << direct->outcome.message;
  ASSERT_TRUE(petsc->outcome.completed) << petsc->outcome.message;
  EXPECT_EQ(petsc->capture.iterations, direct->capture.iterations);
  ASSERT_EQ(petsc->capture.frames.size(), direct->capture.frames.size());
  const auto scales = field_scales(direct->capture);
  double worst = 0.0;
  for (std::size_t i = 0; i < direct->capture.frames.size(); ++i) {
    const auto& a = direct->capture.frames[i];
    const auto& b = petsc->capture.frames[i].frame;
    ASSERT_EQ(a.frame.fields.size(), b.fields.size());
    for (std::size_t k = 0; k < a.frame.fields.size(); ++k) {
      const auto& fa = a.frame.fields[k];
      const auto& fb = b.fields[k];
      ASSERT_EQ(fa.key, fb.key);
      ASSERT_EQ(fa.values.size(), fb.values.size()) << fa.key;
      double scale = scales.at({a.step, fa.key});
      if (is_length(fa.key)) scale = std::max(scale, scales.count({a.step, "U"}) ? scales.at({a.step, "U"}) : 0.0);
      for (std::size_t j = 0; j < fa.values.size(); ++j) {
        // No projection (COPEN of a slave node outside every master facet) is NaN in both.
        ASSERT_EQ(std::isnan(fa.values[j]), std::isnan(fb.values[j])) << fa.key << " frame " << i << " value " << j;
        if (std::isnan(fa.values[j])) continue;
        // (a field of round-off alone — RM of a model without moments — is compared as `compare`
        // does: absolutely, to 1e-12)
        const double diff = std::abs(fa.values[j] - fb.values[j]);
        if (diff <= kRoundOffFloor) continue;
        const double rel = scale > 0 ? diff / scale : diff;
        worst = std::max(worst, rel);
        ASSERT_LE(rel, 1e-6) << fa.key << " frame " << i << " value " << j << ": " << fa.values[j] << " vs "
                             << fb.values[j] << " (scale " << scale << ")";
      }
    }
  }
  ::testing::Test::RecordProperty("worst_relative_difference", std::to_string(worst));
}

std::string verification_deck(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/contact_verification/" + name + ".inp";
}
std::string contact_deck(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + name + ".inp";
}

// Multipliers: a saddle-point system, LU by MUMPS.
TEST(PetscMatchesDirect, DirectMultipliersHertz2dNonmatching) {
  expect_same_results(verification_deck("hertz_2d_nonmatching"), {{"method", "DIRECT"}});
}
// Penalty: symmetric positive definite, CG + GAMG.
TEST(PetscMatchesDirect, PenaltyHertz2dNonmatching) {
  expect_same_results(verification_deck("hertz_2d_nonmatching"), {{"method", "PENALTY"}});
}
// Augmented Lagrange: CG + GAMG across multiplier updates.
TEST(PetscMatchesDirect, AugmentedLagrangeHertz2dNonmatching) {
  expect_same_results(verification_deck("hertz_2d_nonmatching"), {{"method", "AUGMENTED LAGRANGE"}});
}
// A 3D deck with contact stabilization: CG + GAMG with the six rigid-body modes.
TEST(PetscMatchesDirect, StabilizedGap3d) { expect_same_results(verification_deck("contact_stabilization_gap_3d"), {}); }
// Friction with penalty: an unsymmetric tangent, GMRES + GAMG.
TEST(PetscMatchesDirect, FrictionPenaltySlide2d) { expect_same_results(contact_deck("friction_slide_2d_penalty"), {}); }
// Friction with multipliers: an unsymmetric saddle point, MUMPS.
TEST(PetscMatchesDirect, FrictionDirectSlide3d) { expect_same_results(contact_deck("friction_slide_3d_direct"), {}); }
// A stiff penalty (augmented Lagrange on a smoothed interference fit, k ≈ 2e9) turns the last
// 6e-11 of the displacements into CPRESS: at the default R_n = 5e-3 two correct Newton paths,
// direct against a tighter direct alike, end 7e-5 of the largest CPRESS apart. So the solvers
// are compared where Newton has converged that far: *CONTROLS R_n = 1e-9.
TEST(PetscMatchesDirect, StiffAugmentedLagrangeAtNewtonsTightTolerance) {
  std::ifstream in(verification_deck("spherical_seat_3d_smoothed"));
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const auto at = deck.find("*CONTACT CONTROLS");
  ASSERT_NE(at, std::string::npos);
  deck.insert(at, "*CONTROLS, PARAMETERS=FIELD\n1e-9, 1e-9\n");
  const test::DeckDir dir;
  expect_same_results(dir.write("seat_tight.inp", deck), {{"method", "AUGMENTED LAGRANGE"}});
}
// Shells (S4) with rotation nodes: in contact with a block (multipliers, MUMPS, the rotation
// slots in the layout), and bolted by a pretension section (CG + GAMG with the near-null-space
// modes that turn the rotation nodes, solver/linear/rigid_body_modes.hpp).
TEST(PetscMatchesDirect, ShellsOnABlock) {
  expect_same_results(std::string(INPACT_SOURCE_DIR) + "/decks/verification/shell_on_block_s4.inp", {});
}
TEST(PetscMatchesDirect, PretensionedShells) {
  expect_same_results(std::string(INPACT_SOURCE_DIR) + "/decks/verification/pretension_shell_s4.inp", {});
}

}  // namespace
}  // namespace inpact
