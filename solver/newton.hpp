#pragma once
/// The Newton iterations of one increment attempt:
///   K(u_k) Δu = f_ext(t) − f_int(u_k),  u_{k+1} = u_k + Δu.
/// When the increment moves prescribed DOFs (and no contact, rotating rigid body or
/// stabilisation is in the step), the first iteration is Abaqus's: K(u_n) Δu = f_ext(t) −
/// f_int(u_n) − K(u_n)·Δu_p from the converged start, which carries the prescribed motion into
/// the body. Each iteration, as the Abaqus manual describes it:
///   1. contact search and status at u_k (a status change makes it a severe discontinuity
///      iteration);
///   2. assemble the residual r = f_ext − f_int (elements, then contact) and measure it against
///      q̃, the force averaged over the step so far;
///   3. check convergence (convergence.hpp): residual ≤ R_n q̃ and correction ≤ C_n Δu_max, or a
///      residual R_l times smaller outright, with contact compatibility;
///   4. give up on NaN, an inverted element, a contact failure, too many iterations or a residual
///      that grows twice in a row;
///   5. solve K Δu = r (linear_solve.hpp: CHOLMOD → UMFPACK, the rigid-body guard) and correct u.
#include <span>
#include <string>
#include <vector>

#include "assembler.hpp"
#include "contact_problem.hpp"
#include "convergence.hpp"
#include "linear_solve.hpp"
#include "observer.hpp"
#include "solution_controls.hpp"
#include "stabilization.hpp"
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
  PerField average_force{};    ///< q of the increment per field (IncrementForce), for the time average
  double max_residual = 0.0;
  std::int64_t worst_dof = -1;
  std::string failure;  ///< why it did not converge
  bool singular = false;  ///< a rigid-body mode: a smaller increment cannot help
};

/// Which attempt this is, for the progress records and the contact history.
struct AttemptId {
  int step = 0, increment = 0, attempt = 0;  ///< all 1-based
};

/// Everything one increment attempt needs: what the step keeps (model, conditions, assembly,
/// solvers, controls, contact) and what the increment loop knows (q̃'s history, the attempt).
struct NewtonContext {
  const AnalysisModel& am;
  const StepConditions& conditions;
  Assembler& assembler;
  LinearSolvers& solvers;
  const SolutionControls& controls;
  AnalysisObserver& observer;
  ContactProblem* contact = nullptr;  ///< the step's contact pairs, or null
  bool nlgeom = false;
  TimeAveragedForce force_history;  ///< q over the converged increments of the step (q̃)
  AttemptId at;
  /// The increment writes element output (S, E) if it converges: every assembly keeps its
  /// point results, so that the output reads those of the converged state.
  bool keep_points = false;
  /// *STATIC, STABILIZE: the viscous forces c M* Δu/Δt of this attempt, or null.
  const ViscousForces* stabilization = nullptr;
  /// The step's DOF map when rigid bodies rotate finitely (NLGEOM): its weights follow θ,
  /// relinearised after every change of u; null otherwise.
  DofMap* rotating_dofs = nullptr;
};

/// Runs the iterations from `state.u` (the converged state at the increment start) to step
/// time `t`. On success `state` holds the converged solution.
NewtonOutcome solve_increment(NewtonContext& ctx, double t, IncrementState& state);

}  // namespace inpact::solver
