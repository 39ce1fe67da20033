#pragma once
/// The analysis: step → increment → (augmentation →) Newton iteration, as the Abaqus manual
/// describes the loop of a static step with automatic incrementation.
#include <string>

#include "model/model.hpp"
#include "observer.hpp"

namespace inpact::solver {

struct AnalysisOptions {
  int threads = 1;
};

struct AnalysisOutcome {
  bool completed = false;
  /// Why it stopped: step, increment, time, and the worst residual's node and DOF.
  std::string message;
  /// Wall seconds spent computing and writing output (frames and printed tables), so that a
  /// caller can tell the solve from the output it asked for (`inpact run --timings`).
  double output_seconds = 0.0;
};

/// Runs every step of `model`; progress and frames go to `observer`. Throws AnalysisError when
/// the model cannot be analysed at all (the deck is wrong in a way only the analysis sees).
AnalysisOutcome run_analysis(const model::Model& model, AnalysisObserver& observer, const AnalysisOptions& options = {});

}  // namespace inpact::solver
