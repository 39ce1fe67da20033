// The increment controller with a real plastic material: an increment whose Newton iterations
// fail is cut back, and the attempt after the cutback starts from the committed plastic state of
// the last converged increment — the failed attempt's plastic flow leaves no trace.
//
// The bar of decks/verification/plastic_bar_c3d8.inp (uniaxial, linear hardening H = 20000,
// residuals to 1e-12) is pulled to ε = 8e-3 in one step with an initial increment of the whole
// period and at most I_C = 4 equilibrium iterations: the first attempts need 5 and are cut back,
// and so are later ones as the increment grows again (INC=1000: some hundred increments).
// On this radial uniaxial path backward Euler is exact for any increment size, so the plastic
// strain of every converged increment is the closed form εᵖ(ε) = (σ(ε) − σ_y)/H,
// σ = σ_y + E_t (ε − σ_y/E), to round-off: a state that had kept anything of a failed attempt
// (which flowed to a larger strain) would not be.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_model.hpp"
#include "solver/elements/mises_plasticity.hpp"
#include "solver/material_states.hpp"

using namespace inpact;
using namespace inpact::solver;

namespace {

constexpr double kE = 200000.0, kSy = 250.0, kH = 20000.0, kEpsMax = 8e-3;

double plastic_strain_at(double eps) {
  const double Et = kE * kH / (kE + kH), eps_y = kSy / kE;
  return eps <= eps_y ? 0.0 : Et * (eps - eps_y) / kH;
}

/// The bar deck's first step alone, one increment asked for, at most 4 iterations an attempt.
std::string cutback_deck() {
  std::ifstream in(std::string(INPACT_SOURCE_DIR) + "/decks/verification/plastic_bar_c3d8.inp");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  s = s.substr(0, s.find("*STEP, NAME=UNLOAD"));
  s.replace(s.find("*STEP, NAME=LOAD"), 16, "*STEP, NAME=LOAD, INC=1000");  // many cut-back increments
  const std::string direct = "*STATIC, DIRECT\n0.1, 1.\n";
  s.replace(s.find(direct), direct.size(), "*STATIC\n1., 1.\n*CONTROLS, PARAMETERS=TIME INCREMENTATION\n, , , 4\n");
  return s;
}

/// PEEQ of element 0, point 0, committed and trial, when each attempt finished (before the loop
/// commits or discards).
struct PeeqWatch : AnalysisObserver {
  struct Seen {
    StatusRow row;
    double committed, trial;
  };
  explicit PeeqWatch(const MaterialStates& s) : states(s) {}
  void attempt_finished(const StatusRow& row) override {
    using L = elements::MisesStateLayout;
    seen.push_back({row, states.committed(0)[L::equivalent], states.trial(0)[L::equivalent]});
  }
  const MaterialStates& states;
  std::vector<Seen> seen;
};

}  // namespace

TEST(PlasticCutback, FailedAttemptsLeaveTheCommittedPlasticStateUntouched) {
  test::DeckDir dir;
  const auto r = dir.read(cutback_deck());
  ASSERT_TRUE(r.ok()) << r.report();
  const AnalysisModel am = build_analysis_model(r.model);
  MaterialStates states(am);
  ASSERT_FALSE(states.empty());  // plastic: 4 elements × 8 points × 7 values, twice
  EXPECT_EQ(states.bytes(), 5 * sizeof(std::size_t) + 4 * sizeof(std::uint32_t) + 2 * 4 * 8 * 7 * sizeof(double));
  PeeqWatch watch(states);
  const AnalysisOutcome outcome = run_steps(am, states, watch);
  ASSERT_TRUE(outcome.completed) << outcome.message;

  ASSERT_GE(watch.seen.size(), 2u);
  EXPECT_TRUE(watch.seen[0].row.cut_back);  // the whole period in one increment: 5 iterations needed
  int cutbacks = 0;
  double committed_before = 0.0;  // PEEQ of the last converged increment
  for (const auto& s : watch.seen) {
    const double eps_end = kEpsMax * (s.row.step_time + (s.row.cut_back ? s.row.inc_of_time : 0.0));
    // Every attempt starts from the last converged increment's state.
    EXPECT_EQ(s.committed, committed_before) << "increment " << s.row.increment << " attempt " << s.row.attempt;
    EXPECT_NEAR(s.committed, plastic_strain_at(kEpsMax * (s.row.step_time - (s.row.cut_back ? 0 : s.row.inc_of_time))),
                1e-15) << "increment " << s.row.increment;
    if (s.row.cut_back) {
      ++cutbacks;
      EXPECT_GT(s.trial, s.committed);  // the failed attempt did flow plastically...
      continue;                         // ...and the next attempt must not see it
    }
    EXPECT_NEAR(s.trial, plastic_strain_at(eps_end), 1e-15) << "increment " << s.row.increment;
    committed_before = s.trial;
  }
  EXPECT_GE(cutbacks, 2);
  // After the step: the closed form at ε = 8e-3 (εᵖ = 6.136e-3) at every point, to round-off.
  using L = elements::MisesStateLayout;
  for (std::size_t e = 0; e < 4; ++e)
    for (std::size_t p = 0; p < 8; ++p)
      EXPECT_NEAR(states.committed(e)[p * 7 + L::equivalent], plastic_strain_at(kEpsMax), 1e-15);
}

namespace {

/// Records the .sta rows and the messages.
struct Rows : AnalysisObserver {
  void attempt_finished(const StatusRow& row) override { rows.push_back(row); }
  void message(std::string_view text) override { messages.emplace_back(text); }
  std::vector<StatusRow> rows;
  std::vector<std::string> messages;
};

}  // namespace

// An increment that converges with a plastic strain increment beyond fifty times the strain of
// first yield (50 σ_y/E = 0.0625) is cut back, as Abaqus/Standard does: the bar pulled to
// ε = 0.1 in one increment (Δε̄ᵖ ≈ 0.098) converges but is refused; a quarter (Δε̄ᵖ ≈ 0.024) is
// accepted. Every converged increment stays exact.
TEST(PlasticCutback, PlasticStrainIncrementFarBeyondFirstYieldIsCutBack) {
  std::string text = cutback_deck();
  text.replace(text.find(", , , 4\n"), 8, ", , , 16\n");  // the default I_C: Newton itself converges
  text.replace(text.find("RIGHT, 1, 1, 0.032"), 18, "RIGHT, 1, 1, 0.4");  // ε = 0.1
  test::DeckDir dir;
  const auto r = dir.read(text);
  ASSERT_TRUE(r.ok()) << r.report();
  const AnalysisModel am = build_analysis_model(r.model);
  MaterialStates states(am);
  Rows rows;
  const AnalysisOutcome outcome = run_steps(am, states, rows);
  ASSERT_TRUE(outcome.completed) << outcome.message;
  ASSERT_GE(rows.rows.size(), 2u);
  EXPECT_TRUE(rows.rows[0].cut_back);
  EXPECT_EQ(rows.rows[0].inc_of_time, 1.0);
  EXPECT_FALSE(rows.rows[1].cut_back);
  EXPECT_EQ(rows.rows[1].inc_of_time, 0.25);
  ASSERT_FALSE(rows.messages.empty());
  EXPECT_NE(rows.messages[0].find("the strain increment has exceeded fifty times the strain to cause first yield at 32 "
                                  "points"), std::string::npos) << rows.messages[0];
  using L = elements::MisesStateLayout;
  EXPECT_NEAR(states.committed(0)[L::equivalent], plastic_strain_at(0.1), 1e-15);
}
