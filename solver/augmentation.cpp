#include "augmentation.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace inpact::solver {

NewtonOutcome solve_with_augmentations(NewtonContext& ctx, double t, IncrementState& state, int& augmentations) {
  NewtonOutcome total;
  if (ctx.contact) ctx.contact->set_step_time(ctx.conditions, t);  // *CHANGE FRICTION ramps
  // USER ADAPTIVE: the first increment's early iterations with a reduced penalty stiffness, to
  // find the contact status; then its final iterations (below) with the full stiffness.
  if (ctx.contact && ctx.contact->has_user_adaptive() && ctx.at.increment == 1) {
    ctx.contact->set_user_adaptive_scale(kUserAdaptiveScale);
    total = solve_increment(ctx, t, state);
    ctx.contact->set_user_adaptive_scale(1.0);
    if (!total.converged) return total;
  }
  for (augmentations = 0;; ++augmentations) {
    NewtonOutcome outcome = solve_increment(ctx, t, state);
    outcome.iterations += total.iterations;
    outcome.severe_iterations += total.severe_iterations;
    for (std::size_t f = 0; f < kFields; ++f)
      outcome.average_force[f] = std::max(outcome.average_force[f], total.average_force[f]);
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

}  // namespace inpact::solver
