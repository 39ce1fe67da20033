#pragma once
/// Wall time spent in the parts of the Newton iterations, summed over a run: what
/// `inpact run --timings` reports beside the phases, so that a benchmark can set the contact
/// update of one iteration against one element assembly and one factorisation of the same
/// system (bench/contact_iteration). Measured, never asserted: the clock does not change a result.
#include <chrono>

namespace inpact::solver {

struct IterationSeconds {
  double contact_update = 0.0;     ///< ContactProblem::update: search, projection, status, linearisation
  double contact_begin = 0.0;      ///< ContactProblem::begin_attempt (the surfaces at the attempt's start)
  double contact_geometry = 0.0;   ///< of update's and begin_attempt's: the surfaces' update (search, projection)
  double contact_assembly = 0.0;   ///< ContactProblem::assemble: contact forces and tangent
  double element_assembly = 0.0;   ///< Assembler::assemble: element forces (and tangent)
  double factorization = 0.0;      ///< LinearSolver::factorize
  double back_solve = 0.0;         ///< LinearSolver::solve
  long contact_updates = 0, element_assemblies = 0, factorizations = 0;
  long krylov_iterations = 0;      ///< of an iterative linear solver (PETSc), over its solves

  IterationSeconds& operator+=(const IterationSeconds& o) {
    contact_update += o.contact_update;
    contact_begin += o.contact_begin;
    contact_geometry += o.contact_geometry;
    contact_assembly += o.contact_assembly;
    element_assembly += o.element_assembly;
    factorization += o.factorization;
    back_solve += o.back_solve;
    contact_updates += o.contact_updates;
    element_assemblies += o.element_assemblies;
    factorizations += o.factorizations;
    krylov_iterations += o.krylov_iterations;
    return *this;
  }
};

/// Adds the wall time of its scope to `seconds` (and one to `count`, when given).
class ScopedSeconds {
 public:
  explicit ScopedSeconds(double& seconds, long* count = nullptr) : seconds_(seconds) {
    if (count) ++*count;
  }
  ~ScopedSeconds() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  ScopedSeconds(const ScopedSeconds&) = delete;
  ScopedSeconds& operator=(const ScopedSeconds&) = delete;

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace inpact::solver
