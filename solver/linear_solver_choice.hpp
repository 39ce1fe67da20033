#pragma once
/// Which linear solver a run uses (`inpact run --solver direct|petsc|auto`). One function
/// resolves the request, so that `inpact check`, the run, the results file and the .dat header
/// all say the same:
///  - direct: CHOLMOD (symmetric positive definite), UMFPACK (multipliers, friction);
///  - petsc:  CG / GMRES with algebraic multigrid (GAMG), MUMPS for multipliers (linear/petsc_solver.cpp);
///  - auto:   petsc from the model's crossover size (petsc_from_dofs: by dimension and, in 3D,
///            whether the model has solid elements; measured on the C3D8 cube, the CPE4 square and
///            the S4 plate, bench/petsc_solver), direct below it and always when built without
///            PETSc. No memory rule: below the crossovers the direct run's peak is below petsc's
///            or at most 10 % above it on solids (the same runs), 1.4× on the plate at 800k DOF
///            (3.1 against 2.4 GB), and from them on petsc is taken anyway;
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

/// `auto` takes petsc from this many DOFs (nodes × DOFs per node) of a 3D model of solid
/// elements: the cube's crossover (petsc 1.5× faster at 28k DOF, a tie at 15k).
inline constexpr std::int64_t kPetscFromDofs = 25'000;
/// ... of a 2D model: the square's crossover (a tie at 200k DOF; direct 1.1× faster at 100k).
inline constexpr std::int64_t kPetscFromDofs2d = 200'000;
/// ... of a 3D model mostly of shells (under half its DOFs on solid elements; measured on the
/// S4 plate, whose factor fills like a surface's): direct was 1.7× faster at 100k DOF, 1.2× at
/// 800k, and they tie at 1.6M (direct 1.1× less CPU, petsc 0.69× the memory). Beams and
/// trusses take it too (not measured apart).
inline constexpr std::int64_t kPetscFromDofsShells = 1'500'000;

/// The crossover of `auto` for a model of `dim` (2 or 3) dimensions; `solids`: a 3D model with
/// at least half its DOFs on solid (3D continuum) elements.
std::int64_t petsc_from_dofs(int dim, bool solids);

struct SolverChoice {
  SolverRequest requested = SolverRequest::Direct;
  SolverKind kind = SolverKind::Direct;
  /// The model's DOFs, nodes × dimension: the rotations of beam, shell and reference nodes are
  /// the translations of their rotation nodes (model/reference_nodes.hpp), counted with them.
  std::int64_t model_dofs = 0;
  int dim = 3;  ///< model::model_dimension, as the analysis takes it
  bool solids = true;  ///< a 3D model with at least half its DOFs on solid elements (3D continuum)
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
/// "LINEAR SOLVER: petsc (CG or GMRES with GAMG; MUMPS for contact multipliers); auto: 3D, 250000 DOF >= 25000".
std::string describe(const SolverChoice& choice);

/// Starts what the choice needs, once per process: for petsc, loads the PETSc module and calls
/// PetscInitialize (MPI_Init, one rank). Throws std::runtime_error when it cannot.
void start_linear_solver(const SolverChoice& choice);

/// The PETSc part of `inpact --version`.
std::string petsc_availability();

}  // namespace inpact::solver
