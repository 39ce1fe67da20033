#pragma once
/// The text of a PETSc call that failed, for the PETSc module's sources (petsc_solver.cpp,
/// petsc_partition.cpp): "PETSc: <what>: <PETSc's message>"; and a scope-owned PETSc object.
#include <petscsys.h>

#include <string>
#include <utility>

namespace inpact::solver {

inline std::string petsc_error(PetscErrorCode code, const char* what) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  return std::string("PETSc: ") + what + ": " + (text ? text : "error");
}

/// A PETSc object (Vec, Mat, MatNullSpace, ...) destroyed with its scope, also when a failed
/// call throws on the way.
template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscOwned {
 public:
  PetscOwned() = default;
  PetscOwned(PetscOwned&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}
  PetscOwned(const PetscOwned&) = delete;
  PetscOwned& operator=(const PetscOwned&) = delete;
  PetscOwned& operator=(PetscOwned&&) = delete;
  ~PetscOwned() {
    if (handle_) Destroy(&handle_);
  }
  T get() const { return handle_; }
  T* out() { return &handle_; }  ///< for the creating call
 private:
  T handle_ = nullptr;
};

}  // namespace inpact::solver
