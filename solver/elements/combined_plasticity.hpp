#pragma once
/// Mises plasticity with nonlinear kinematic hardening (Chaboche; Abaqus's *PLASTIC,
/// HARDENING=COMBINED with DATATYPE=PARAMETERS) at small strain:
///
///   f = q(σ − α) − σ⁰(ε̄ᵖ),  α = Σ_k α_k,  α̇_k = C_k (1/σ⁰)(σ − α) ε̄̇ᵖ − γ_k α_k ε̄̇ᵖ,
///
/// σ⁰ the size of the yield surface (*CYCLIC HARDENING: a table, or σ|0 + Q∞(1 − e^{−bε̄ᵖ});
/// constant σ|0 without it). On the yield surface (σ − α)/σ⁰ = 2/3 n with n = 3/2 dev(σ − α)/q,
/// so α̇_k = 2/3 C_k n ε̄̇ᵖ − γ_k α_k ε̄̇ᵖ (Abaqus's form, with deviatoric backstresses).
///
/// Integration: backward Euler. With a_k = 1/(1 + γ_k Δγ) the backstresses are
/// α_k = a_k (α_k,n + 2/3 C_k Δγ n), and σ − α is parallel to η(Δγ) = dev σ_tr − Σ a_k α_k,n,
/// so the return is the one scalar equation
///
///   r(Δγ) = q(η) − (3G + Σ C_k a_k) Δγ − σ⁰(ε̄ᵖ_n + Δγ) = 0,
///
/// solved by Newton's method safeguarded by bisection (to 1e-12 of σ⁰). With all γ_k = 0 it is
/// the linear Prager–Ziegler law. The consistent tangent is unsymmetric where γ_k > 0 (the
/// direction of η turns with Δγ); inpact's element systems are symmetric, so the material
/// returns its symmetric part — exact for γ_k = 0, and Newton then converges linearly, fast
/// in practice, where γ_k > 0 (Abaqus/Standard, too, uses a symmetric solver unless UNSYMM).
///
/// State per point: εᵖ (6, engineering shear), ε̄ᵖ, then α_k (6 tensor components each).
/// Families: 3D, plane strain and axisymmetric (plane stress is refused by the analysis setup).
#include <vector>

#include "material.hpp"

namespace inpact::solver::elements {

struct CombinedHardening {
  struct Backstress {
    double modulus = 0.0;   ///< C_k
    double recovery = 0.0;  ///< γ_k
  };
  std::vector<Backstress> backstresses;
  /// σ⁰(ε̄ᵖ): a table (points from ε̄ᵖ = 0, piecewise linear, constant beyond), or, when
  /// `table_strain` is empty, σ|0 + Q∞ (1 − exp(−b ε̄ᵖ)).
  std::vector<double> table_strain, table_stress;
  double initial = 0.0, saturation = 0.0, rate = 0.0;
};

class CombinedPlasticity final : public Material {
 public:
  CombinedPlasticity(const ElasticConstants& constants, CombinedHardening hardening);

  static constexpr std::size_t kPlasticStrain = 0, kEquivalent = 6, kBackstress = 7;

  std::size_t state_size() const override { return kBackstress + 6 * hardening_.backstresses.size(); }
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return constants_; }
  void plastic_output(std::span<const double> state, PointResult& out) const override;
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override;
  /// Δε̄ᵖ > 50 σ⁰(0)/E, as for MisesPlasticity.
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override;

  /// σ⁰(ε̄ᵖ) and its slope.
  double yield_size(double eq, double* slope = nullptr) const;

 private:
  struct Return;
  Return solve_return(const Vec6& s_trial, std::span<const double> committed) const;
  void consistent_tangent(const Return& r, Mat6& tangent) const;

  ElasticConstants constants_;
  CombinedHardening hardening_;
  double shear_ = 0.0, bulk_ = 0.0;
  Mat6 D_;
};

}  // namespace inpact::solver::elements
