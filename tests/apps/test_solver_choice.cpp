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
#include <stdexcept>
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

/// Runs inpact with `args`, after `environment` ("NAME=value " words for the shell).
Output run_inpact_with(const std::string& environment, const std::string& args) {
  Output out;
  const std::string command = environment + "\"" + std::string(INPACT_EXECUTABLE) + "\" " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.text.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) out.exit_code = WEXITSTATUS(status);
  return out;
}

Output run_inpact(const std::string& args) { return run_inpact_with("", args); }

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

// auto's size rule on a small deck (thick_cylinder, CPE8R: far below): direct; petsc only when
// asked, or when the model reaches its dimension's crossover and PETSc is built. 2D models keep
// the direct solver longer (the square ties from 200k DOF, the cube from 15k).
TEST(SolverChoice, AutoTakesDirectBelowTheCrossoverAndPetscAbove) {
  const auto deck = parser::read_deck(kDeck);
  ASSERT_TRUE(deck.ok());
  const auto small = solver::resolve_linear_solver(solver::SolverRequest::Auto, deck.model, 1);
  EXPECT_EQ(small.dim, 2);
  EXPECT_LT(small.model_dofs, solver::petsc_from_dofs(2, false));
  EXPECT_EQ(small.kind, solver::SolverKind::Direct);
  EXPECT_EQ(solver::petsc_from_dofs(2, false), solver::kPetscFromDofs2d);
  EXPECT_EQ(solver::petsc_from_dofs(3, true), solver::kPetscFromDofs);
  model::Model large = deck.model;
  // A 2D model of the 3D crossover's size stays direct; of its own crossover's, petsc.
  large.mesh.nodes.labels.resize(static_cast<std::size_t>(solver::kPetscFromDofs));  // × 2 DOF per node
  EXPECT_EQ(solver::resolve_linear_solver(solver::SolverRequest::Auto, large, 1).kind, solver::SolverKind::Direct);
  large.mesh.nodes.labels.resize(static_cast<std::size_t>(solver::kPetscFromDofs2d / 2));
  const auto big = solver::resolve_linear_solver(solver::SolverRequest::Auto, large, 1);
  EXPECT_EQ(big.model_dofs, solver::kPetscFromDofs2d);
  EXPECT_EQ(big.kind, solver::petsc_built() ? solver::SolverKind::Petsc : solver::SolverKind::Direct);
  if (solver::petsc_built()) {
    EXPECT_NE(solver::describe(big).find("auto: 2D, 200000 DOF >= 200000"), std::string::npos) << solver::describe(big);
  }
  EXPECT_EQ(solver::resolve_linear_solver(solver::SolverRequest::Direct, large, 1).kind, solver::SolverKind::Direct);
  EXPECT_EQ(solver::parse_solver_request("auto"), solver::SolverRequest::Auto);
  EXPECT_FALSE(solver::parse_solver_request("cholmod"));
}

// A 3D model mostly of shells has a surface's sparsity: the direct solver stays faster much
// longer (the S4 plate: 1.2× at 800k DOF, a tie at 1.6M), and auto keeps it to 1.5M DOF.
TEST(SolverChoice, AModelOfShellsKeepsTheDirectSolverLonger) {
  const auto deck = parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/verification/edge_load_ednor_s4.inp");
  ASSERT_TRUE(deck.ok());
  model::Model large = deck.model;
  large.mesh.nodes.labels.resize(static_cast<std::size_t>(solver::kPetscFromDofs));  // × 3 DOF per node
  const auto shells = solver::resolve_linear_solver(solver::SolverRequest::Auto, large, 1);
  EXPECT_EQ(shells.dim, 3);
  EXPECT_FALSE(shells.solids);
  EXPECT_EQ(shells.kind, solver::SolverKind::Direct);
  EXPECT_EQ(solver::petsc_from_dofs(3, false), solver::kPetscFromDofsShells);
  large.mesh.nodes.labels.resize(static_cast<std::size_t>(solver::kPetscFromDofsShells / 3));
  const auto big = solver::resolve_linear_solver(solver::SolverRequest::Auto, large, 1);
  EXPECT_EQ(big.kind, solver::petsc_built() ? solver::SolverKind::Petsc : solver::SolverKind::Direct);
  if (solver::petsc_built()) {
    EXPECT_NE(solver::describe(big).find("auto: 3D, mostly shells or beams, 1500000 DOF >= 1500000"), std::string::npos)
        << solver::describe(big);
  }
  // Solids with a coupling's rotation node: the cube's crossover.
  const auto solid =
      parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/verification/coupling_kinematic_push_c3d8.inp");
  ASSERT_TRUE(solid.ok());
  EXPECT_TRUE(solver::resolve_linear_solver(solver::SolverRequest::Auto, solid.model, 1).solids);
  // A 2D model has no such distinction.
  EXPECT_FALSE(solver::resolve_linear_solver(solver::SolverRequest::Auto, parser::read_deck(kDeck).model, 1).solids);
}

// The dimension is the analysis's (model::model_dimension): a model of springs is a 3D one, as
// build_analysis_model takes it, not a 0D one of no DOFs.
TEST(SolverChoice, AModelOfSpringsCountsThreeDofsPerNode) {
  const auto deck = parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/verification/spring_chain.inp");
  ASSERT_TRUE(deck.ok());
  const auto choice = solver::resolve_linear_solver(solver::SolverRequest::Auto, deck.model, 1);
  EXPECT_EQ(choice.dim, 3);
  EXPECT_EQ(choice.model_dofs, static_cast<std::int64_t>(deck.model.mesh.nodes.size()) * 3);
}

// Under mpirun (its environment says how many ranks) the run is PETSc's: without --solver, and
// with auto whatever the size; the direct solvers, one process's, are refused.
TEST(SolverChoice, SeveralMpiRanksTakePetscAndRefuseDirect) {
  const auto deck = parser::read_deck(kDeck);
  ASSERT_TRUE(deck.ok());
  EXPECT_EQ(solver::resolve_linear_solver(solver::SolverRequest::Default, deck.model, 1).kind,
            solver::SolverKind::Direct);
  if (!solver::petsc_built()) {
    EXPECT_THROW(solver::resolve_linear_solver(solver::SolverRequest::Default, deck.model, 2), std::invalid_argument);
    return;
  }
  for (auto request : {solver::SolverRequest::Default, solver::SolverRequest::Auto, solver::SolverRequest::Petsc}) {
    const auto choice = solver::resolve_linear_solver(request, deck.model, 2);
    EXPECT_EQ(choice.kind, solver::SolverKind::Petsc);
    EXPECT_NE(solver::describe(choice).find("; 2 MPI ranks"), std::string::npos) << solver::describe(choice);
  }
  EXPECT_THROW(solver::resolve_linear_solver(solver::SolverRequest::Direct, deck.model, 2), std::invalid_argument);
  // `inpact check` reads the launcher's environment as `run` does (no MPI is started by check).
  const std::string two_ranks = "OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 ";
  const Output check = run_inpact_with(two_ranks, "check " + kDeck);
  EXPECT_EQ(check.exit_code, 0) << check.text;
  EXPECT_NE(solver_line(check.text).find("LINEAR SOLVER: petsc"), std::string::npos) << check.text;
  const Output direct = run_inpact_with(two_ranks, "check " + kDeck + " --solver direct");
  EXPECT_EQ(direct.exit_code, 2) << direct.text;
  EXPECT_NE(direct.text.find("the direct solvers run on one process"), std::string::npos) << direct.text;
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
