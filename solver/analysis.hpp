#pragma once
/// The analysis: step → increment → (augmentation →) Newton iteration, as the Abaqus manual
/// describes the loop of a static step with automatic incrementation:
///   step        analysis.cpp              conditions, DOFs, contact pairs and output of the step
///   increment   analysis.cpp              sizes from increment_controller.hpp; commits the
///                                         material history when an increment converges
///   augmentation augmentation.hpp         augmented-Lagrange multiplier updates
///   iteration   newton.hpp                residual, convergence.hpp, linear_solve.hpp
#include <string>

#include "iteration_seconds.hpp"
#include "linear_solver_choice.hpp"
#include "model/model.hpp"
#include "observer.hpp"

namespace inpact::solver {

struct AnalysisOptions {
  int threads = 1;
  SolverKind linear_solver = SolverKind::Direct;  ///< resolve_linear_solver's choice
};

struct AnalysisOutcome {
  bool completed = false;
  /// Why it stopped: step, increment, time, and the worst residual's node and DOF.
  std::string message;
  /// Wall seconds spent computing and writing output (frames and printed tables), so that a
  /// caller can tell the solve from the output it asked for (`inpact run --timings`).
  double output_seconds = 0.0;
  /// Wall seconds in the parts of the Newton iterations (contact, element assembly, linear solve).
  IterationSeconds iteration_seconds;
};

/// Runs every step of `model`; progress and frames go to `observer`. Throws AnalysisError when
/// the model cannot be analysed at all (the deck is wrong in a way only the analysis sees).
AnalysisOutcome run_analysis(const model::Model& model, AnalysisObserver& observer, const AnalysisOptions& options = {});

struct AnalysisModel;
class MaterialStates;

/// What each step's run is built from, without analysing: its conditions and its DOF map, with
/// the deck errors only they find (an *EQUATION on a held DOF, a DOF eliminated twice, a load on
/// a DOF nothing connects). `inpact check` calls it; a run finds the same errors as it builds
/// each step (the same functions). Throws AnalysisError.
void check_step_setup(const AnalysisModel& am);

/// The same for a model already resolved, with the points' material history in `states`
/// (built for `am`, committed increment after increment): for callers that give elements
/// their own material laws (tests), or look at the history afterwards.
AnalysisOutcome run_steps(const AnalysisModel& am, MaterialStates& states, AnalysisObserver& observer,
                          const AnalysisOptions& options = {});

}  // namespace inpact::solver
