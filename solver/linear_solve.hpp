#pragma once
/// The linear solve of a Newton iteration, K Δu = r:
///  - CHOLMOD for a symmetric positive definite tangent; UMFPACK for a saddle-point system
///    (contact multipliers), an unsymmetric tangent given in full (friction), and from the first
///    tangent CHOLMOD finds not positive definite on, for the rest of the attempt;
///  - a singular factorisation, or one out of memory, is a failure that says so;
///  - the rigid-body guard: a rigid-body mode often factorises with round-off pivots instead of
///    failing, and its correction is then absurdly large (beyond 1e8 × the model size, or not a
///    number): that is reported as the singular system it is rather than iterated on.
#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "iteration_seconds.hpp"
#include "linear/linear_solver.hpp"

namespace inpact::solver {

/// The two direct solvers of a step; each keeps its symbolic analysis from one factorisation
/// to the next while the pattern holds.
struct LinearSolvers {
  std::unique_ptr<LinearSolver> cholmod = make_cholmod_solver();
  std::unique_ptr<LinearSolver> umfpack = make_umfpack_solver();
  IterationSeconds seconds;  ///< factorization and back_solve (with their counts) of the step
};

struct CorrectionOutcome {
  bool solved = false;
  bool singular = false;  ///< a rigid-body mode: a smaller increment cannot help
  std::string failure;    ///< why it was not solved
};

/// The solver choice of one Newton attempt (it starts with CHOLMOD).
class CorrectionSolver {
 public:
  explicit CorrectionSolver(LinearSolvers& solvers) : solvers_(solvers), current_(solvers.cholmod.get()) {}

  /// Solves `tangent` du = r. `saddle_point`: the system has equations beyond the displacement
  /// ones (multipliers); the first `n_displacement` entries of du are displacements, judged by
  /// the rigid-body guard against `model_size`.
  CorrectionOutcome solve(const SparseMatrix& tangent, bool saddle_point, std::span<const double> r,
                          std::span<double> du, std::size_t n_displacement, double model_size);

  /// The solver of the last solve.
  const LinearSolver& current() const { return *current_; }

 private:
  LinearSolvers& solvers_;
  LinearSolver* current_;
};

}  // namespace inpact::solver
