#include "newton.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "elements/corotation.hpp"

namespace inpact::solver {

namespace {

/// One iteration's residual and what it is measured against.
struct Residual {
  AssemblyRequest request;  ///< how the elements were assembled (the solve may add the tangent)
  AssemblyResult assembly;
  FieldMaxima largest;      ///< per field, the largest |r| at a free DOF and its DOF
  PerField q{};             ///< q̃ per field
  double max = 0.0;         ///< the largest |r| of the field furthest from its tolerance (below)
  std::int64_t worst = -1;  ///< its DOF
  double ratio = 0.0;       ///< its r_max / q̃ (0 without force)

  /// max, worst and ratio from `largest` and `q`: the field with the larger r_max / q̃.
  void pick_worst_field() {
    for (std::size_t f = 0; f < kFields; ++f) {
      const double field_ratio = q[f] > 0 ? largest.value[f] / q[f] : 0.0;
      if (f == 0 || field_ratio > ratio || !std::isfinite(largest.value[f])) {
        ratio = field_ratio;
        max = largest.value[f];
        worst = largest.dof[f];
      }
    }
  }
};

/// The iterations of one attempt and the state they share.
class NewtonIterations {
 public:
  NewtonIterations(NewtonContext& ctx, double t, IncrementState& state);
  NewtonOutcome run();

 private:
  ContactIteration update_contact(int k);
  Residual assemble_residual(int k);
  PerField largest_correction(int k) const;
  bool failed(int k, const Residual& res, const ContactIteration& contact);
  std::string turned_inside_out(const AssemblyResult& assembly, bool solved) const;
  bool gives_up(int k, const Residual& res, const ContactIteration& contact);
  bool solve_correction(Residual& res);
  void apply_correction();
  bool limits_correction() const;
  void limit_correction(int k, ContactIteration& contact, Residual& res);
  void scale_last_correction(double factor);
  bool predict();

  NewtonContext& ctx_;
  IncrementState& state_;
  const double t_;  ///< the step time the increment ends at
  const DofMap& dofs_;
  const std::size_t n_, n_eq_;  ///< DOFs, and the DOF map's equations (the multipliers follow)
  const std::vector<double> u_start_;
  const std::vector<double> delta_t_;
  std::vector<double> r_full_, r_, du_;
  std::vector<Field> equation_field_;  ///< per equation of the DOF map, the field of its free DOF
  std::vector<double> f_int_elements_;  ///< f_int before the contact forces are added (for q)
  std::vector<PerField> history_;       ///< per field, the largest residual of each iteration without a status change
  CorrectionSolver solver_;
  IncrementForce increment_force_;
  bool status_changed_at_start_ = false;
  AugmentedPenetrations penetrations_;  ///< augmented-Lagrange pairs: before the last correction
  SlippingTrials slipping_trials_;      ///< pairs with friction: before the last correction
  ContactState contact_before_;         ///< the contact state before this iteration's update
  NewtonOutcome out_;
};

NewtonIterations::NewtonIterations(NewtonContext& ctx, double t, IncrementState& state)
    : ctx_(ctx),
      state_(state),
      t_(t),
      dofs_(ctx.assembler.dofs()),
      n_(static_cast<std::size_t>(dofs_.n_dof())),
      n_eq_(static_cast<std::size_t>(dofs_.n_equations())),
      u_start_(state.u),
      delta_t_(ctx.conditions.temperature_change(t)),
      r_full_(n_),
      r_(n_eq_),
      du_(n_eq_),
      equation_field_(n_eq_, kDisplacementField),
      solver_(ctx.solvers) {
  for (std::int64_t d = 0; d < dofs_.n_dof(); ++d)
    if (dofs_.kind(d) == DofMap::Kind::Free) equation_field_[static_cast<std::size_t>(dofs_.equation(d))] = dofs_.field(d);
  // Impose the boundary conditions of time t, then iterate on the free DOFs.
  solver_.set_residual_tolerance(ctx.controls.residual_tolerance);
  ctx.conditions.apply_prescribed(t, u_start_, state.u);
  dofs_.update_dependent(state.u);
  if (ctx.rotating_dofs) ctx.rotating_dofs->relinearize(ctx.am, state.u);
  state.f_ext.assign(n_, 0.0);
  // (on the increment's start, u with its prescribed values, where the load follows u)
  if (ctx.conditions.depends_on_displacement()) ctx.conditions.external_force(t, state.u, state.f_ext);
  else ctx.conditions.external_force(t, state.f_ext);
  state.f_int.assign(n_, 0.0);
}

NewtonOutcome NewtonIterations::run() {
  // A new increment commits the friction history of the converged state it starts from.
  if (ctx_.contact) ctx_.contact->begin_attempt(state_.contact, ctx_.at.step, ctx_.at.increment, u_start_);
  for (int k = predict() ? 1 : 0;; ++k) {
    // (the contact state the iterate starts from: limit_correction evaluates a cut iterate from it)
    if (k > 0 && limits_correction()) contact_before_ = state_.contact;
    ContactIteration contact = update_contact(k);
    Residual res = assemble_residual(k);
    limit_correction(k, contact, res);
    const PerField max_correction = largest_correction(k);
    ctx_.observer.iteration({ctx_.at.step, ctx_.at.increment, ctx_.at.attempt, k, res.max, res.ratio,
                             *std::max_element(max_correction.begin(), max_correction.end()), res.worst});
    if (failed(k, res, contact)) return out_;
    const ConvergenceCheck check = check_convergence(
        {.iteration = k, .max_residual = res.largest.value, .q = res.q, .max_correction = max_correction,
         .max_increment = largest_increment(dofs_, state_.u, u_start_),
         .contact_status_changed = contact.blocks_convergence, .max_gap_error = contact.max_gap_error},
        ctx_.controls);
    if (check.converged) {
      ctx_.assembler.complete_states(state_.u, res.request);
      out_.converged = true;
      return out_;
    }
    if (gives_up(k, res, contact) || !solve_correction(res)) return out_;
    apply_correction();
  }
}

/// Contact search, projection and status at u_k (may resize the system: multipliers).
ContactIteration NewtonIterations::update_contact(int k) {
  ContactIteration contact;
  if (!ctx_.contact) return contact;
  contact = ctx_.contact->update(state_.u, state_.contact, ctx_.assembler);
  // A severe discontinuity iteration: one in which a contact status changed. Changes found
  // before the first solve (the start of the increment) belong to the first iteration, so
  // SEVERE never exceeds TOTAL in the .sta.
  if (k == 0) status_changed_at_start_ = contact.status_changes > 0;
  else if (contact.status_changes > 0 || (k == 1 && status_changed_at_start_)) ++out_.severe_iterations;
  return contact;
}

/// r = f_ext − f_int(u_k) over the equations (elements, then contact forces and constraint
/// rows), its largest entry and q̃.
Residual NewtonIterations::assemble_residual(int k) {
  const std::size_t n_sys = static_cast<std::size_t>(ctx_.assembler.n_equations());
  r_.assign(n_sys, 0.0);
  du_.resize(n_sys, 0.0);
  Residual res;
  // From the second pass on the residual alone decides convergence (a linear step converges
  // there); the tangent is assembled in solve_correction only when another solve follows.
  res.request.tangent = k == 0 || ctx_.contact != nullptr;
  res.request.nlgeom = ctx_.nlgeom;
  res.request.delta_t = delta_t_;
  // The first pass seldom converges (it would need no residual at all to start with): its
  // points are not kept, and should it converge the output computes them instead.
  // A distributed run's ranks evaluate their own elements here, and every element once the
  // increment has converged (Assembler::complete_states).
  res.request.points = ctx_.keep_points && k > 0 && !ctx_.assembler.distributed();
  res.assembly = ctx_.assembler.assemble(state_.u, res.request, state_.f_int);
  double contact_force_sum = 0.0;
  std::size_t contact_force_count = 0;
  if (ctx_.contact) {
    f_int_elements_.assign(state_.f_int.begin(), state_.f_int.end());
    ctx_.contact->assemble(state_.contact, state_.f_int, ctx_.assembler);
    for (std::size_t d = 0; d < n_; ++d)
      if (const double fc = state_.f_int[d] - f_int_elements_[d]; fc != 0.0) {
        contact_force_sum += std::abs(fc);
        ++contact_force_count;
      }
  }
  if (ctx_.stabilization) ctx_.stabilization->add_force(state_.u, state_.f_int);
  // NLGEOM: pressure follows the surface and moments act on turning nodes, f_ext(u) (without
  // their load stiffness in the tangent).
  if (ctx_.conditions.depends_on_displacement()) ctx_.conditions.external_force(t_, state_.u, state_.f_ext);
  for (std::size_t d = 0; d < n_; ++d) r_full_[d] = state_.f_ext[d] - state_.f_int[d];
  ctx_.assembler.reduce(r_full_, std::span(r_).first(n_eq_));
  if (ctx_.contact) ctx_.contact->constraint_residual(state_.contact, std::span(r_).subspan(n_eq_));

  res.largest = largest_residual(dofs_, r_);
  const PerField q_now = average_force(res.assembly, dofs_, state_.f_ext, contact_force_sum, contact_force_count);
  out_.iterations = k;
  const PerField q_without_contact =
      ctx_.contact ? average_force(res.assembly, dofs_, state_.f_ext, 0.0, 0) : q_now;
  out_.average_force = increment_force_.update(q_without_contact, q_now);
  res.q = coupled_fields(ctx_.force_history.with(out_.average_force), ctx_.am.size);
  res.pick_worst_field();
  out_.max_residual = res.max;
  out_.worst_dof = res.worst;
  return res;
}

/// Per field, the largest |correction| of the last solve (0 before one).
PerField NewtonIterations::largest_correction(int k) const {
  PerField largest{};
  if (k == 0) return largest;
  for (std::size_t eq = 0; eq < n_eq_; ++eq)
    largest[equation_field_[eq]] = std::max(largest[equation_field_[eq]], std::abs(du_[eq]));
  return largest;
}

/// A state no iteration can recover from.
bool NewtonIterations::failed(int k, const Residual& res, const ContactIteration& contact) {
  // An inverted point first: a hyperelastic law answers one with NaN.
  if (const std::string inverted = turned_inside_out(res.assembly, k > 0); !inverted.empty()) {
    out_.failure = inverted;
    return true;
  }
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!std::all_of(res.largest.value.begin(), res.largest.value.end(), finite) ||
      !std::all_of(res.q.begin(), res.q.end(), finite)) {
    out_.failure = "the residual is not a number (NaN or infinite)";
    return true;
  }
  if (!contact.failure.empty()) {
    out_.failure = contact.failure;
    return true;
  }
  return false;
}

/// Why the assembled state is no body's (empty: it is one): an element whose reference geometry
/// is inverted or degenerate, or, under NLGEOM, one turned inside out at an integration point
/// (det F ≤ 0) in an iterate a solve gave (`solved`): the start of an increment that moved its
/// prescribed DOFs alone (no prediction: contact, stabilisation) may fold the elements beside
/// them, which the first correction undoes. Abaqus cuts the increment back on "excessively
/// distorted" elements alike.
std::string NewtonIterations::turned_inside_out(const AssemblyResult& assembly, bool solved) const {
  const auto label = [&](std::int64_t e) { return ctx_.am.model->mesh.elements.labels[static_cast<std::size_t>(e)]; };
  if (assembly.jacobian.element >= 0 && assembly.jacobian.value <= 0.0)
    return fmt::format("element {} is turned inside out (Jacobian {:.3g})", label(assembly.jacobian.element),
                       assembly.jacobian.value);
  if (!solved || assembly.volume_ratio.element < 0 || assembly.volume_ratio.value > 0.0) return {};
  const auto e = static_cast<std::size_t>(assembly.volume_ratio.element);
  if (elements::takes_finite_rotations(*ctx_.am.elements[e].type))  // corotation.hpp: no frame or log
    return fmt::format("element {} is distorted beyond its corotated frame (a node turned half round against it)",
                       label(assembly.volume_ratio.element));
  return fmt::format("element {} is turned inside out at an integration point (det F = {:.3g})",
                     label(assembly.volume_ratio.element), assembly.volume_ratio.value);
}

/// Too many iterations, or a residual that grows twice in a row (in either field: a force and a
/// moment are not compared).
bool NewtonIterations::gives_up(int k, const Residual& res, const ContactIteration& contact) {
  // Severe discontinuity iterations count apart (Abaqus: I_S = 50 of them, I_C equilibrium
  // ones) and stay out of the divergence check.
  if (contact.status_changes == 0) history_.push_back(res.largest.value);
  if (k - out_.severe_iterations >= ctx_.controls.max_iterations || out_.severe_iterations > kMaxSevereIterations) {
    out_.failure = fmt::format("no convergence in {} iterations ({} with contact status changes)", k,
                               out_.severe_iterations);
    return true;
  }
  const std::size_t h = history_.size();
  const auto grows_twice = [&](std::size_t f) {
    return history_[h - 1][f] > history_[h - 2][f] && history_[h - 2][f] > history_[h - 3][f];
  };
  if (k >= ctx_.controls.divergence_check_after && h >= 3 &&
      (grows_twice(kDisplacementField) || grows_twice(kRotationField))) {
    out_.failure = "the residual grows in two consecutive iterations (diverging)";
    return true;
  }
  return false;
}

/// K Δu = r; the tangent of an unsymmetric contact formulation (friction) is given in full.
bool NewtonIterations::solve_correction(Residual& res) {
  if (!res.request.tangent) {  // same u: f_int comes out the same, now with K(u_k)
    res.request.tangent = true;
    res.request.points = false;  // the points kept above are at this u already
    ctx_.assembler.assemble(state_.u, res.request, state_.f_int);
  }
  if (ctx_.stabilization) ctx_.stabilization->add_tangent(ctx_.assembler);
  const SparseMatrix* tangent = &ctx_.assembler.tangent();
  if (ctx_.contact && ctx_.contact->unsymmetric()) tangent = &ctx_.contact->unsymmetric_tangent(*tangent);
  const std::size_t n_sys = static_cast<std::size_t>(ctx_.assembler.n_equations());
  CorrectionOutcome solved =
      solver_.solve(*tangent, n_sys > n_eq_, r_, du_, n_eq_, ctx_.am.size, res.ratio);
  if (solved.solved) return true;
  out_.failure = std::move(solved.failure);
  out_.singular = solved.singular;
  return false;
}

/// The first iteration of prescribed motion, as Abaqus makes it: the tangent of the converged
/// state at the increment start carries the prescribed increment Δu_p into the body,
///   K(u_n) Δu = f_ext(t) − f_int(u_n) − K(u_n)·Δu_p,  u = u_n + Δu_p + Δu,
/// instead of moving the prescribed DOFs alone, which strains only the elements next to them
/// (with plasticity into a localised plastic state whose tangent Newton does not recover from).
/// K(u_n)·Δu_p comes from the same element stiffnesses as the tangent. A rigid body or kinematic
/// coupling turned by a prescribed rotation has its nodes on the exact R(θ) already (in Δu_p):
/// the body follows their chord (a quarter turn of a coupled face moved alone inverts the
/// elements beside it). Not with contact or stabilisation, whose states follow u; false when
/// nothing moves or the start's tangent is singular (then the iterations start from the moved
/// DOFs).
bool NewtonIterations::predict() {
  if (ctx_.contact || ctx_.stabilization) return false;
  std::vector<double> delta(n_), product(n_, 0.0);
  double largest = 0.0;
  for (std::size_t d = 0; d < n_; ++d) largest = std::max(largest, std::abs(delta[d] = state_.u[d] - u_start_[d]));
  if (largest == 0.0 || n_eq_ == 0) return false;
  AssemblyRequest request;
  request.nlgeom = ctx_.nlgeom;
  request.delta_t = delta_t_;
  request.multiply = delta;
  request.product = product;
  AssemblyResult start = ctx_.assembler.assemble(u_start_, request, state_.f_int);
  if (!turned_inside_out(start, true).empty()) return false;
  // The increment's forces include those of the moved state, as they did when the first
  // iteration moved the boundary alone: a rigid motion then has a force scale to converge to.
  start.average_force = start.moved_average_force;
  const PerField q_moved = average_force(start, dofs_, state_.f_ext, 0.0, 0);
  increment_force_.update(q_moved, q_moved);
  for (std::size_t d = 0; d < n_; ++d) r_full_[d] = state_.f_ext[d] - state_.f_int[d] - product[d];
  r_.assign(n_eq_, 0.0);
  du_.assign(n_eq_, 0.0);
  ctx_.assembler.reduce(r_full_, r_);
  if (!std::all_of(r_.begin(), r_.end(), [](double v) { return std::isfinite(v); })) return false;
  if (!solver_.solve(ctx_.assembler.tangent(), false, r_, du_, n_eq_, ctx_.am.size, 1.0).solved) return false;
  apply_correction();
  return true;
}

bool NewtonIterations::limits_correction() const {
  return ctx_.contact && (ctx_.contact->has_augmented_lagrange() || ctx_.contact->has_friction());
}

/// Two contact laws whose kinks the tangent cannot see across, so that Newton cycles over them:
///  - augmented Lagrange at its 1000 k_e: a correction computed while nodes were open can drive
///    them deep into the master (a body held by a force sinks into a ring of open nodes), and
///    the force of that penetration throws the next iterate off again. A correction that takes
///    a node that was open deeper than the deepest node of its pair was is cut back to where
///    none is (ContactProblem::overshoot_fraction);
///  - friction: a slipping node's tangent has no stiffness along its slip, so a correction may
///    carry it across the stick zone to slip the other way, and the next one back: the slip
///    force flips each iteration. A correction that turns a slipping node's slip around is cut
///    back to where the node's trial slip is perpendicular to its slip before
///    (ContactProblem::slip_reversal_fraction): in 2D the middle of its stick zone, where the
///    next tangent is the stick one; in 3D the trial slip keeps its part across the old slip. A
///    slip reversed in earnest then follows in the next correction.
/// Neither cuts below 1 % of the correction. The cut iterate is evaluated again from the contact
/// state the iteration started from: the discarded one's status changes, flips and failures
/// never happened.
void NewtonIterations::limit_correction(int k, ContactIteration& contact, Residual& res) {
  if (!limits_correction()) return;
  const bool augmented = ctx_.contact->has_augmented_lagrange(), friction = ctx_.contact->has_friction();
  if (k > 0) {
    double fraction = 1.0;
    if (augmented) fraction = ctx_.contact->overshoot_fraction(penetrations_);
    if (friction) fraction = std::min(fraction, ctx_.contact->slip_reversal_fraction(slipping_trials_, state_.contact));
    if (fraction < 1.0) {
      scale_last_correction(fraction);
      // update_contact(k)'s count of severe iterations, for the evaluation that stands
      const auto severe = [&](const ContactIteration& c) { return c.status_changes > 0 || (k == 1 && status_changed_at_start_); };
      const bool counted = severe(contact);
      state_.contact = contact_before_;
      contact = ctx_.contact->update(state_.u, state_.contact, ctx_.assembler);
      out_.severe_iterations += (severe(contact) ? 1 : 0) - (counted ? 1 : 0);
      res = assemble_residual(k);
    }
  }
  if (augmented) penetrations_ = ctx_.contact->augmented_penetrations();
  if (friction) slipping_trials_ = ctx_.contact->slipping_trials(state_.contact);
}

/// u_k = u_{k−1} + factor Δu instead of u_{k−1} + Δu on the free DOFs. Contact multipliers
/// (a direct pair beside the augmented one) keep the whole correction: the update in between
/// may have renumbered them, and the next solve corrects them anyway.
void NewtonIterations::scale_last_correction(double factor) {
  for (std::int64_t d = 0; d < dofs_.n_dof(); ++d) {
    const std::int64_t eq = dofs_.equation(d);
    if (eq >= 0) state_.u[d] -= (1.0 - factor) * du_[eq];
  }
  dofs_.update_dependent(state_.u);
  if (ctx_.rotating_dofs) ctx_.rotating_dofs->relinearize(ctx_.am, state_.u);
  for (std::size_t e = 0; e < n_eq_; ++e) du_[e] *= factor;
}

/// u_{k+1} = u_k + Δu on the free DOFs, the dependents follow; contact multipliers too.
void NewtonIterations::apply_correction() {
  for (std::int64_t d = 0; d < dofs_.n_dof(); ++d) {
    const std::int64_t eq = dofs_.equation(d);
    if (eq >= 0) state_.u[d] += du_[eq];
  }
  dofs_.update_dependent(state_.u);
  if (ctx_.rotating_dofs) ctx_.rotating_dofs->relinearize(ctx_.am, state_.u);
  if (ctx_.contact) ctx_.contact->apply_correction(std::span<const double>(du_).subspan(n_eq_), state_.contact);
}

}  // namespace

NewtonOutcome solve_increment(NewtonContext& ctx, double t, IncrementState& state) {
  return NewtonIterations(ctx, t, state).run();
}

}  // namespace inpact::solver
