#include "newton.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace inpact::solver {

namespace {

/// Largest |r| over the equations, and the DOF it sits on. `r` is the reduced residual (one
/// entry per equation): a free DOF that masters *EQUATION dependents carries their residual
/// too, and only that sum vanishes at equilibrium.
std::pair<double, std::int64_t> largest_residual(const DofMap& dofs, std::span<const double> r) {
  double worst = 0.0;
  std::int64_t at = -1;
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d) {
    if (dofs.kind(d) != DofMap::Kind::Free) continue;
    const double v = std::abs(r[dofs.equation(d)]);
    if (!(v <= worst)) {  // also catches NaN
      worst = v;
      at = d;
    }
  }
  return {worst, at};
}

/// Abaqus's q: the spatial average of the force magnitudes over the model, element nodal forces
/// and applied loads together (without the applied loads the first iteration of a load-driven
/// increment would see no force at all).
/// Contact forces count too: an interference fit with no applied load has nothing else at its
/// first iteration, and measured against zero it would "converge" with the overclosure in place.
double average_force(const AssemblyResult& assembly, std::span<const double> f_ext, double contact_sum,
                     std::size_t contact_count) {
  double sum = assembly.average_force * static_cast<double>(assembly.n_force_entries) + contact_sum;
  std::size_t count = assembly.n_force_entries + contact_count;
  for (double f : f_ext)
    if (f != 0.0) {
      sum += std::abs(f);
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace

NewtonOutcome solve_increment(NewtonContext& ctx, double t, IncrementState& state) {
  const DofMap& dofs = ctx.assembler.dofs();
  const std::size_t n = static_cast<std::size_t>(dofs.n_dof());
  const std::size_t n_eq = static_cast<std::size_t>(dofs.n_equations());
  const std::vector<double> u_start = state.u;
  const std::vector<double> delta_t = ctx.conditions.temperature_change(t);

  // Impose the boundary conditions of time t, then iterate on the free DOFs.
  ctx.conditions.apply_prescribed(t, u_start, state.u);
  dofs.update_dependent(state.u);
  state.f_ext.assign(n, 0.0);
  ctx.conditions.external_force(t, state.f_ext);
  state.f_int.assign(n, 0.0);

  std::vector<double> r_full(n), r(n_eq), du(n_eq);
  std::vector<double> f_int_elements;  // f_int before the contact forces are added (for q)
  NewtonOutcome out;
  std::vector<double> history;  // largest residual per iteration
  LinearSolver* solver = &ctx.cholmod;
  double increment_force = 0.0;
  bool status_changed_at_start = false;

  // A new increment commits the friction history of the converged state it starts from.
  if (ctx.contact) ctx.contact->begin_attempt(state.contact, ctx.step_number, ctx.increment, u_start);
  for (int k = 0;; ++k) {
    // Contact search, projection and status at u_k (may resize the system: multipliers).
    ContactIteration contact;
    if (ctx.contact) {
      contact = ctx.contact->update(state.u, state.contact, ctx.assembler);
      // A severe discontinuity iteration: one in which a contact status changed. Changes found
      // before the first solve (the start of the increment) belong to the first iteration, so
      // SEVERE never exceeds TOTAL in the .sta.
      if (k == 0) status_changed_at_start = contact.status_changes > 0;
      else if (contact.status_changes > 0 || (k == 1 && status_changed_at_start)) ++out.severe_iterations;
    }
    const std::size_t n_sys = static_cast<std::size_t>(ctx.assembler.n_equations());
    r.assign(n_sys, 0.0);
    du.resize(n_sys, 0.0);
    AssemblyRequest request;
    // From the second pass on the residual alone decides convergence (a linear step converges
    // there); the tangent is assembled below only when another solve follows.
    request.tangent = k == 0 || ctx.contact != nullptr;
    request.nlgeom = ctx.nlgeom;
    request.delta_t = delta_t;
    // The first pass seldom converges (it would need no residual at all to start with): its
    // points are not kept, and should it converge the output computes them instead.
    request.points = ctx.keep_points && k > 0;
    const AssemblyResult asm_result = ctx.assembler.assemble(state.u, request, state.f_int);
    double contact_force_sum = 0.0;
    std::size_t contact_force_count = 0;
    if (ctx.contact) {
      f_int_elements.assign(state.f_int.begin(), state.f_int.end());
      ctx.contact->assemble(state.contact, state.f_int, ctx.assembler);
      for (std::size_t d = 0; d < n; ++d)
        if (const double fc = state.f_int[d] - f_int_elements[d]; fc != 0.0) {
          contact_force_sum += std::abs(fc);
          ++contact_force_count;
        }
    }
    for (std::size_t d = 0; d < n; ++d) r_full[d] = state.f_ext[d] - state.f_int[d];
    ctx.assembler.reduce(r_full, std::span(r).first(n_eq));
    if (ctx.contact) ctx.contact->constraint_residual(state.contact, std::span(r).subspan(n_eq));

    const auto [max_r, worst] = largest_residual(dofs, r);
    const double q_now = average_force(asm_result, state.f_ext, contact_force_sum, contact_force_count);
    out.max_residual = max_r;
    out.worst_dof = worst;
    out.iterations = k;
    // q̃: the force magnitude averaged over the step's converged increments and this one, where
    // this one counts with the largest element-and-load q of its iterations (a rigid-body move
    // ends with nearly no force at all; measured against its own round-off it would never
    // converge, against the forces its first iteration met, it does) or this iteration's q with
    // the contact forces, if larger. Contact forces count only in the iteration that has them:
    // a stiff penalty's first-iteration spike (an overclosure times 1000 k_e) would otherwise
    // loosen the test for the whole increment and accept a residual the size of a node's force.
    const double q_without_contact = ctx.contact ? average_force(asm_result, state.f_ext, 0.0, 0) : q_now;
    increment_force = std::max(increment_force, q_without_contact);
    out.average_force = std::max(increment_force, q_now);
    const double q = (ctx.force_sum + out.average_force) / (ctx.force_count + 1);
    double max_correction = 0.0;
    if (k > 0 && n_eq > 0)
      max_correction = *std::max_element(du.begin(), du.begin() + static_cast<std::ptrdiff_t>(n_eq),
                                         [](double a, double b) { return std::abs(a) < std::abs(b); });
    ctx.observer.iteration({ctx.step_number, ctx.increment, ctx.attempt, k, max_r, q > 0 ? max_r / q : 0.0,
                            std::abs(max_correction), worst});

    if (!std::isfinite(max_r)) {
      out.failure = "the residual is not a number (NaN or infinite)";
      return out;
    }
    if (asm_result.min_jacobian <= 0.0) {
      out.failure = fmt::format("element {} is turned inside out (Jacobian {:.3g})",
                                ctx.am.model->mesh.elements.labels[asm_result.min_jacobian_element],
                                asm_result.min_jacobian);
      return out;
    }
    if (!contact.failure.empty()) {
      out.failure = contact.failure;
      return out;
    }
    // Convergence (from the second pass on, a correction exists to judge).
    double max_du_inc = 0.0;
    for (std::size_t d = 0; d < n; ++d) max_du_inc = std::max(max_du_inc, std::abs(state.u[d] - u_start[d]));
    // Contact: no status change in this iteration, and the closed direct nodes on the surface
    // (|g| ≤ C_ε max|Δu|, C_ε = 1e-3: Abaqus's contact compatibility tolerance, *CONTROLS FIELD).
    const bool contact_ok = !contact.blocks_convergence && contact.max_gap_error <= 1e-3 * max_du_inc + 1e-14;
    const bool no_force = q <= 0.0;  // nothing loads the model: equilibrium is exact or nothing
    if (contact_ok && (no_force || max_r <= ctx.controls.linear_tolerance * q)) {
      out.converged = true;  // Abaqus accepts a residual this small without the correction test
      return out;
    }
    if (contact_ok && k > 0 && max_r <= ctx.controls.residual_tolerance * q &&
        std::abs(max_correction) <= ctx.controls.correction_tolerance * max_du_inc) {
      out.converged = true;
      return out;
    }
    // Severe discontinuity iterations count apart (Abaqus: I_S = 50 of them, I_C equilibrium
    // ones) and stay out of the divergence check.
    if (contact.status_changes == 0) history.push_back(max_r);
    if (k - out.severe_iterations >= ctx.controls.max_iterations || out.severe_iterations > kMaxSevereIterations) {
      out.failure = fmt::format("no convergence in {} iterations ({} with contact status changes)", k, out.severe_iterations);
      return out;
    }
    const std::size_t h = history.size();
    if (k >= ctx.controls.divergence_check_after && h >= 3 && history[h - 1] > history[h - 2] &&
        history[h - 2] > history[h - 3]) {
      out.failure = "the residual grows in two consecutive iterations (diverging)";
      return out;
    }

    // Solve K Δu = r; a tangent that is not positive definite (or a saddle-point system with
    // contact multipliers) goes to UMFPACK, and so does an unsymmetric one (friction), given
    // in full.
    if (!request.tangent) {  // same u: f_int comes out the same, now with K(u_k)
      request.tangent = true;
      request.points = false;  // the points kept above are at this u already
      ctx.assembler.assemble(state.u, request, state.f_int);
    }
    const SparseMatrix* tangent = &ctx.assembler.tangent();
    if (ctx.contact && ctx.contact->unsymmetric()) tangent = &ctx.contact->unsymmetric_tangent(*tangent);
    if (n_sys > n_eq || !tangent->upper_only) solver = &ctx.umfpack;
    FactorStatus status = solver->factorize(*tangent);
    if (status == FactorStatus::NotPositiveDefinite) {
      solver = &ctx.umfpack;
      status = solver->factorize(*tangent);
    }
    if (status == FactorStatus::Singular || status == FactorStatus::NotPositiveDefinite) {
      out.failure = "the stiffness matrix is singular: a part of the model is free to move as a rigid body "
                    "(check its boundary conditions)";
      out.singular = true;
      return out;
    }
    if (status == FactorStatus::OutOfMemory) {
      out.failure = "out of memory in the factorisation";
      return out;
    }
    solver->solve(r, du);
    // A rigid-body mode often factorises with round-off pivots instead of failing: its
    // correction is then absurdly large. Say what it is rather than iterate on it.
    double largest_du = 0.0;  // over the displacement equations (not the contact multipliers)
    bool finite = true;
    for (std::size_t i = 0; i < n_eq; ++i) {
      finite = finite && std::isfinite(du[i]);
      largest_du = std::max(largest_du, std::abs(du[i]));
    }
    if (!finite || largest_du > 1e8 * ctx.am.size) {
      out.failure = fmt::format("the stiffness matrix is singular: a part of the model is free to move as a rigid "
                                "body (check its boundary conditions); the correction was {:.3g}, {:.3g} times the "
                                "model size", largest_du, largest_du / ctx.am.size);
      out.singular = true;
      return out;
    }
    for (std::int64_t d = 0; d < dofs.n_dof(); ++d) {
      const std::int64_t eq = dofs.equation(d);
      if (eq >= 0) state.u[d] += du[eq];
    }
    dofs.update_dependent(state.u);
    if (ctx.contact) ctx.contact->apply_correction(std::span<const double>(du).subspan(n_eq), state.contact);
  }
}

}  // namespace inpact::solver
