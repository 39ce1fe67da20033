#pragma once
/// The linear solve of a Newton iteration, K Δu = r:
///  - CHOLMOD for a symmetric positive definite tangent; UMFPACK for a saddle-point system
///    (contact multipliers), an unsymmetric tangent given in full (friction), and from the first
///    tangent CHOLMOD finds not positive definite on, for the rest of the attempt;
///  - or, when the run chose petsc (linear_solver_choice.hpp), PETSc for every system, its
///    Krylov tolerance tied to Newton's residual (krylov_tolerance);
///  - a singular factorisation, or one out of memory, is a failure that says so;
///  - the rigid-body guard: a rigid-body mode often factorises with round-off pivots instead of
///    failing, and its correction is then absurdly large (beyond 1e8 × the model size, or not a
///    number): that is reported as the singular system it is rather than iterated on.
#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "analysis_model.hpp"
#include "dof_map.hpp"
#include "iteration_seconds.hpp"
#include "linear/linear_solver.hpp"

namespace inpact::solver {

/// The solvers of a step; each keeps its symbolic analysis from one factorisation to the next
/// while the pattern holds.
struct LinearSolvers {
  std::unique_ptr<LinearSolver> cholmod = make_cholmod_solver();
  std::unique_ptr<LinearSolver> umfpack = make_umfpack_solver();
  std::unique_ptr<LinearSolver> petsc;  ///< when the run chose petsc: it solves every system
  IterationSeconds seconds;  ///< factorization and back_solve (with their counts) of the step
};

/// The node and component of each equation of `dofs`, and the node coordinates (for PETSc's
/// multigrid: the rigid-body modes).
EquationPoints equation_points(const AnalysisModel& am, const DofMap& dofs);

/// The inexact Newton rule: the relative tolerance of a Krylov solve whose right-hand side is
/// the residual r, with residual ratio ρ = max|r| / q̃ (Newton's own measure, converged at
/// R_n: 5e-3 unless *CONTROLS says otherwise). The correction then leaves a linear residual of
/// about rtol·ρ·q̃; the rule holds that at kKrylovTarget·R_n·q̃ (1e-8 q̃ at the default R_n) —
/// far under Newton's criterion, so that the converged state is the direct solver's to about
/// 1e-7 (at 2e-5 the smoothed rubber O-ring's stresses differed by 1.2e-6 of their largest; at
/// 2e-6 by 1.5e-7, for 10 % more Krylov iterations over the contact decks and none on the cube:
/// bench/petsc_solver/README.md), and Newton keeps its rate down to a deck's own strict R_n —
/// within [1e-10, 1e-2]:
///   rtol = clamp(kKrylovTarget·R_n / ρ, 1e-10, 1e-2).
inline constexpr double kKrylovTarget = 2e-6;
double krylov_tolerance(double residual_ratio, double residual_tolerance);

struct CorrectionOutcome {
  bool solved = false;
  bool singular = false;  ///< a rigid-body mode: a smaller increment cannot help
  std::string failure;    ///< why it was not solved
};

/// The solver choice of one Newton attempt (it starts with CHOLMOD, or PETSc).
class CorrectionSolver {
 public:
  explicit CorrectionSolver(LinearSolvers& solvers)
      : solvers_(solvers), current_(solvers.petsc ? solvers.petsc.get() : solvers.cholmod.get()) {}

  /// Solves `tangent` du = r. `saddle_point`: the system has equations beyond the displacement
  /// ones (multipliers); the first `n_displacement` entries of du are displacements, judged by
  /// the rigid-body guard against `model_size`. `residual_ratio`: max|r| / q̃ (krylov_tolerance).
  CorrectionOutcome solve(const SparseMatrix& tangent, bool saddle_point, std::span<const double> r,
                          std::span<double> du, std::size_t n_displacement, double model_size,
                          double residual_ratio = 1.0);

  /// Newton's R_n (SolutionControls::residual_tolerance), which krylov_tolerance holds to.
  void set_residual_tolerance(double residual_tolerance) { residual_tolerance_ = residual_tolerance; }

  /// The solver of the last solve.
  const LinearSolver& current() const { return *current_; }

 private:
  LinearSolvers& solvers_;
  LinearSolver* current_;
  double residual_tolerance_ = 5e-3;
};

}  // namespace inpact::solver
