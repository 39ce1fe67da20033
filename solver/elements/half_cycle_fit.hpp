#pragma once
/// Abaqus's HARDENING=COMBINED, DATATYPE=HALF CYCLE: the backstress of one nonlinear kinematic
/// component fitted to the first half cycle of a uniaxial test. Integrated over a monotonic
/// half cycle from ε̄ᵖ_1 = 0, the law α̇ = C (σ − α)/σ⁰ ε̄̇ᵖ − γ α ε̄̇ᵖ gives
///
///   α(ε̄ᵖ) = C/γ (1 − e^{−γ ε̄ᵖ}) + α_1 e^{−γ ε̄ᵖ}   (α = C ε̄ᵖ + α_1 for γ = 0),
///
/// and each data row gives α_i = σ_i − σ⁰(ε̄ᵖ_i), σ⁰ the size of the yield surface (from
/// *CYCLIC HARDENING, or the first row's stress without it). C and γ are the least-squares
/// fit of that curve through the rows: for a given γ the best C is linear least squares, and
/// γ ≥ 0 minimises the remaining sum of squares (a scan in log γ, then golden sections).
/// Two rows fix only the slope: γ = 0, linear kinematic hardening.
#include <span>

namespace inpact::solver::elements {

struct HalfCycleFit {
  double modulus = 0.0;   ///< C
  double recovery = 0.0;  ///< γ
  double rms = 0.0;       ///< root mean square of α_i − α(ε̄ᵖ_i) over the rows
};

/// The fit through (plastic_strain[i], backstress[i]); plastic_strain[0] = 0, increasing, at
/// least two rows. C may come out negative (softening data): the caller refuses it.
HalfCycleFit fit_half_cycle(std::span<const double> plastic_strain, std::span<const double> backstress);

}  // namespace inpact::solver::elements
