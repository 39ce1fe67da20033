// `inpact check` prints, per step, exactly the contact interactions the run enforces: for every
// deck of decks/ with contact, the lines of check's summary equal, step by step, the lines the
// run's ContactProblem holds (what the run reports to its observer, the results file and the
// .dat header). The decks of decks/contact/ are also run to the end, and the lines the analysis
// reported at each step's start are compared too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "apps/commands.hpp"
#include "contact/initial_adjustment.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_model.hpp"
#include "solver/contact_problem.hpp"

namespace inpact::app {
namespace {

namespace fs = std::filesystem;
using StepLines = std::vector<std::vector<std::string>>;

/// The contact lines of `inpact check DECK`, per step (steps without contact: empty).
StepLines check_lines(const std::string& deck, std::size_t n_steps) {
  std::ostringstream captured;
  std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
  const int rc = run_check({deck, {}});
  std::cout.rdbuf(old);
  EXPECT_EQ(rc, 0) << deck;
  StepLines out(n_steps);
  std::istringstream in(captured.str());
  std::string line;
  bool in_steps = false, in_contact = false;
  std::size_t step = 0, steps_seen = 0;
  while (std::getline(in, line)) {
    if (line.rfind("Steps ", 0) == 0) in_steps = true;
    if (!in_steps) continue;
    if (line.size() > 2 && line.rfind("  ", 0) == 0 && line[2] != ' ') {  // "  NAME: STATIC, ..." starts a step
      step = steps_seen++;
      in_contact = false;
      continue;
    }
    if (line == "    contact, as the analysis enforces it:") in_contact = true;
    else if (in_contact && line.rfind("      ", 0) == 0 && step < out.size()) out[step].push_back(line.substr(6));
  }
  EXPECT_EQ(steps_seen, n_steps) << deck;
  return out;
}

/// What each step's ContactProblem (the object the run builds) describes.
StepLines problem_lines(const model::Model& m) {
  const solver::AnalysisModel am = solver::build_analysis_model(m);
  StepLines out(m.steps.size());
  for (std::size_t s = 0; s < m.steps.size(); ++s) out[s] = solver::ContactProblem(am, s).describe();
  return out;
}

struct LineCapture : solver::AnalysisObserver {
  StepLines lines;
  void contact_interactions(int step, const std::vector<std::string>& l) override {
    lines.resize(static_cast<std::size_t>(step));
    lines[static_cast<std::size_t>(step) - 1] = l;
  }
};

std::vector<std::string> contact_decks() {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(INPACT_SOURCE_DIR) / "decks")) {
    const std::string p = e.path().string();
    if (e.path().extension() != ".inp" || p.find("/errors/") != std::string::npos) continue;
    out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(CheckMatchesRun, EveryContactDeckPrintsWhatTheRunEnforces) {
  int with_contact = 0, run_to_the_end = 0;
  for (const std::string& deck : contact_decks()) {
    parser::ReadResult r = parser::read_deck(deck);
    if (!r.ok()) continue;  // decks that are included by others
    contact::apply_adjust(r.model);
    const StepLines run = problem_lines(r.model);
    bool any = false;
    for (const auto& s : run) any = any || !s.empty();
    if (!any) continue;
    ++with_contact;
    EXPECT_EQ(check_lines(deck, r.model.steps.size()), run) << deck;
    if (deck.find("/decks/contact/") == std::string::npos) continue;
    LineCapture capture;
    const solver::AnalysisOutcome outcome = solver::run_analysis(r.model, capture);
    if (!outcome.completed) continue;  // (a deck that aborts on purpose)
    capture.lines.resize(run.size());
    EXPECT_EQ(capture.lines, run) << deck;
    ++run_to_the_end;
  }
  std::printf("%d decks with contact compared, %d of them run to the end\n", with_contact, run_to_the_end);
  EXPECT_GE(with_contact, 50);
  EXPECT_GE(run_to_the_end, 35);
}

// `inpact run` writes the same lines into the .dat header of each step (and the results file,
// tests/io/test_results_writer.cpp): a two-step deck, one pair.
TEST(CheckMatchesRun, RunWritesTheStepsInteractionsIntoTheDatFile) {
  const fs::path dir = fs::temp_directory_path() / ("inpact-check-run-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string deck = (fs::path(INPACT_SOURCE_DIR) / "decks/contact/friction_slide_2d_penalty.inp").string();
  RunOptions options;
  options.deck = deck;
  options.output_dir = dir.string();
  options.job = "job";
  options.quiet = true;
  ASSERT_EQ(run_analysis(options), 0);
  parser::ReadResult r = parser::read_deck(deck);
  const StepLines expected = check_lines(deck, r.model.steps.size());
  std::ifstream in(dir / "job.dat");
  std::vector<std::string> dat_lines;
  for (std::string l; std::getline(in, l);)
    if (l.rfind("     ", 0) == 0 && l.find("contact pair ") == 5) dat_lines.push_back(l.substr(5));
  std::vector<std::string> all;
  for (const auto& s : expected) all.insert(all.end(), s.begin(), s.end());
  EXPECT_EQ(dat_lines, all);
  EXPECT_EQ(all.size(), 2u);  // one pair, two steps
  fs::remove_all(dir);
}

// A deck error only a step's conditions or DOF map find (here two loads at one DOF in step 2
// with two amplitudes, which add up) stops `inpact check` as it stops `inpact run`: exit 3, the
// same line, and the run before it analyses step 1 (no results file).
TEST(CheckMatchesRun, AStepsDeckErrorStopsCheckAsItStopsTheRun) {
  const fs::path dir = fs::temp_directory_path() / ("inpact-check-step-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string deck = (dir / "deck.inp").string();
  std::ofstream(deck) << "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n"
                         "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n"
                         "*AMPLITUDE, NAME=A\n0., 0., 1., 1.\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n*STEP\n*STATIC\n"
                         "*CLOAD\n2, 1, 1.\n*END STEP\n*STEP\n*STATIC\n"
                         "*CLOAD\n2, 1, 1.\n*CLOAD, AMPLITUDE=A\n2, 1, 2.\n*END STEP\n";
  const std::string expected = "deck.inp:26:1: error: *CLOAD: node 2 DOF 1 is loaded earlier in this step with the "
                               "step's own amplitude";
  testing::internal::CaptureStderr();
  const int rc = run_check({deck, {}});
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_EQ(rc, 3);
  EXPECT_NE(said.find(expected), std::string::npos) << said;
  RunOptions options;
  options.deck = deck;
  options.output_dir = dir.string();
  options.job = "job";
  options.quiet = true;
  testing::internal::CaptureStderr();
  EXPECT_EQ(run_analysis(options), 3);
  const std::string run_said = testing::internal::GetCapturedStderr();
  EXPECT_NE(run_said.find(expected), std::string::npos) << run_said;
  EXPECT_FALSE(fs::exists(dir / "job.h5"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace inpact::app
