#pragma once
/// Mises (J2) plasticity at small strain: isotropic elasticity, the yield function
///
///   f = q(σ − α) − σ_y(ε̄ᵖ),   q(ξ) = √(3/2 dev ξ : dev ξ),
///
/// associated flow ε̇ᵖ = ε̄̇ᵖ · 3/2 dev(σ − α)/q, and either
///  - isotropic hardening: σ_y(ε̄ᵖ) piecewise linear through the table points, constant beyond
///    the last one (one point: perfectly plastic), α = 0; or
///  - linear kinematic hardening: σ_y = σ⁰ (the first point), α̇ = 2/3 C ε̇ᵖ with C the slope of
///    the first two points (Prager; for a Mises surface and a deviatoric backstress this is
///    Abaqus's linear Ziegler law α̇ = C/σ⁰ (σ − α) ε̄̇ᵖ, since dev(σ − α) = 2/3 σ⁰ · 3/2 n).
///
/// Integration: backward Euler, the radial return (Simo & Hughes, Computational Inelasticity,
/// §3.3): the trial stress σ_tr = D(ε − εᵖ_n − ε_th), and on yield the one scalar equation
/// q_tr − 3GΔγ − H_kin Δγ − σ_y(ε̄ᵖ_n + Δγ) = 0, solved exactly segment by segment of the
/// piecewise-linear table (no iteration, no tolerance). Tangent: the consistent (algorithmic)
/// one, C = K 1⊗1 + 2Gθ I_dev − 2G θ̄ n⊗n, θ = 1 − 3GΔγ/q_tr, θ̄ = 1/(1 + H/3G) − (1 − θ),
/// H the slope at the returned point (+ C kinematic).
///
/// State per point (state_size()): εᵖ (6, Voigt 11 22 33 12 13 23, engineering shear), ε̄ᵖ,
/// with kinematic hardening α (6, tensor components), and in plane stress the thickness strain
/// ε33 last. Families: 3D, plane strain and axisymmetric take the full 3D return (ε33 = 0 resp.
/// the hoop strain comes in the strain). Plane stress: the same 3D return inside a local Newton
/// iteration on ε33 until σ33 = 0 (to 1e-12 of the stress), started from the last converged ε33;
/// the tangent is the 3D consistent one condensed for σ33 = 0, C − C·₃ C₃· / C₃₃ (exact: the
/// derivative of the converged plane-stress return), with zero rows for 33, 13, 23 as
/// elasticity_matrix has them. A local iteration that does not converge gives NaN stresses, so
/// the increment is cut back.
#include <span>
#include <vector>

#include "material.hpp"
#include "model/material.hpp"

namespace inpact::solver::elements {

/// The hardening data of *PLASTIC: points (ε̄ᵖ, σ_y), the first at ε̄ᵖ = 0, strains increasing.
/// Temperature dependence: `yield_stress` holds one row of σ_y on the `plastic_strain` grid per
/// entry of `temperatures` (row-major); at a point's temperature the rows are interpolated
/// linearly, constant outside their range. Empty `temperatures`: one row, no dependence.
struct MisesHardening {
  bool kinematic = false;
  std::vector<double> plastic_strain;
  std::vector<double> yield_stress;
  std::vector<double> temperatures = {};
};

/// *PLASTIC's isotropic rows (blocks of one temperature, each from ε̄ᵖ = 0) as MisesHardening:
/// one strain grid, the union of the blocks' strains, with every block's curve sampled on it.
/// The sampling is exact (a curve is linear between its own points and constant beyond its
/// last), so interpolating the rows in temperature is the bilinear interpolation of the data.
MisesHardening isotropic_hardening(std::span<const model::Plastic::Point> rows);

/// Where the state of a point keeps what.
struct MisesStateLayout {
  static constexpr std::size_t plastic_strain = 0;  ///< 6 values
  static constexpr std::size_t equivalent = 6;      ///< ε̄ᵖ
  static constexpr std::size_t backstress = 7;      ///< 6 values, kinematic hardening only
  /// Plane stress: the thickness strain ε33, after the others (7, or 13 with backstress).
  static std::size_t thickness(bool kinematic) { return kinematic ? 13 : 7; }
};

class MisesPlasticity final : public Material {
 public:
  MisesPlasticity(const ElasticConstants& constants, MisesHardening hardening,
                  model::ElementFamily family = model::ElementFamily::Solid3D);

  std::size_t state_size() const override {
    return MisesStateLayout::thickness(hardening_.kinematic) + (plane_stress_ ? 1 : 0);
  }
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return constants_; }
  void plastic_output(std::span<const double> state, PointResult& out) const override;
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override;
  /// Δε̄ᵖ > 50 σ_y⁰/E: Abaqus/Standard's limit ("the strain increment has exceeded fifty times
  /// the strain to cause first yield", then a cutback), which keeps the return's one backward
  /// Euler step from spanning a large part of a nonradial path.
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override;

  bool temperature_dependent() const override { return hardening_.temperatures.size() > 1; }

  /// σ_y(ε̄ᵖ, T) of the isotropic table (σ⁰ with kinematic hardening).
  double yield_stress(double equivalent_plastic_strain, double temperature = 0.0) const;
  /// The 3D elasticity matrix.
  const Mat6& D() const { return D_; }

 private:
  struct Return {
    double dgamma = 0.0;  ///< Δε̄ᵖ
    double slope = 0.0;   ///< dσ_y/dε̄ᵖ + C at the returned point
  };
  /// σ_y on the strain grid at `temperature`: the table's one row, or the rows interpolated
  /// into `buffer`.
  std::span<const double> curve_at(double temperature, std::vector<double>& buffer) const;
  Return solve_return(double q_trial, double eq_n, std::span<const double> curve) const;
  /// The 3D return at `strain` (ε33 included) from point.committed into point.trial.
  const Mat6& update_3d(const Vec6& strain, const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                        Mat6& scratch) const;
  const Mat6& update_plane_stress(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                  Mat6& scratch) const;

  ElasticConstants constants_;
  MisesHardening hardening_;
  double shear_ = 0.0, bulk_ = 0.0;
  double kinematic_modulus_ = 0.0;  ///< C (0 without kinematic hardening)
  double first_yield_ = 0.0;        ///< the lowest initial yield stress over the temperatures
  bool plane_stress_ = false;
  Mat6 D_;
};

}  // namespace inpact::solver::elements
