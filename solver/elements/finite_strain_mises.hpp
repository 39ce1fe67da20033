#pragma once
/// Mises plasticity at finite strain (NLGEOM), the exponential-map model of Simo (1992; also
/// de Souza Neto, Perić & Owen, Computational Methods for Plasticity, ch. 14):
///
///   F = Fᵉ Fᵖ,  εᵉ = ½ ln bᵉ (bᵉ = Fᵉ Fᵉᵀ),  τ = D εᵉ (Hencky: the small-strain D on
///   logarithmic elastic strains, τ the Kirchhoff stress),  f = q(τ) − σ_y(ε̄ᵖ).
///
/// One increment: the trial elastic strain εᵉ_tr = ½ ln(F Cᵖ⁻¹_n Fᵀ) goes through the very
/// radial return of the small-strain law (MisesPlasticity), which in logarithmic strains is
/// exact for this model; then bᵉ = exp(2εᵉ), Cᵖ⁻¹ = F⁻¹ bᵉ F⁻ᵀ and S = F⁻¹ τ F⁻ᵀ for the
/// total-Lagrangian element. Plastic flow is isochoric, so J = det F = det Fᵉ.
///
/// Where Abaqus differs: Abaqus integrates a hypoelastic Jaumann rate and writes the yield
/// function in the Cauchy stress σ = τ/J. For metals J − 1 = (1 − 2ν) tr εᵉ is of the order of
/// σ_y/E, so yield stresses differ by a factor of about 1 + (1 − 2ν)σ_y/E (6e-4 for steel);
/// the Kirchhoff form has a potential, hence a symmetric consistent tangent.
///
/// Tangent: exact, ∂S/∂E column by column for δE, through dF = F⁻ᵀ δE (so that sym(Fᵀ dF) = δE),
/// the derivative of the tensor logarithm by the Daleckii–Krein formula in the eigenbasis of
/// bᵉ_tr (divided differences of ln, the limit 1/λ for equal eigenvalues) and the small-strain
/// return's consistent tangent.
///
/// State per point: PE (6, engineering shear; = LE − εᵉ, the logarithmic plastic strain), ε̄ᵖ,
/// Cᵖ⁻¹ (6 tensor components). The first seven are MisesPlasticity's layout, so a step without
/// NLGEOM runs the small-strain law on them and sets Cᵖ⁻¹ = exp(−2εᵖ). Isotropic hardening only;
/// 3D, plane strain and axisymmetric elements (not plane stress).
#include "mises_plasticity.hpp"

namespace inpact::solver::elements {

class FiniteStrainMises final : public Material {
 public:
  /// Throws std::invalid_argument for kinematic hardening (no finite-strain backstress here).
  FiniteStrainMises(const ElasticConstants& constants, MisesHardening hardening);

  static constexpr std::size_t kPlasticStrain = 0;  ///< PE, 6 values
  static constexpr std::size_t kEquivalent = 6;     ///< ε̄ᵖ
  static constexpr std::size_t kInversePlasticCauchyGreen = 7;  ///< Cᵖ⁻¹, 6 values

  std::size_t state_size() const override { return 13; }
  void initial_state(std::span<double> state) const override;
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return small_.elastic(); }
  void plastic_output(std::span<const double> state, PointResult& out) const override;
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override;
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override;
  bool temperature_dependent() const override { return small_.temperature_dependent(); }

 private:
  const Mat6& update_finite(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                            Mat6& scratch) const;
  const Mat6& update_small(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                           Mat6& scratch) const;

  MisesPlasticity small_;  ///< the return in (logarithmic) strain space
};

}  // namespace inpact::solver::elements
