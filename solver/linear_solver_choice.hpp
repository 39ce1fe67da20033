#pragma once
/// Which linear solver a run uses (`inpact run --solver direct|petsc|auto`). One function
/// resolves the request, so that `inpact check`, the run, the results file and the .dat header
/// all say the same:
///  - direct: CHOLMOD (symmetric positive definite), UMFPACK (multipliers, friction);
///  - petsc:  CG / GMRES with algebraic multigrid (GAMG), MUMPS for multipliers (linear/petsc_solver.cpp);
///  - auto:   direct below kPetscFromDofs DOFs of the model, petsc from there (when built with
///            PETSc) — the crossover measured on a C3D8 cube (bench/petsc_solver);
///  - none given: direct on one process, petsc on several MPI ranks (`mpirun -np N`), where the
///    direct solvers cannot go (they are one process's).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "model/model.hpp"

namespace inpact::solver {

enum class SolverRequest { Direct, Petsc, Auto, Default };
enum class SolverKind { Direct, Petsc };

/// `auto` takes petsc from this many DOFs (nodes × DOFs per node) of the model.
inline constexpr std::int64_t kPetscFromDofs = 25'000;

struct SolverChoice {
  SolverRequest requested = SolverRequest::Direct;
  SolverKind kind = SolverKind::Direct;
  std::int64_t model_dofs = 0;
  int ranks = 1;  ///< MPI ranks of the run (mpi_launch.hpp); petsc whenever more than one
};

/// "direct", "petsc", "auto" → the request, "" (no --solver) → Default; anything else → nullopt.
std::optional<SolverRequest> parse_solver_request(std::string_view text);
const char* request_name(SolverRequest request);

/// The solver `request` comes to for `model` on `ranks` MPI ranks. Throws std::invalid_argument
/// when petsc is requested from a build without PETSc (auto then takes direct on one rank), and
/// when direct is requested on several ranks.
SolverChoice resolve_linear_solver(SolverRequest request, const model::Model& model, int ranks);
/// The same for the text of `--solver` on the ranks this process was launched among; throws
/// std::invalid_argument for an unknown request too.
SolverChoice resolve_linear_solver(std::string_view request, const model::Model& model);

/// "petsc" or "direct": the name the results file records.
const char* kind_name(SolverKind kind);
/// One line for `check`, the .dat header and the log, e.g.
/// "LINEAR SOLVER: petsc (CG/GMRES + GAMG, MUMPS for multipliers; auto: 250000 DOF >= 200000)".
std::string describe(const SolverChoice& choice);

/// Starts what the choice needs, once per process: for petsc, loads the PETSc module and calls
/// PetscInitialize (MPI_Init, one rank). Throws std::runtime_error when it cannot.
void start_linear_solver(const SolverChoice& choice);

/// The PETSc part of `inpact --version`.
std::string petsc_availability();

}  // namespace inpact::solver
