// The increment controller with a real plastic material: an increment whose Newton iterations
// fail is cut back, and the attempt after the cutback starts from the committed plastic state of
// the last converged increment — the failed attempt's plastic flow leaves no trace.
//
// The bar of decks/verification/plastic_bar_c3d8.inp (uniaxial, residuals to 1e-12), here pulled
// by a force (σ = 315 at the end of the step) against a hardening curve of four segments, in one
// step with an initial increment of the whole period and at most I_C = 3 equilibrium iterations:
// Newton crosses about a segment an iteration, so the first attempts need more and are cut
// back (a prescribed displacement would not do: the first iteration carries it through the
// bar, which then converges at once). On this radial uniaxial path backward Euler is exact for
// any increment size, so the plastic strain of every converged increment is the curve's
// inverse at σ(t) = 315 t to round-off: a state that had kept anything of a failed attempt
// (which flowed further) would not be.
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

constexpr double kE = 200000.0, kSy = 250.0, kH = 20000.0, kEpsMax = 8e-3, kSigmaMax = 315.0;

double plastic_strain_at(double eps) {
  const double Et = kE * kH / (kE + kH), eps_y = kSy / kE;
  return eps <= eps_y ? 0.0 : Et * (eps - eps_y) / kH;
}

/// ε̄ᵖ on the force-driven deck's curve (250, 0) (270, 0.001) (285, 0.002) (300, 0.004) (320, 0.01).
double plastic_strain_at_stress(double sigma) {
  const double s[] = {250, 270, 285, 300, 320}, e[] = {0, 0.001, 0.002, 0.004, 0.01};
  if (sigma <= s[0]) return 0.0;
  std::size_t k = 0;
  while (sigma > s[k + 1]) ++k;
  return e[k] + (sigma - s[k]) / (s[k + 1] - s[k]) * (e[k + 1] - e[k]);
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

/// The same bar pulled by the force σ = 315 on its end face (a quarter on each of its nodes)
/// against the four-segment curve.
std::string force_deck() {
  std::string s = cutback_deck();
  const std::string table = "*PLASTIC\n250.0, 0.\n2250, 0.1\n";
  s.replace(s.find(table), table.size(), "*PLASTIC\n250., 0.\n270., 0.001\n285., 0.002\n300., 0.004\n320., 0.01\n");
  const std::string pull = "*BOUNDARY\nRIGHT, 1, 1, 0.032\n";
  s.replace(s.find(pull), pull.size(), "*CLOAD\nRIGHT, 1, 78.75\n");
  s.replace(s.find(", , , 4\n"), 8, ", , , 3\n");  // crossing several segments needs more
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
  const auto r = dir.read(force_deck());
  ASSERT_TRUE(r.ok()) << r.report();
  const AnalysisModel am = build_analysis_model(r.model);
  MaterialStates states(am);
  ASSERT_FALSE(states.empty());  // plastic: 4 elements × 8 points × 7 values, twice
  EXPECT_EQ(states.bytes(), 5 * sizeof(std::size_t) + 4 * sizeof(std::uint32_t) + 2 * 4 * 8 * 7 * sizeof(double));
  PeeqWatch watch(states);
  const AnalysisOutcome outcome = run_steps(am, states, watch);
  ASSERT_TRUE(outcome.completed) << outcome.message;

  ASSERT_GE(watch.seen.size(), 2u);
  EXPECT_TRUE(watch.seen[0].row.cut_back);  // the whole load in one increment: too many iterations
  int cutbacks = 0;
  double committed_before = 0.0;  // PEEQ of the last converged increment
  for (const auto& s : watch.seen) {
    const double t_end = s.row.step_time + (s.row.cut_back ? s.row.inc_of_time : 0.0);
    const double t_start = s.row.step_time - (s.row.cut_back ? 0 : s.row.inc_of_time);
    // Every attempt starts from the last converged increment's state.
    EXPECT_EQ(s.committed, committed_before) << "increment " << s.row.increment << " attempt " << s.row.attempt;
    EXPECT_NEAR(s.committed, plastic_strain_at_stress(kSigmaMax * t_start), 1e-15) << "increment " << s.row.increment;
    if (s.row.cut_back) {
      ++cutbacks;
      continue;  // the next attempt must not see what this one did
    }
    EXPECT_NEAR(s.trial, plastic_strain_at_stress(kSigmaMax * t_end), 1e-15) << "increment " << s.row.increment;
    committed_before = s.trial;
  }
  EXPECT_GE(cutbacks, 1);
  // After the step: the curve's inverse at σ = 315 (ε̄ᵖ = 0.0085) at every point, to round-off.
  using L = elements::MisesStateLayout;
  for (std::size_t e = 0; e < 4; ++e)
    for (std::size_t p = 0; p < 8; ++p)
      EXPECT_NEAR(states.committed(e)[p * 7 + L::equivalent], plastic_strain_at_stress(kSigmaMax), 1e-15);
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
