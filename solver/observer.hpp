#pragma once
/// How the analysis reports progress: apps/ connects an observer that writes the status log,
/// the progress line and the results file, so the solver never includes io/.
#include <string>
#include <string_view>
#include <vector>

#include "model/step.hpp"
#include "results_frame.hpp"

namespace inpact::solver {

/// One Newton iteration, for the progress line and the iteration table of -v.
struct IterationRecord {
  int step, increment, attempt, iteration;
  double max_residual;     ///< largest residual force at a free DOF
  double residual_ratio;   ///< max_residual / the time-averaged force
  double max_correction;   ///< largest displacement correction of this iteration
  std::int64_t worst_dof;  ///< global DOF of the largest residual
};

class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  virtual void step_started(const model::Step& step, int step_number) {}
  /// The contact rows in force in the step, as the analysis enforces them (contact::describe()
  /// of each resolved record: the text `inpact check` prints). Called after step_started.
  virtual void contact_interactions(int step_number, const std::vector<std::string>& lines) {}
  virtual void iteration(const IterationRecord& record) {}
  virtual void attempt_finished(const StatusRow& row) {}
  virtual void frame(const Frame& frame) {}
  /// The *NODE PRINT / *EL PRINT tables due at a converged increment (the .dat file).
  virtual void print_frame(const PrintFrame& frame) {}
  virtual void message(std::string_view text) {}
  /// A note line for the status (.sta) file, below the rows (stabilization energies).
  virtual void status_note(std::string_view text) {}
};

}  // namespace inpact::solver
