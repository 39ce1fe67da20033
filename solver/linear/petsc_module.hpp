#pragma once
/// The C entry points of the PETSc module (libinpact_petsc.so, petsc_solver.cpp) that
/// petsc_module.cpp looks up after loading it; and the process-wide PETSc session.
#include <string>

#include "linear_solver.hpp"

extern "C" {
/// PetscInitialize (MPI_Init with it), on one rank or on those of mpirun; 0 on success.
int inpact_petsc_start();
/// PetscFinalize (MPI_Finalize with it).
void inpact_petsc_finish();
/// A new solver; the caller owns it. Null (with the reason in `error`) on failure.
inpact::solver::LinearSolver* inpact_petsc_create(const inpact::solver::EquationPoints* points, std::string* error);
}

namespace inpact::solver {

/// Whether this build has the PETSc path (PETSc was found when it was configured).
bool petsc_built();
/// "PETSc 3.18.5" (the version built against), or "" without PETSc.
std::string petsc_build_version();
/// Loads the module and starts PETSc (MPI_Init, PetscInitialize), once per process; later
/// calls do nothing. PetscFinalize runs at exit. Throws std::runtime_error when it cannot.
void start_petsc();

}  // namespace inpact::solver
