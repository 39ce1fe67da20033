#pragma once
/// Mises plasticity with nonlinear kinematic hardening (Chaboche; Abaqus's *PLASTIC,
/// HARDENING=COMBINED, with C_k, γ_k given or fitted to half-cycle data, and linear KINEMATIC
/// hardening that depends on temperature) at small strain:
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
/// Temperature dependence (Abaqus): every parameter is given at a list of temperatures and
/// interpolated linearly between them (constant outside). Abaqus's backstress law then has the
/// extra term (1/C_k)(dC_k/dT) α_k Ṫ; with β_k = α_k / C_k it drops out exactly,
/// β̇_k = 2/3 n ε̄̇ᵖ − γ_k β_k ε̄̇ᵖ, so the state keeps β_k and α_k = C_k(T) β_k at the point's
/// current temperature. Without temperature dependence this is the same law.
///
/// State per point: εᵖ (6, engineering shear), ε̄ᵖ, then β_k (6 tensor components each).
/// Families: 3D, plane strain and axisymmetric (plane stress is refused by the analysis setup).
#include <array>
#include <vector>

#include "material.hpp"
#include "temperature_bracket.hpp"

namespace inpact::solver::elements {

/// The parameters at one temperature.
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
  /// One set of parameters per entry of the increasing `temperatures`, all with the same number
  /// of backstresses and the same kind of σ⁰ (table or exponential).
  CombinedPlasticity(const ElasticConstants& constants, std::vector<CombinedHardening> sets,
                     std::vector<double> temperatures);

  static constexpr std::size_t kPlasticStrain = 0, kEquivalent = 6, kBackstress = 7;
  static constexpr std::size_t kMaxBackstresses = 10;  // Abaqus's limit

  std::size_t state_size() const override { return kBackstress + 6 * backstress_count(); }
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return constants_; }
  void plastic_output(std::span<const double> state, PointResult& out) const override;
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override;
  /// Δε̄ᵖ > 50 σ⁰(0)/E (the lowest σ⁰(0) over the temperatures), as for MisesPlasticity.
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override;
  bool temperature_dependent() const override { return temperatures_.size() > 1; }

  std::size_t backstress_count() const { return sets_.front().backstresses.size(); }
  /// σ⁰(ε̄ᵖ, T) and its slope in ε̄ᵖ.
  double yield_size(double eq, double* slope = nullptr, double temperature = 0.0) const;
  /// C_k and γ_k at `temperature`.
  CombinedHardening::Backstress backstress(std::size_t k, double temperature = 0.0) const;

 private:
  struct Return;
  /// The parameters at one point's temperature.
  struct AtTemperature {
    TemperatureBracket bracket;
    std::array<CombinedHardening::Backstress, kMaxBackstresses> backstresses{};
  };
  AtTemperature at(double temperature) const;
  double yield_size(const AtTemperature& p, double eq, double* slope) const;
  Return solve_return(const AtTemperature& p, const Vec6& s_trial, std::span<const Vec6> alpha_n,
                      double eq_n) const;
  void consistent_tangent(const AtTemperature& p, const Return& r, Mat6& tangent) const;

  ElasticConstants constants_;
  std::vector<CombinedHardening> sets_;
  std::vector<double> temperatures_;
  double shear_ = 0.0, bulk_ = 0.0;
  double first_yield_ = 0.0;
  Mat6 D_;
};

}  // namespace inpact::solver::elements
