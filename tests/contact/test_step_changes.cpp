// Contact changed between steps: *CHANGE FRICTION, *CHANGE SURFACE BEHAVIOR and *MODEL CHANGE,
// TYPE=CONTACT PAIR, resolved per step (contact/step_changes.hpp, resolved_interaction.hpp) and
// run on the decks of decks/contact/ against hand values, with the contact state they carry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/resolved_interaction.hpp"
#include "contact/step_changes.hpp"
#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/contact_problem.hpp"
#include "verification/verification_fixture.hpp"

namespace inpact::test {
namespace {

using verification::Run;

std::string contact_deck(const std::string& name) { return std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + name; }

const solver::FieldData& fd(const solver::Frame& f, const std::string& key) {
  const auto* p = verification::field(f, key);
  if (!p) throw std::runtime_error("frame has no field " + key);
  return *p;
}

/// Σ RF component c over a node set.
double set_reaction(const Run& r, const solver::Frame& f, const std::string& set, int c) {
  double s = 0.0;
  for (std::int32_t n : verification::nset(r.model(), set)) s += verification::nodal(f, "RF", static_cast<std::size_t>(n), c);
  return s;
}

parser::ReadResult read(const std::string& deck) {
  parser::ReadResult r = parser::read_deck(contact_deck(deck));
  EXPECT_TRUE(r.ok()) << r.report();
  return r;
}

// --- Resolution: what check and run enforce in each step ------------------------------------

TEST(StepChangesResolution, ChangeFrictionRampsResetsAndKeepsOtherSteps) {
  const parser::ReadResult deck = read("change_friction_2d.inp");
  const solver::AnalysisModel am = solver::build_analysis_model(deck.model);
  ASSERT_EQ(am.interactions.size(), 4u);
  // Step 1: the model data's μ = 0 (frictionless).
  ASSERT_EQ(am.interactions[0].size(), 1u);
  EXPECT_FALSE(am.interactions[0][0].friction);
  // Step 2: μ = 0.3, ramped from frictionless by the step (RAMP): μ(a) = 0.3 a.
  const contact::ResolvedInteraction& slide = am.interactions[1][0];
  ASSERT_TRUE(slide.friction);
  EXPECT_DOUBLE_EQ(slide.friction->mu, 0.3);
  ASSERT_TRUE(slide.friction_ramp);
  EXPECT_FALSE(slide.friction_ramp->from);
  EXPECT_DOUBLE_EQ(slide.friction_at(0.0)->mu, 0.0);
  EXPECT_DOUBLE_EQ(slide.friction_at(0.5)->mu, 0.15);
  EXPECT_DOUBLE_EQ(slide.friction_at(1.0)->mu, 0.3);
  EXPECT_DOUBLE_EQ(slide.friction_at(0.5)->gamma_crit, 0.005 * 0.5);  // SLIP TOLERANCE × facet, unchanged
  EXPECT_NE(contact::describe(slide).find("Coulomb friction mu = 0.3"), std::string::npos) << contact::describe(slide);
  EXPECT_NE(contact::describe(slide).find("*CHANGE FRICTION: from frictionless at the step start"), std::string::npos);
  // Step 3 (*STEP, AMPLITUDE=STEP): μ = 0.5 at once, no ramp.
  const contact::ResolvedInteraction& faster = am.interactions[2][0];
  EXPECT_DOUBLE_EQ(faster.friction->mu, 0.5);
  EXPECT_FALSE(faster.friction_ramp);
  EXPECT_DOUBLE_EQ(faster.friction_at(0.0)->mu, 0.5);
  // Step 4: RESET, the model data's μ = 0 again.
  EXPECT_FALSE(am.interactions[3][0].friction);
  // The one function every record comes from.
  EXPECT_DOUBLE_EQ(contact::interaction_in_step(deck.model, "SLIDING", 2)->friction->mu, 0.5);
  EXPECT_DOUBLE_EQ(contact::interaction_in_step(deck.model, "SLIDING", 3)->friction->mu, 0.0);
}

TEST(StepChangesResolution, ARemovedPairHasNoRecordUntilItIsAddedBack) {
  const parser::ReadResult deck = read("model_change_2d.inp");
  const solver::AnalysisModel am = solver::build_analysis_model(deck.model);
  EXPECT_EQ(am.interactions[0].size(), 1u);
  EXPECT_TRUE(am.interactions[1].empty());
  EXPECT_EQ(am.interactions[2].size(), 1u);
  EXPECT_EQ(contact::rows_removed_in(deck.model, *am.contact, 1), std::vector<std::size_t>{0});
  EXPECT_TRUE(contact::rows_removed_in(deck.model, *am.contact, 2).empty());
  EXPECT_TRUE(solver::ContactProblem(am, 1).empty());
}

TEST(StepChangesResolution, ChangeSurfaceBehaviorGivesEachStepItsLaw) {
  const parser::ReadResult deck = read("change_surface_behavior_2d.inp");
  const solver::AnalysisModel am = solver::build_analysis_model(deck.model);
  ASSERT_EQ(am.interactions.size(), 4u);
  EXPECT_DOUBLE_EQ(am.interactions[0][0].law->max_slope(0.0), 1e4);
  EXPECT_DOUBLE_EQ(am.interactions[1][0].law->max_slope(0.0), 4e4);
  EXPECT_EQ(am.interactions[2][0].enforcement, contact::EnforcementKind::DirectMultipliers);
  EXPECT_EQ(am.interactions[3][0].enforcement, contact::EnforcementKind::AugmentedLagrange);
}

// What inpact cannot change is a deck error where the change is written (check and run alike).
TEST(StepChangesResolution, TheTiedLawCannotStartInALaterStep) {
  DeckDir dir;
  const std::string path =
      dir.write("deck.inp", "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n5, 0, 1\n6, 1, 1\n7, 1, 2\n8, 0, 2\n"
                            "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1, 2, 3, 4\n2, 5, 6, 7, 8\n*ELSET, ELSET=E1\n1\n"
                            "*ELSET, ELSET=E2\n2\n*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n"
                            "1000, 0.3\n*SURFACE, NAME=LOW\nE1, S3\n*SURFACE, NAME=UP\nE2, S1\n"
                            "*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e4\n"
                            "*FRICTION\n0.1, 100\n*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE\nUP, LOW\n"
                            "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=I\n"
                            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1e4\n*END STEP\n");
  const parser::ReadResult r = parser::read_deck(path);
  ASSERT_TRUE(r.ok()) << r.report();
  try {
    (void)solver::build_analysis_model(r.model);
    FAIL() << "TIED in a *CHANGE SURFACE BEHAVIOR was accepted";
  } catch (const std::exception& e) {  // what `inpact check` and `inpact run` print
    EXPECT_NE(std::string(e.what()).find("deck.inp:35:1: error: *SURFACE BEHAVIOR: *CHANGE SURFACE BEHAVIOR to "
                                         "PRESSURE-OVERCLOSURE=TIED"),
              std::string::npos)
        << e.what();
  }
}

// --- The state carried between steps ------------------------------------------------------

TEST(StepChangesState, APairAddedBackStartsOpenAndAChangedMethodStartsItsMultipliersAtZero) {
  const parser::ReadResult deck = read("model_change_2d.inp");
  const solver::AnalysisModel am = solver::build_analysis_model(deck.model);
  solver::ContactProblem added(am, 2);
  const std::vector<double> u(static_cast<std::size_t>(am.n_dof()), 0.0);
  solver::ContactState state;
  state.pairs.assign(1, std::vector<solver::SlaveState>(5));
  for (auto& s : state.pairs[0]) {
    s.closed = true;
    s.lambda = -6.7;
  }
  solver::ContactState later = state;
  added.begin_attempt(state, 3, 1, u);  // the step's first increment: reset
  ASSERT_EQ(state.pairs[0].size(), 5u);
  for (const auto& s : state.pairs[0]) {
    EXPECT_FALSE(s.closed);
    EXPECT_EQ(s.lambda, 0.0);
  }
  for (auto& s : state.pairs[0]) s.closed = true;
  added.begin_attempt(state, 3, 1, u);  // an augmentation of that increment (same state): no reset
  for (const auto& s : state.pairs[0]) EXPECT_TRUE(s.closed);
  added.begin_attempt(later, 3, 2, u);  // a later increment keeps the state
  for (const auto& s : later.pairs[0]) EXPECT_TRUE(s.closed);

  // Direct (step 3) → augmented Lagrange (step 4): direct's λ = −p must not become the augmented λ.
  const parser::ReadResult sb = read("change_surface_behavior_2d.inp");
  const solver::AnalysisModel am_sb = solver::build_analysis_model(sb.model);
  solver::ContactProblem augmented(am_sb, 3);
  solver::ContactState st;
  st.pairs.assign(1, std::vector<solver::SlaveState>(5));
  for (auto& s : st.pairs[0]) {
    s.closed = true;
    s.lambda = -10.0;
  }
  augmented.begin_attempt(st, 4, 1, std::vector<double>(static_cast<std::size_t>(am_sb.n_dof()), 0.0));
  for (const auto& s : st.pairs[0]) {
    EXPECT_TRUE(s.closed);  // the status is kept, only the multipliers restart
    EXPECT_EQ(s.lambda, 0.0);
  }
}

// --- The decks against hand values -----------------------------------------------------------

// A block pressed by p = 10 and slid with every node moved in x (the pressure stays p at every
// slave node): CSHEAR = μ(t) p at every frame, μ(t) = 0.3 t/T in step 2 (ramped from 0), 0.5 in
// step 3 (AMPLITUDE=STEP), 0 after RESET; the block's x-reaction is μ(t) p × 1; the slip of step
// 2 is kept by step 3.
TEST(StepChangesDecks, ChangeFrictionGivesShearMuTimesPressure) {
  auto r = verification::run_deck(contact_deck("change_friction_2d.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double p = 10.0;
  double worst = 0.0;
  int frames = 0;
  for (const auto& sf : r->capture.frames) {
    const solver::Frame& f = sf.frame;
    const double mu = sf.step == 1 ? 0.0 : sf.step == 2 ? 0.3 * f.step_time : sf.step == 3 ? 0.5 : 0.0;
    const auto& cpress = fd(f, "CPRESS");
    const auto& cshear = fd(f, "CSHEAR1");
    for (std::size_t i = 0; i < cpress.values.size(); ++i) {
      EXPECT_NEAR(cpress.values[i], sf.step == 1 ? p * f.step_time : p, 1e-9 * p) << "step " << sf.step;
      worst = std::max(worst, std::abs(std::abs(cshear.values[i]) - mu * p) / p);
    }
    const double rf1 = set_reaction(*r, f, "BLOCK_N", 0);
    EXPECT_NEAR(rf1, mu * p * 1.0, 1e-6 * std::max(mu * p, 1.0)) << "step " << sf.step << " t " << f.step_time;
    ++frames;
  }
  EXPECT_EQ(frames, 2 + 4 + 2 + 1);
  EXPECT_LE(worst, 1e-9);
  // The slip history: 0.05 in step 2, 0.1 at the end of step 3 (friction changed, history kept).
  const auto slide = r->capture.of_step(2), faster = r->capture.of_step(3);
  for (double s : fd(*slide.back(), "CSLIP1").values) EXPECT_NEAR(std::abs(s), 0.05, 1e-9);
  for (double s : fd(*faster.back(), "CSLIP1").values) EXPECT_NEAR(std::abs(s), 0.1, 1e-9);
  std::printf("[step changes] *CHANGE FRICTION: max ||CSHEAR| - mu(t) p|/p = %.2e over %d frames; step-2 end shear "
              "%.12g (mu p = 3), step-3 %.12g (5)\n",
              worst, frames, std::abs(fd(*slide.back(), "CSHEAR1").values[0]),
              std::abs(fd(*faster.back(), "CSHEAR1").values[0]));
}

// Two blocks pressed by d = 0.01 at the top: N = M d (uniaxial strain d/2 over width 2). The pair
// removed: the bottom reaction is (1 − t/T) N and zero at the end (the upper block held by its
// top only, stress free); added back: N again.
TEST(StepChangesDecks, ModelChangeReleasesTheContactForceAndAddsThePairBack) {
  auto r = verification::run_deck(contact_deck("model_change_2d.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double m = 1000.0 * 0.7 / (1.3 * 0.4), n = m * 0.01;
  const auto press = r->capture.of_step(1), removed = r->capture.of_step(2), added = r->capture.of_step(3);
  ASSERT_EQ(removed.size(), 4u);
  EXPECT_NEAR(set_reaction(*r, *press.back(), "BOTTOM", 1), n, 1e-9 * n);
  for (double cp : fd(*press.back(), "CPRESS").values) EXPECT_NEAR(cp, m * 0.005, 1e-9 * n);
  double worst = 0.0;
  for (const solver::Frame* f : removed) {
    const double expected = (1.0 - f->step_time) * n;
    worst = std::max(worst, std::abs(set_reaction(*r, *f, "BOTTOM", 1) - expected) / n);
    worst = std::max(worst, std::abs(set_reaction(*r, *f, "TOP", 1) + expected) / n);
    EXPECT_EQ(verification::field(*f, "CPRESS"), nullptr);  // the pair is not in force: no contact output
  }
  EXPECT_LE(worst, 1e-9);
  // Held by its BCs only: the upper block translated by −d, the lower one back at rest.
  for (std::int32_t node : verification::nset(r->model(), "TOP"))
    EXPECT_NEAR(verification::nodal(*removed.back(), "U", static_cast<std::size_t>(node), 1), -0.01, 1e-12);
  for (std::int32_t row = 0; row < 9; ++row)  // the lower block's nodes (labels 1-9)
    EXPECT_NEAR(verification::nodal(*removed.back(), "U", static_cast<std::size_t>(row), 1), 0.0, 1e-12);
  EXPECT_NEAR(set_reaction(*r, *added.back(), "BOTTOM", 1), n, 1e-9 * n);
  for (double cp : fd(*added.back(), "CPRESS").values) EXPECT_NEAR(cp, m * 0.005, 1e-9 * n);
  std::printf("[step changes] *MODEL CHANGE: N = %.10g; removal step reactions within %.2e N of (1 - t/T) N; added "
              "back: %.10g\n",
              n, worst, set_reaction(*r, *added.back(), "BOTTOM", 1));
}

// The patch test under p = 10 with the penalty changed from step to step: penetration p/k.
TEST(StepChangesDecks, ChangeSurfaceBehaviorGivesThePenetrationOfTheNewStiffness) {
  auto r = verification::run_deck(contact_deck("change_surface_behavior_2d.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double p = 10.0;
  const double expected[] = {p / 1e4, p / 4e4, 0.0};
  for (int step = 1; step <= 4; ++step) {
    const solver::Frame& f = *r->capture.of_step(step).back();
    for (double cp : fd(f, "CPRESS").values) EXPECT_NEAR(cp, p, 1e-9 * p) << "step " << step;
    for (double open : fd(f, "COPEN").values) {
      if (step <= 3) EXPECT_NEAR(-open, expected[step - 1], 1e-9 * p / 1e4) << "step " << step;
      else EXPECT_LE(-open, 0.001 * 0.5) << "augmented Lagrange within its tolerance";
    }
  }
  // Step 4 needed augmentations (p/k = 2 × the tolerance), each keeping the λ of the last.
  int augmentations = 0;
  for (const auto& row : r->capture.rows)
    if (row.step == 4 && !row.cut_back) augmentations += row.augmentations;
  EXPECT_GE(augmentations, 1);
  EXPECT_LE(augmentations, 10);
  std::printf("[step changes] *CHANGE SURFACE BEHAVIOR: penetration %.10g (p/k1 = 1e-3), %.10g (p/k2 = 2.5e-4), "
              "%.3g after %d augmentations (tolerance 5e-4)\n",
              -fd(*r->capture.of_step(1).back(), "COPEN").values[0], -fd(*r->capture.of_step(2).back(), "COPEN").values[0],
              -fd(*r->capture.of_step(4).back(), "COPEN").values[0], augmentations);
}

}  // namespace
}  // namespace inpact::test
