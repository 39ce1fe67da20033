// `--solver direct|petsc|auto`: one function (solver::resolve_linear_solver) decides, and
// `inpact check`, the run's .dat header and its results file all say what it decided. Runs the
// executable (INPACT_EXECUTABLE) as a user does; PETSc's half needs a build with PETSc and is
// skipped only when it was not found at configure time.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "parser/read_deck.hpp"
#include "solver/linear/petsc_module.hpp"
#include "solver/linear_solver_choice.hpp"

namespace inpact {
namespace {

namespace fs = std::filesystem;

struct Output {
  std::string text;  ///< stdout and stderr together
  int exit_code = -1;
};

Output run_inpact(const std::string& args) {
  Output out;
  const std::string command = "\"" + std::string(INPACT_EXECUTABLE) + "\" " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.text.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) out.exit_code = WEXITSTATUS(status);
  return out;
}

const std::string kDeck = std::string(INPACT_SOURCE_DIR) + "/decks/thick_cylinder.inp";

/// The "LINEAR SOLVER: ..." line of a text.
std::string solver_line(const std::string& text) {
  const auto at = text.find("LINEAR SOLVER: ");
  return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The 25,000-DOF rule of auto on a small deck (thick_cylinder: far below): direct; petsc only
// when asked, or when the model is large and PETSc is built.
TEST(SolverChoice, AutoTakesDirectBelowTheCrossoverAndPetscAbove) {
  const auto deck = parser::read_deck(kDeck);
  ASSERT_TRUE(deck.ok());
  const auto small = solver::resolve_linear_solver(solver::SolverRequest::Auto, deck.model);
  EXPECT_LT(small.model_dofs, solver::kPetscFromDofs);
  EXPECT_EQ(small.kind, solver::SolverKind::Direct);
  model::Model large = deck.model;
  const std::size_t nodes = static_cast<std::size_t>(solver::kPetscFromDofs);  // × 2 DOF per node (CPE8R)
  large.mesh.nodes.labels.resize(nodes);
  const auto big = solver::resolve_linear_solver(solver::SolverRequest::Auto, large);
  EXPECT_GE(big.model_dofs, solver::kPetscFromDofs);
  EXPECT_EQ(big.kind, solver::petsc_built() ? solver::SolverKind::Petsc : solver::SolverKind::Direct);
  EXPECT_EQ(solver::resolve_linear_solver(solver::SolverRequest::Direct, large).kind, solver::SolverKind::Direct);
  EXPECT_EQ(solver::parse_solver_request("auto"), solver::SolverRequest::Auto);
  EXPECT_FALSE(solver::parse_solver_request("cholmod"));
}

TEST(SolverChoice, AnUnknownSolverIsAUsageError) {
  const Output out = run_inpact("run " + kDeck + " --solver cholmod");
  EXPECT_EQ(out.exit_code, 2) << out.text;
  EXPECT_NE(out.text.find("--solver"), std::string::npos) << out.text;
}

TEST(SolverChoice, VersionSaysWhetherPetscIsBuilt) {
  const Output out = run_inpact("--version");
  EXPECT_EQ(out.exit_code, 0);
  EXPECT_NE(out.text.find(solver::petsc_built() ? "PETSc 3." : "PETSc: not built"), std::string::npos) << out.text;
}

// check, the .dat header and the results file's root attribute carry the same decision.
void expect_recorded(const std::string& request, const char* kind) {
  const fs::path dir = fs::temp_directory_path() / ("inpact-solver-choice-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Output check = run_inpact("check " + kDeck + " --solver " + request);
  ASSERT_EQ(check.exit_code, 0) << check.text;
  const std::string line = solver_line(check.text);
  EXPECT_NE(line.find(std::string("LINEAR SOLVER: ") + kind), std::string::npos) << line;
  const Output run = run_inpact("run " + kDeck + " -q -j job -o " + dir.string() + " --solver " + request);
  ASSERT_EQ(run.exit_code, 0) << run.text;
  EXPECT_EQ(solver_line(read_file(dir / "job.dat")), line);
  // The root attributes are plain strings in the file's header: found by their text.
  const std::string h5 = read_file(dir / "job.h5");
  EXPECT_NE(h5.find(line.substr(0, 40)), std::string::npos);
  fs::remove_all(dir);
}

TEST(SolverChoice, CheckDatAndResultsFileSayTheSame) { expect_recorded("auto", "direct"); }

TEST(SolverChoice, PetscIsRecordedOrRefused) {
  if (!solver::petsc_built()) {
    const Output out = run_inpact("run " + kDeck + " --solver petsc -q -o " + fs::temp_directory_path().string());
    EXPECT_EQ(out.exit_code, 2) << out.text;
    EXPECT_NE(out.text.find("built without PETSc"), std::string::npos) << out.text;
    return;
  }
  expect_recorded("petsc", "petsc");
}

}  // namespace
}  // namespace inpact
