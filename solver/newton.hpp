#pragma once
/// The Newton iterations of one increment attempt:
///   K(u_k) Δu = f_ext(t) − f_int(u_k),  u_{k+1} = u_k + Δu,
/// until the largest residual is below R_n · q̃ (q̃: the force averaged over the step so far)
/// and the largest correction below C_n · the largest displacement increment — Abaqus's
/// default criteria for a displacement field.
#include <span>
#include <string>
#include <vector>

#include "assembler.hpp"
#include "contact_problem.hpp"
#include "linear/linear_solver.hpp"
#include "observer.hpp"
#include "solution_controls.hpp"
#include "step_conditions.hpp"

namespace inpact::solver {

/// The state Newton works on and returns: displacements and the quantities derived from them.
struct IncrementState {
  std::vector<double> u;          ///< full DOF vector
  std::vector<double> f_int;      ///< internal forces at u
  std::vector<double> f_ext;      ///< external forces at the increment's time
  ContactState contact;           ///< multipliers and contact status (empty without contact)
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;          ///< all iterations, severe discontinuity ones included
  int severe_iterations = 0;   ///< iterations in which a contact status changed
  double average_force = 0.0;  ///< q of the increment (largest over its iterations), for the time average
  double max_residual = 0.0;
  std::int64_t worst_dof = -1;
  std::string failure;  ///< why it did not converge
  bool singular = false;  ///< a rigid-body mode: a smaller increment cannot help
};

/// Everything one increment attempt needs.
struct NewtonContext {
  const AnalysisModel& am;
  const StepConditions& conditions;
  Assembler& assembler;
  LinearSolver& cholmod;
  LinearSolver& umfpack;  ///< used when the tangent is not positive definite
  const SolutionControls& controls;
  AnalysisObserver& observer;
  bool nlgeom;
  /// Sum and count of q over the converged increments of the step (time averaging).
  double force_sum;
  int force_count;
  int step_number, increment, attempt;
  ContactProblem* contact = nullptr;  ///< the step's contact pairs, or null
  /// The increment writes element output (S, E) if it converges: every assembly keeps its
  /// point results, so that the output reads those of the converged state.
  bool keep_points = false;
};

/// Runs the iterations from `state.u` (the converged state at the increment start) to step
/// time `t`. On success `state` holds the converged solution.
NewtonOutcome solve_increment(NewtonContext& ctx, double t, IncrementState& state);

}  // namespace inpact::solver
