#include "analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "analysis_model.hpp"
#include "assembler.hpp"
#include "augmentation.hpp"
#include "blas_info.hpp"
#include "contact/step_changes.hpp"
#include "contact_problem.hpp"
#include "dof_map.hpp"
#include "dof_names.hpp"
#include "element_activity.hpp"
#include "field_output.hpp"
#include "increment_controller.hpp"
#include "linear_solve.hpp"
#include "material_states.hpp"
#include "newton.hpp"
#include "pretension.hpp"
#include "rotation_moments.hpp"
#include "solution_controls.hpp"
#include "stabilization.hpp"
#include "step_conditions.hpp"

namespace inpact::solver {

namespace {

/// The deck line of the last *CLOAD up to step `index` that loads global DOF d.
model::SourceLoc cload_line(const AnalysisModel& am, std::size_t index, std::int64_t d) {
  model::SourceLoc loc{};
  for (std::size_t s = 0; s <= index; ++s)
    for (const auto& block : am.model->steps[s].cloads)
      for (const auto& e : block.entries)
        for (std::int32_t n : e.nodes)
          if (am.dof_index(n, e.dof) == d) loc = e.loc;
  return loc;
}

/// A *CLOAD on a DOF that nothing connects (no element, and not a DOF its reference node's
/// coupling couples) would act on nothing: a deck error rather than a lost load.
void check_loads_act_on_something(const AnalysisModel& am, std::size_t index, const StepConditions& conditions,
                                  const DofMap& dofs) {
  for (std::int64_t d : conditions.loaded_dofs())
    if (dofs.kind(d) == DofMap::Kind::Unused)
      throw AnalysisError(fmt::format("{}: error: *CLOAD: {} carries a load but nothing connects that degree of "
                                      "freedom (no element; for a coupling's reference node, the DOF is not among the "
                                      "coupled ones), so the load would act on nothing",
                                      am.model->sources.describe(cload_line(am, index, d)), node_dof(am, d)));
}

}  // namespace

void check_step_setup(const AnalysisModel& am) {
  ConditionHistory history = initial_history(am);
  double total_time = 0.0;
  for (std::size_t index = 0; index < am.model->steps.size(); ++index) {
    const model::Step& step = am.model->steps[index];
    const StepConditions conditions(am, step, history, total_time);
    const DofMap dofs = DofMap::build(am, conditions.prescribed(), step.nlgeom, step_elements(*am.model, index).active);
    check_loads_act_on_something(am, index, conditions, dofs);
    history = conditions.end_state(std::vector<double>(am.n_dof(), 0.0));
    total_time += step.static_procedure->time_period;
  }
}

namespace {

/// What a step needs while it runs, built when it starts. Not movable: the assembler keeps a
/// reference to the DOF map beside it.
struct StepRun {
  StepRun(const AnalysisModel& am, std::size_t index, const ConditionHistory& history, double total_time, int threads,
          MaterialStates& material_states)
      : step(am.model->steps[index]),
        number(static_cast<int>(index + 1)),
        start_time(total_time),
        conditions(am, step, history, total_time),
        elements(step_elements(*am.model, index)),
        dofs(DofMap::build(am, conditions.prescribed(), step.nlgeom, elements.active)),
        assembler(am, dofs, threads, &material_states),
        controls(solution_controls(step)),
        output(am, index),
        contact(std::make_unique<ContactProblem>(am, index)),
        states(material_states) {
    if (contact->empty()) contact.reset();
    else contact->set_threads(threads);
    check_loads_act_on_something(am, index, conditions, dofs);
  }
  StepRun(const StepRun&) = delete;

  const model::Step& step;
  int number;  ///< 1-based
  double start_time;
  StepConditions conditions;
  StepElements elements;  ///< *MODEL CHANGE, TYPE=ELEMENT: the active ones
  DofMap dofs;
  Assembler assembler;
  SolutionControls controls;
  LinearSolvers solvers;  ///< their symbolic analyses last the step
  StepOutput output;
  std::unique_ptr<ContactProblem> contact;  ///< null when no contact pair is in force
  std::unique_ptr<StepStabilization> stabilization;  ///< *STATIC, STABILIZE or contact stabilization, else null
  MaterialStates& states;                   ///< the points' material history (the analysis's)
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

/// Under NLGEOM in 3D a turning node's reactions are conjugate to its rotation vector; RM reports
/// the spatial moment T⁻ᵀ(ψ) f_ψ (rotation_moments.hpp) where all three of its rotations are
/// held (with some free, the conjugate reaction stays as it is).
void spatial_reaction_moments(const AnalysisModel& am, const DofMap& dofs, std::span<const double> u,
                              std::vector<double>& rf) {
  std::vector<std::int32_t> held;
  for (std::int32_t node : rotation_nodes(am)) {
    const std::int64_t first = static_cast<std::int64_t>(node) * am.dim;
    if (dofs.kind(first) == DofMap::Kind::Prescribed && dofs.kind(first + 1) == DofMap::Kind::Prescribed &&
        dofs.kind(first + 2) == DofMap::Kind::Prescribed)
      held.push_back(node);
  }
  conjugate_to_moments(u, held, rf);
}

std::string describe_dof(const AnalysisModel& am, std::int64_t d) {
  if (d < 0) return "";
  return ", largest residual at " + node_dof(am, d);
}

/// The assembler's element points at u (its forces are discarded).
const ElementPoints* assemble_points(StepRun& run, std::span<const double> u, std::span<const double> delta_t) {
  AssemblyRequest request;
  request.tangent = false;
  request.points = true;
  request.nlgeom = run.step.nlgeom;
  request.delta_t = delta_t;
  std::vector<double> f_int(u.size());
  run.assembler.assemble(u, request, f_int);
  return run.assembler.points_at(u, delta_t, run.step.nlgeom);
}

/// The output due at a converged increment: a results frame and/or the printed tables.
void write_output(const AnalysisModel& am, StepRun& run, const IncrementState& s, int increment, double t,
                  double dt, const OutputDue& due, AnalysisObserver& observer, std::vector<HistoryValue> history) {
  if (!due.any_field() && !due.any_print()) return;
  const auto started = std::chrono::steady_clock::now();
  ContactResults contact;
  if (run.contact) contact = run.contact->results(s.u, s.contact);
  const std::vector<double> delta_t = run.conditions.temperature_change(t);
  // The element point values of the converged state, as its last assembly kept them. With
  // *MODEL CHANGE only the assembler knows where each element's strain is measured from.
  const ElementPoints* points = run.assembler.points_at(s.u, delta_t, run.step.nlgeom);
  if (!points && !run.elements.active.empty()) points = assemble_points(run, s.u, delta_t);
  std::vector<double> rf = reactions(run.dofs, s);
  if (run.step.nlgeom && am.dim == 3) spatial_reaction_moments(am, run.dofs, s.u, rf);
  report_pretension_forces(am, s.f_int, s.f_ext, rf);  // RF1 of a pre-tension node: the bolt force
  OutputValues values = compute_output(am, run.output, due, s.u, rf, run.step.nlgeom, delta_t,
                                       run.contact ? &contact : nullptr, points, &run.states);
  if (due.any_field()) {
    Frame frame;
    frame.increment = increment;
    frame.step_time = t;
    frame.total_time = run.start_time + t;
    frame.fields = std::move(values.fields);
    frame.history = std::move(history);
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

/// The outcome of an analysis that stopped, saying why.
AnalysisOutcome stopped(std::string message) {
  AnalysisOutcome out;
  out.message = std::move(message);
  return out;
}

/// The .sta row of an attempt. A cut-back attempt shows the time at the start of the increment,
/// as Abaqus does.
StatusRow status_row(const StepRun& run, const IncrementController& inc, const NewtonOutcome& outcome,
                     int augmentations) {
  StatusRow row;
  row.step = run.number;
  row.increment = inc.increment();
  row.attempt = inc.attempt();
  row.cut_back = !outcome.converged;
  row.severe_discon_iters = outcome.severe_iterations;
  row.equil_iters = outcome.iterations - outcome.severe_iterations;
  row.total_iters = outcome.iterations;
  row.augmentations = augmentations;
  row.step_time = inc.start() + (outcome.converged ? inc.size() : 0.0);
  row.total_time = run.start_time + row.step_time;
  row.inc_of_time = inc.size();
  return row;
}

/// ALLSE and ALLSD of a stabilized step at a converged increment: a .sta note and the frame's
/// history values.
std::vector<HistoryValue> stabilization_energies(StepRun& run, std::span<const double> u_start,
                                                 std::span<const double> u, double t, double dt,
                                                 AnalysisObserver& observer) {
  StepStabilization& stab = *run.stabilization;
  const std::vector<double> delta_t = run.conditions.temperature_change(t);
  const double contact_dissipated = run.contact ? run.contact->damping_dissipated() : 0.0;
  observer.status_note(
      stab.increment_converged(u_start, u, dt, run.assembler, delta_t, run.step.nlgeom, contact_dissipated));
  return {{"ALLSE", stab.allse()}, {"ALLSD", stab.allsd()}};
}

/// One attempt of the current increment: the augmentation level, then its .sta row.
NewtonOutcome run_attempt(const AnalysisModel& am, StepRun& run, const IncrementController& inc,
                          const TimeAveragedForce& force, IncrementState& trial, AnalysisObserver& observer) {
  NewtonContext ctx{.am = am,
                    .conditions = run.conditions,
                    .assembler = run.assembler,
                    .solvers = run.solvers,
                    .controls = run.controls,
                    .observer = observer,
                    .contact = run.contact.get(),
                    .nlgeom = run.step.nlgeom,
                    .force_history = force,
                    .at = {run.number, inc.increment(), inc.attempt()},
                    .keep_points = run.output.points_due(inc.increment(), inc.end(), inc.ends_step()),
                    .stabilization = run.stabilization ? run.stabilization->for_attempt(inc.size(), trial.u) : nullptr,
                    .rotating_dofs = run.dofs.has_finite_rotations() ? &run.dofs : nullptr};
  if (run.contact && run.contact->has_damping())  // contact stabilization: this attempt's damping
    run.contact->set_damping(run.conditions, trial.u, inc.end(), inc.size(), inc.increment(),
                             run.step.static_procedure->time_period);
  int augmentations = 0;
  NewtonOutcome outcome = solve_with_augmentations(ctx, inc.end(), trial, augmentations);
  // Equilibrium alone does not make an increment acceptable: a plastic strain increment far
  // beyond first yield is cut back (Abaqus/Standard does the same, with this message).
  if (outcome.converged && !run.states.empty())
    if (const std::size_t n = run.states.points_with_too_large_increments(am); n > 0) {
      outcome.converged = false;
      outcome.failure = fmt::format("the strain increment has exceeded fifty times the strain to cause first yield at "
                                    "{} point{}", n, n == 1 ? "" : "s");
    }
  observer.attempt_finished(status_row(run, inc, outcome, augmentations));
  return outcome;
}

/// The increments of one step: the controller sizes them (automatic or DIRECT incrementation,
/// cutbacks, time marks); each converged one advances the state and writes its output.
AnalysisOutcome run_increments(const AnalysisModel& am, StepRun& run, IncrementState& state, AnalysisObserver& observer) {
  IncrementController inc(increment_limits(run.step, run.controls));
  TimeAveragedForce force;  // q̃ over the step's converged increments
  const auto time_mark = [&run](double t, double dt) { return run.output.limit_increment(t, dt); };
  while (!inc.step_complete()) {
    if (auto stop = inc.begin_increment(time_mark))
      return stopped(fmt::format("step {} ({}): {}", run.number, run.step.name, *stop));
    IncrementState trial;
    NewtonOutcome outcome;
    for (;;) {
      trial = state;
      outcome = run_attempt(am, run, inc, force, trial, observer);
      if (outcome.converged) break;
      // A stabilized step's first increment is tried without damping; when it fails (a body
      // held only by contact: a rigid-body mode), damping starts and the singularity is no reason to stop.
      const bool damping_starts = run.stabilization && run.stabilization->attempt_failed(run.assembler);
      // A singular first solve with a contact pair that touched nowhere at its start: a free body
      // that no cutback can hold (unless damping starts now).
      const std::string untouched =
          outcome.singular && run.contact && !damping_starts ? run.contact->untouched_at_start() : "";
      const std::string where = fmt::format("step {} ({}), increment {}, attempt {}, step time {:.6g} + {:.3g}: {}{}{}",
                                            run.number, run.step.name, inc.increment(), inc.attempt(), inc.start(),
                                            inc.size(), outcome.failure, describe_dof(am, outcome.worst_dof), untouched);
      const Cutback cutback = damping_starts ? inc.retry_same_size()
                                             : inc.attempt_failed(outcome.singular, run.contact != nullptr && untouched.empty());
      if (!cutback.retry) return stopped(where + cutback.note);
      observer.message(where + cutback.note +
                       (damping_starts ? fmt::format(" (damping factor {:.4g})", run.stabilization->factor()) : ""));
      run.states.discard();  // the next attempt starts from the same committed history
    }
    const int increment = inc.increment();
    const double t = inc.end(), dt = inc.size();
    inc.attempt_converged(outcome.iterations - outcome.severe_iterations);
    std::vector<HistoryValue> history;
    if (run.stabilization) history = stabilization_energies(run, state.u, trial.u, t, dt, observer);
    state = std::move(trial);
    force.add(outcome.average_force);
    write_output(am, run, state, increment, t, dt, run.output.due(increment, t, inc.step_complete()), observer,
                 std::move(history));
    run.states.commit();  // after the output, which evaluates from the committed history
  }
  AnalysisOutcome completed;
  completed.completed = true;
  return completed;
}

/// What a step keeps of its stabilization (*STATIC, STABILIZE and/or contact stabilization), or null.
std::unique_ptr<StepStabilization> step_stabilization(const AnalysisModel& am, StepRun& run, std::span<const double> u,
                                                      double previous_factor, double allsd) {
  const auto& stabilize = run.step.static_procedure->stabilize;
  const bool contact_damping = run.contact && run.contact->has_damping();
  if (!stabilize && !contact_damping) return nullptr;
  return std::make_unique<StepStabilization>(am, stabilize ? &*stabilize : nullptr, run.step.static_procedure->time_period,
                                             run.dofs, run.assembler, u, previous_factor, allsd, contact_damping);
}

/// *MODEL CHANGE at the step's start: the reactivated elements start from a virgin material
/// state, the strain-free ones from where their nodes are; the assembler sees the active set.
void begin_element_changes(const AnalysisModel& am, StepRun& run, std::span<const double> u,
                           ElementReferences& references) {
  if (run.elements.active.empty()) return;
  references.begin_step(am, run.elements, u);
  for (std::int32_t e : run.elements.added) run.states.reset(am, static_cast<std::size_t>(e));
  run.assembler.set_elements(&run.elements, &references);
}

/// The forces the elements that `next` removes exert at the end of this step, added to what the
/// next step releases (ConditionHistory::released_forces).
void release_element_forces(StepRun& run, const StepElements& next,
                            const IncrementState& state, ConditionHistory& history) {
  if (next.removed.empty()) return;
  AssemblyRequest request;
  request.tangent = false;
  request.nlgeom = run.step.nlgeom;
  const std::vector<double> delta_t = run.conditions.temperature_change(run.step.static_procedure->time_period);
  request.delta_t = delta_t;
  const std::vector<double> f = run.assembler.element_forces(next.removed, state.u, request);
  if (history.released_forces.empty()) history.released_forces.assign(f.size(), 0.0);
  for (std::size_t d = 0; d < f.size(); ++d) history.released_forces[d] += f[d];
}

}  // namespace

AnalysisOutcome run_analysis(const model::Model& model, AnalysisObserver& observer, const AnalysisOptions& options) {
  set_blas_threads(options.threads);
  const AnalysisModel am = build_analysis_model(model);
  MaterialStates material_states(am);
  return run_steps(am, material_states, observer, options);
}

AnalysisOutcome run_steps(const AnalysisModel& am, MaterialStates& material_states, AnalysisObserver& observer,
                          const AnalysisOptions& options) {
  const model::Model& model = *am.model;
  for (const auto& note : model.preprocessing_notes) observer.message(note);
  for (const auto& note : am.contact->notes) observer.message(note);
  if (const std::string shared = describe_distribution(am, rank_world()); !shared.empty()) {
    observer.message(shared);
    observer.status_note(shared);
  }
  ConditionHistory history = initial_history(am);
  IncrementState state;
  state.u.assign(am.n_dof(), 0.0);
  state.f_int.assign(am.n_dof(), 0.0);
  state.f_ext.assign(am.n_dof(), 0.0);
  double total_time = 0.0;
  double output_seconds = 0.0;
  double previous_factor = 0.0;  // the damping factor the last step ended with (CONTINUE=YES)
  double allsd = 0.0;            // ALLSD over the steps so far
  IterationSeconds iteration_seconds;
  ElementReferences references;  // elements reactivated strain free (*MODEL CHANGE)
  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const model::Step& step = model.steps[s];
    observer.step_started(step, static_cast<int>(s + 1));
    StepRun run(am, s, history, total_time, options.threads, material_states);
    begin_element_changes(am, run, state.u, references);
    if (options.linear_solver == SolverKind::Petsc) run.solvers.petsc = make_petsc_solver(equation_points(am, run.dofs));
    if (run.contact) {
      const std::vector<std::string> lines = run.contact->describe();
      observer.contact_interactions(static_cast<int>(s + 1), lines);
      for (const auto& line : lines) observer.message(fmt::format("step {} ({}): {}", s + 1, step.name, line));
    }
    for (const auto& v : run.output.not_computed())
      observer.message(fmt::format("step {} ({}): output variable {} is not computed by this version", s + 1,
                                   step.name, v));
    run.stabilization = step_stabilization(am, run, state.u, previous_factor, allsd);
    AnalysisOutcome outcome = run_increments(am, run, state, observer);
    output_seconds += run.output_seconds;
    previous_factor = run.stabilization ? run.stabilization->factor() : 0.0;
    if (run.stabilization) allsd = run.stabilization->allsd();
    if (const auto shared = run.contact ? run.contact->share_summary() : std::nullopt) {
      const std::string line = fmt::format("step {} ({}): {}", s + 1, step.name, *shared);
      observer.message(line);
      observer.status_note("     " + line);
    }
    for (const auto& warning : {run.stabilization ? run.stabilization->end_of_step_warning() : std::nullopt,
                                run.contact && outcome.completed ? run.contact->deep_penetration_warning()
                                                                 : std::nullopt})
      if (warning) {
        const std::string line = fmt::format("step {} ({}): {}", s + 1, step.name, *warning);
        observer.message(line);
        observer.status_note("     " + line);
      }
    iteration_seconds += run.assembler.seconds();
    iteration_seconds += run.solvers.seconds;
    if (run.contact) iteration_seconds += run.contact->seconds();
    if (!outcome.completed) {
      outcome.output_seconds = output_seconds;
      outcome.iteration_seconds = iteration_seconds;
      return outcome;
    }
    // (a turning node's reaction moments carried as spatial moments, StepConditions::external_force)
    std::vector<double> rf_end = reactions(run.dofs, state);
    if (run.step.nlgeom && am.dim == 3) conjugate_to_moments(state.u, rotation_nodes(am), rf_end);
    history = run.conditions.end_state(rf_end);
    // *MODEL CHANGE, REMOVE in the next step releases the forces of the pairs and elements it removes.
    const std::vector<std::size_t> removed = contact::rows_removed_in(model, *am.contact, s + 1);
    if (run.contact && !removed.empty() && s + 1 < model.steps.size())
      history.released_forces = run.contact->pair_forces(removed, state.contact);
    if (s + 1 < model.steps.size()) release_element_forces(run, step_elements(model, s + 1), state, history);
    total_time += step.static_procedure->time_period;
  }
  AnalysisOutcome outcome;
  outcome.completed = true;
  outcome.output_seconds = output_seconds;
  outcome.iteration_seconds = iteration_seconds;
  return outcome;
}

}  // namespace inpact::solver
