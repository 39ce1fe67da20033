#pragma once
/// The time incrementation of one static step, Abaqus's automatic incrementation ([AX]
/// "Commonly used control parameters", *STATIC): the controller owns the increment size dt.
///  - An increment is as large as the controller chose, shortened to end on the period's end
///    (a remainder below 1e-12 of the period joins it) and on the next output time mark.
///  - A failed attempt is cut back by D_f, at most I_A times, never below the minimum increment;
///    DIRECT incrementation never cuts back; a rigid-body mode without contact stops at once.
///  - Two easy increments in a row (at most I_G equilibrium iterations, no cutback) grow the
///    next one by D_D, up to the maximum increment (never with DIRECT).
///  - An increment cut short by a time mark is followed by the size chosen before the mark.
///  - INC bounds the number of increments of the step.
/// The increment loop asks what to try and says how each attempt ended; it formats no size.
#include <functional>
#include <optional>
#include <string>

#include "model/step.hpp"
#include "solution_controls.hpp"

namespace inpact::solver {

/// The numbers that steer the incrementation of one step.
struct IncrementLimits {
  double period = 1.0;    ///< the step's time period
  double initial = 1.0;   ///< the first increment (before the period and time marks shorten it)
  double minimum = 1e-5;  ///< a cutback below it stops the analysis
  double maximum = 1.0;   ///< growth stops there
  bool direct = false;    ///< DIRECT: fixed increments, no cutback, no growth
  int max_increments = 100;      ///< INC
  int max_cutbacks = 5;          ///< I_A: attempts of one increment beyond the first
  double cutback_factor = 0.25;  ///< D_f
  double growth_factor = 1.5;    ///< D_D
  int easy_iterations = 4;       ///< I_G
};

/// The limits of `step` (its *STATIC data line, INC and *CONTROLS), with Abaqus's defaults:
/// minimum min(initial, 1e-5 × period), maximum the period.
IncrementLimits increment_limits(const model::Step& step, const SolutionControls& controls);

/// What becomes of a failed attempt.
struct Cutback {
  bool retry = false;  ///< try again with size(), already cut back
  /// Appended to the failure's description: why the analysis stops (may be empty), or
  /// "; cutting back to <new size>".
  std::string note;
};

class IncrementController {
 public:
  explicit IncrementController(const IncrementLimits& limits);

  /// The step's time period is reached.
  bool step_complete() const { return t_ >= limits_.period * (1 - 1e-12); }
  /// Opens the next increment, sized as described above; `time_mark(t, dt)` returns dt
  /// shortened to end on the next output time mark. Returns why the step cannot go on when INC
  /// increments are spent ("more increments needed than INC=… allows, at step time …").
  std::optional<std::string> begin_increment(const std::function<double(double t, double dt)>& time_mark);

  int increment() const { return increment_; }  ///< 1-based
  int attempt() const { return attempt_; }      ///< 1-based
  double start() const { return t_; }           ///< step time at the increment's start
  double size() const { return dt_; }           ///< the current attempt's dt
  double end() const { return t_ + dt_; }       ///< step time the current attempt reaches
  bool ends_step() const { return end() >= limits_.period * (1 - 1e-12); }

  /// The attempt failed. `singular`: a rigid-body mode; `contact`: contact pairs are in force
  /// (they may hold the body once a smaller increment stops an overshooting iteration).
  Cutback attempt_failed(bool singular, bool contact);
  /// The attempt failed for a reason the size does not cure (automatic stabilization had not
  /// started yet): try again with the same size, as one more attempt.
  Cutback retry_same_size();
  /// The attempt converged in `equilibrium_iterations`: time advances, the next size is chosen.
  void attempt_converged(int equilibrium_iterations);

 private:
  IncrementLimits limits_;
  double t_ = 0.0;
  double dt_ = 0.0;
  double dt_unmarked_ = 0.0;  ///< the size before the time mark shortened it
  int increment_ = 0;
  int attempt_ = 1;
  bool cut_back_ = false;  ///< this increment was cut back
  int easy_in_a_row_ = 0;
};

}  // namespace inpact::solver
