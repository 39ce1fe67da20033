#include "analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "analysis_model.hpp"
#include "assembler.hpp"
#include "blas_info.hpp"
#include "contact_problem.hpp"
#include "dof_map.hpp"
#include "field_output.hpp"
#include "linear/linear_solver.hpp"
#include "newton.hpp"
#include "solution_controls.hpp"
#include "step_conditions.hpp"

namespace inpact::solver {

namespace {

/// What a step needs while it runs, built when it starts. Not movable: the assembler keeps a
/// reference to the DOF map beside it.
struct StepRun {
  StepRun(const AnalysisModel& am, std::size_t index, const ConditionHistory& history, double total_time, int threads)
      : step(am.model->steps[index]),
        number(static_cast<int>(index + 1)),
        start_time(total_time),
        conditions(am, step, history, total_time),
        dofs(DofMap::build(am, conditions.prescribed())),
        assembler(am, dofs, threads),
        controls(solution_controls(step)),
        output(am, index),
        contact(std::make_unique<ContactProblem>(am, index)) {
    if (contact->empty()) contact.reset();
  }
  StepRun(const StepRun&) = delete;

  const model::Step& step;
  int number;  ///< 1-based
  double start_time;
  StepConditions conditions;
  DofMap dofs;
  Assembler assembler;
  SolutionControls controls;
  StepOutput output;
  std::unique_ptr<ContactProblem> contact;  ///< null when no contact pair is in force
  double output_seconds = 0.0;              ///< wall time in write_output this step
};

/// Reactions at the prescribed DOFs: RF = f_int − f_ext (zero elsewhere). A DOF that an
/// *EQUATION ties to a prescribed DOF passes its force on to it with the equation's weight.
std::vector<double> reactions(const DofMap& dofs, const IncrementState& s) {
  std::vector<double> rf(s.u.size(), 0.0);
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d)
    if (dofs.kind(d) == DofMap::Kind::Prescribed || dofs.kind(d) == DofMap::Kind::Dependent)
      for (const auto& m : dofs.masters(d))
        if (dofs.kind(m.dof) == DofMap::Kind::Prescribed) rf[m.dof] += m.weight * (s.f_int[d] - s.f_ext[d]);
  return rf;
}

std::string describe_dof(const AnalysisModel& am, std::int64_t d) {
  if (d < 0) return "";
  const auto& nodes = am.model->mesh.nodes;
  const std::size_t node = static_cast<std::size_t>(d / am.dim);
  const std::string inst = am.model->instances[nodes.instance[node]];
  return fmt::format(", largest residual at node {}{} DOF {}", inst.empty() ? "" : inst + ".", nodes.labels[node],
                     d % am.dim + 1);
}

/// The output due at a converged increment: a results frame and/or the printed tables.
void write_output(const AnalysisModel& am, StepRun& run, const IncrementState& s, int increment, double t,
                  double dt, const OutputDue& due, AnalysisObserver& observer) {
  if (!due.any_field() && !due.any_print()) return;
  const auto started = std::chrono::steady_clock::now();
  ContactResults contact;
  if (run.contact) contact = run.contact->results(s.u, s.contact);
  const std::vector<double> delta_t = run.conditions.temperature_change(t);
  // The element point values of the converged state, as its last assembly kept them.
  const ElementPoints* points = run.assembler.points_at(s.u, delta_t, run.step.nlgeom);
  OutputValues values = compute_output(am, run.output, due, s.u, reactions(run.dofs, s), run.step.nlgeom, delta_t,
                                       run.contact ? &contact : nullptr, points);
  if (due.any_field()) {
    Frame frame;
    frame.increment = increment;
    frame.step_time = t;
    frame.total_time = run.start_time + t;
    frame.fields = std::move(values.fields);
    observer.frame(frame);
  }
  if (due.any_print()) {
    PrintFrame print;
    print.step = run.number;
    print.increment = increment;
    print.step_time = t;
    print.total_time = run.start_time + t;
    print.inc_of_time = dt;
    print.time_period = run.step.static_procedure->time_period;
    print.tables = std::move(values.tables);
    observer.print_frame(print);
  }
  run.output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

/// The augmentation level of one increment attempt: Newton to convergence, then, for
/// augmented-Lagrange pairs, while a penetration exceeds its tolerance,
///   λ ← ⟨λ + k (h + c0)⟩  and Newton again from the converged state,
/// at most I_A^c times (*CONTROLS, PARAMETERS=TIME INCREMENTATION, field 13; default 50).
NewtonOutcome solve_with_augmentations(NewtonContext& ctx, double t, IncrementState& state, int& augmentations) {
  NewtonOutcome total;
  // USER ADAPTIVE: the first increment's early iterations with a reduced penalty stiffness, to
  // find the contact status; then its final iterations (below) with the full stiffness.
  if (ctx.contact && ctx.contact->has_user_adaptive() && ctx.increment == 1) {
    ctx.contact->set_user_adaptive_scale(kUserAdaptiveScale);
    total = solve_increment(ctx, t, state);
    ctx.contact->set_user_adaptive_scale(1.0);
    if (!total.converged) return total;
  }
  for (augmentations = 0;; ++augmentations) {
    NewtonOutcome outcome = solve_increment(ctx, t, state);
    outcome.iterations += total.iterations;
    outcome.severe_iterations += total.severe_iterations;
    outcome.average_force = std::max(outcome.average_force, total.average_force);
    total = outcome;
    if (!total.converged || !ctx.contact || !ctx.contact->has_augmented_lagrange()) return total;
    const AugmentationCheck check = ctx.contact->check_augmentation(state.contact);
    if (check.converged) return total;
    if (augmentations >= ctx.controls.max_augmentations) {
      total.converged = false;
      total.failure = fmt::format("augmented Lagrange: penetration {:.4g} at slave node {} still exceeds the tolerance "
                                  "{:.4g} after {} augmentations (the most *CONTROLS allows)",
                                  check.max_penetration, ctx.am.model->mesh.nodes.labels[check.node], check.tolerance,
                                  augmentations);
      return total;
    }
    ctx.contact->augment(state.contact);
  }
}

/// The increments of one step: automatic (or DIRECT fixed) incrementation with cutbacks.
AnalysisOutcome run_increments(const AnalysisModel& am, StepRun& run, IncrementState& state, AnalysisObserver& observer) {
  const model::StaticProcedure& proc = *run.step.static_procedure;
  const double period = proc.time_period;
  const double dt_min = proc.min_increment.value_or(std::min(proc.initial_increment, 1e-5 * period));
  const double dt_max = proc.max_increment.value_or(period);
  const SolutionControls& c = run.controls;
  auto cholmod = make_cholmod_solver();
  auto umfpack = make_umfpack_solver();

  double t = 0.0, dt = std::min(proc.initial_increment, period);
  double force_sum = 0.0;
  int force_count = 0, easy_in_a_row = 0;
  for (int increment = 1; t < period * (1 - 1e-12); ++increment) {
    if (increment > run.step.max_increments)
      return {false, fmt::format("step {} ({}): more increments needed than INC={} allows, at step time {:.6g}",
                                 run.number, run.step.name, run.step.max_increments, t)};
    dt = std::min(dt, period - t);
    if (period - t - dt < 1e-12 * period) dt = period - t;
    const double dt_unmarked = dt;  // *OUTPUT, TIME MARKS=YES: end the increment on the next mark
    dt = run.output.limit_increment(t, dt);
    IncrementState trial;
    NewtonOutcome outcome;
    bool cut_back_this_increment = false;
    for (int attempt = 1;; ++attempt) {
      trial = state;
      NewtonContext ctx{am, run.conditions, run.assembler, *cholmod, *umfpack, c, observer, run.step.nlgeom,
                        force_sum, force_count, run.number, increment, attempt, run.contact.get()};
      ctx.keep_points = run.output.points_due(increment, t + dt, t + dt >= period * (1 - 1e-12));
      int augmentations = 0;
      outcome = solve_with_augmentations(ctx, t + dt, trial, augmentations);
      StatusRow row;
      row.step = run.number;
      row.increment = increment;
      row.attempt = attempt;
      row.cut_back = !outcome.converged;
      row.severe_discon_iters = outcome.severe_iterations;
      row.equil_iters = outcome.iterations - outcome.severe_iterations;
      row.total_iters = outcome.iterations;
      row.augmentations = augmentations;
      // A cut-back attempt shows the time at the start of the increment, as Abaqus does.
      row.step_time = t + (outcome.converged ? dt : 0.0);
      row.total_time = run.start_time + row.step_time;
      row.inc_of_time = dt;
      observer.attempt_finished(row);
      if (outcome.converged) break;
      const std::string where = fmt::format("step {} ({}), increment {}, attempt {}, step time {:.6g} + {:.3g}: {}{}",
                                            run.number, run.step.name, increment, attempt, t, dt, outcome.failure,
                                            describe_dof(am, outcome.worst_dof));
      // No increment size removes a rigid-body mode — unless contact holds the body: an
      // overshooting iteration may have opened what supports it, and a smaller increment may not.
      if (outcome.singular && !run.contact) return {false, where};
      if (proc.direct) return {false, where + " (DIRECT incrementation cannot cut back)"};
      if (attempt > c.max_cutbacks) return {false, where + fmt::format(" — gave up after {} cutbacks", c.max_cutbacks)};
      if (dt * c.cutback_factor < dt_min)
        return {false, where + fmt::format(" — the increment would fall below the minimum {:.3g}", dt_min)};
      observer.message(where + fmt::format("; cutting back to {:.3g}", dt * c.cutback_factor));
      dt *= c.cutback_factor;
      cut_back_this_increment = true;
    }
    state = std::move(trial);
    t += dt;
    force_sum += outcome.average_force;
    ++force_count;
    const bool last = t >= period * (1 - 1e-12);
    write_output(am, run, state, increment, t, dt, run.output.due(increment, t, last), observer);
    // After an increment cut short by a time mark, go on with the size the controller chose.
    if (dt < dt_unmarked && !cut_back_this_increment) dt = dt_unmarked;
    // Grow the increment after two easy ones in a row (never right after a cutback).
    const int equilibrium_iterations = outcome.iterations - outcome.severe_iterations;
    easy_in_a_row = (!cut_back_this_increment && equilibrium_iterations <= c.easy_iterations) ? easy_in_a_row + 1 : 0;
    if (!proc.direct && easy_in_a_row >= 2) dt = std::min(dt * c.growth_factor, dt_max);
  }
  return {true, ""};
}

}  // namespace

AnalysisOutcome run_analysis(const model::Model& model, AnalysisObserver& observer, const AnalysisOptions& options) {
  set_blas_threads(options.threads);
  const AnalysisModel am = build_analysis_model(model);
  for (const auto& note : model.preprocessing_notes) observer.message(note);
  for (const auto& note : am.contact->notes) observer.message(note);
  ConditionHistory history = initial_history(am);
  IncrementState state;
  state.u.assign(am.n_dof(), 0.0);
  state.f_int.assign(am.n_dof(), 0.0);
  state.f_ext.assign(am.n_dof(), 0.0);
  double total_time = 0.0;
  double output_seconds = 0.0;
  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const model::Step& step = model.steps[s];
    observer.step_started(step, static_cast<int>(s + 1));
    StepRun run(am, s, history, total_time, options.threads);
    if (run.contact) {
      const std::vector<std::string> lines = run.contact->describe();
      observer.contact_interactions(static_cast<int>(s + 1), lines);
      for (const auto& line : lines) observer.message(fmt::format("step {} ({}): {}", s + 1, step.name, line));
    }
    for (const auto& v : run.output.not_computed())
      observer.message(fmt::format("step {} ({}): output variable {} is not computed by this version", s + 1,
                                   step.name, v));
    AnalysisOutcome outcome = run_increments(am, run, state, observer);
    output_seconds += run.output_seconds;
    if (!outcome.completed) {
      outcome.output_seconds = output_seconds;
      return outcome;
    }
    history = run.conditions.end_state(reactions(run.dofs, state));
    total_time += step.static_procedure->time_period;
  }
  return {true, "", output_seconds};
}

}  // namespace inpact::solver
