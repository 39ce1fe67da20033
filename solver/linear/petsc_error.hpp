#pragma once
/// The text of a PETSc call that failed, for the PETSc module's sources (petsc_solver.cpp,
/// petsc_partition.cpp): "PETSc: <what>: <PETSc's message>".
#include <petscsys.h>

#include <string>

namespace inpact::solver {

inline std::string petsc_error(PetscErrorCode code, const char* what) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  return std::string("PETSc: ") + what + ": " + (text ? text : "error");
}

}  // namespace inpact::solver
