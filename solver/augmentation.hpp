#pragma once
/// The augmentation level of one increment attempt, between the increment and Newton: Newton to
/// convergence, then, for augmented-Lagrange pairs, while a penetration exceeds its tolerance,
///   λ ← ⟨λ + k (h + c0)⟩  and Newton again from the converged state,
/// at most I_A^c times (*CONTROLS, PARAMETERS=TIME INCREMENTATION, field 13; default 50).
/// USER ADAPTIVE pairs start the first increment with a reduced penalty stiffness.
#include "newton.hpp"

namespace inpact::solver {

/// Runs the attempt to step time `t`; `augmentations` receives how many were made. The outcome
/// sums the iterations of every Newton pass.
NewtonOutcome solve_with_augmentations(NewtonContext& ctx, double t, IncrementState& state, int& augmentations);

}  // namespace inpact::solver
