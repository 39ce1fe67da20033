#include "increment_controller.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace inpact::solver {

IncrementLimits increment_limits(const model::Step& step, const SolutionControls& controls) {
  const model::StaticProcedure& proc = *step.static_procedure;
  IncrementLimits l;
  l.period = proc.time_period;
  l.initial = proc.initial_increment;
  l.minimum = proc.min_increment.value_or(std::min(proc.initial_increment, 1e-5 * l.period));
  l.maximum = proc.max_increment.value_or(l.period);
  l.direct = proc.direct;
  l.max_increments = step.max_increments;
  l.max_cutbacks = controls.max_cutbacks;
  l.cutback_factor = controls.cutback_factor;
  l.growth_factor = controls.growth_factor;
  l.easy_iterations = controls.easy_iterations;
  return l;
}

IncrementController::IncrementController(const IncrementLimits& limits)
    : limits_(limits), dt_(std::min(limits.initial, limits.period)) {}

std::optional<std::string> IncrementController::begin_increment(
    const std::function<double(double t, double dt)>& time_mark) {
  ++increment_;
  attempt_ = 1;
  cut_back_ = false;
  if (increment_ > limits_.max_increments)
    return fmt::format("more increments needed than INC={} allows, at step time {:.6g}", limits_.max_increments, t_);
  const double period = limits_.period;
  dt_ = std::min(dt_, period - t_);
  if (period - t_ - dt_ < 1e-12 * period) dt_ = period - t_;
  dt_unmarked_ = dt_;  // *OUTPUT, TIME MARKS=YES: end the increment on the next mark
  dt_ = time_mark(t_, dt_);
  return std::nullopt;
}

Cutback IncrementController::attempt_failed(bool singular, bool contact) {
  // No increment size removes a rigid-body mode — unless contact holds the body: an
  // overshooting iteration may have opened what supports it, and a smaller increment may not.
  if (singular && !contact) return {false, ""};
  if (limits_.direct) return {false, " (DIRECT incrementation cannot cut back)"};
  if (attempt_ > limits_.max_cutbacks) return {false, fmt::format(" — gave up after {} cutbacks", limits_.max_cutbacks)};
  if (dt_ * limits_.cutback_factor < limits_.minimum)
    return {false, fmt::format(" — the increment would fall below the minimum {:.3g}", limits_.minimum)};
  const std::string note = fmt::format("; cutting back to {:.3g}", dt_ * limits_.cutback_factor);
  dt_ *= limits_.cutback_factor;
  cut_back_ = true;
  ++attempt_;
  return {true, note};
}

Cutback IncrementController::retry_same_size() {
  if (attempt_ > limits_.max_cutbacks) return {false, fmt::format(" — gave up after {} attempts", attempt_)};
  ++attempt_;
  return {true, fmt::format("; trying {:.3g} again with automatic stabilization", dt_)};
}

void IncrementController::attempt_converged(int equilibrium_iterations) {
  t_ += dt_;
  // After an increment cut short by a time mark, go on with the size the controller chose.
  if (dt_ < dt_unmarked_ && !cut_back_) dt_ = dt_unmarked_;
  // Grow the increment after two easy ones in a row (never right after a cutback).
  easy_in_a_row_ = (!cut_back_ && equilibrium_iterations <= limits_.easy_iterations) ? easy_in_a_row_ + 1 : 0;
  if (!limits_.direct && easy_in_a_row_ >= 2) dt_ = std::min(dt_ * limits_.growth_factor, limits_.maximum);
}

}  // namespace inpact::solver
