#pragma once
/// Hyperelasticity (*HYPERELASTIC): strain energies of the right Cauchy–Green tensor C = FᵀF,
/// split into an isochoric part of the deviatoric invariants and a volumetric part of J,
///
///   W = W_iso(Ī1, Ī2) + U(J),   Ī1 = J^(−2/3) I1,  Ī2 = J^(−4/3) I2,  J = det F,
///
/// as Abaqus writes them (no thermal expansion: J_el = J). Each energy is a pure kernel:
/// C in, the second Piola–Kirchhoff stress S = 2 ∂W/∂C and the material tangent
/// ℂ = 4 ∂²W/∂C∂C out (Voigt 11 22 33 12 13 23; ℂ acts on engineering shear strains, so
/// dS = ℂ dE).
///
/// Invariant energies (InvariantEnergy): the isochoric part is a sum of terms
/// c (Ī1 − a)^i (Ī2 − 3)^j — POLYNOMIAL (a = 3, i + j ≤ N), its special cases NEO HOOKE (C10),
/// MOONEY-RIVLIN (C10, C01), REDUCED POLYNOMIAL and YEOH (j = 0), and ARRUDA-BOYCE
/// (a = 0, the five terms of the inverse-Langevin series,
///   W = μ Σ_k c_k / λm^(2k−2) (Ī1^k − 3^k),  c = 1/2, 1/20, 11/1050, 19/7000, 519/673750).
/// The stress and tangent go through the invariants I1, I2, J of C by the chain rule:
///   S = 2 [W₁ I + W₂ (I1 I − C) + W_J ½ J C⁻¹]
///   ℂ = 4 [Σ W_ab ∂a ⊗ ∂b + W₂ (I ⊗ I − 𝕀) + W_J (¼ J C⁻¹ ⊗ C⁻¹ − ½ J 𝕀_C⁻¹)]
/// with W_a the derivatives of W(J^(−2/3) I1, J^(−4/3) I2, J) in (I1, I2, J),
/// 𝕀_A,ijkl = ½ (A_ik A_jl + A_il A_jk).
///
/// Volumetric parts: U = Σ_i (1/D_i)(J − 1)^(2i) (POLYNOMIAL family, OGDEN; a D_i of zero drops
/// its term), and U = (1/D)((J² − 1)/2 − ln J) (ARRUDA-BOYCE). Initial moduli: μ0 from the
/// isochoric part, K0 = 2/D1.
///
/// OGDEN (OgdenEnergy): W = Σ_p 2μ_p/α_p² (λ̄1^α_p + λ̄2^α_p + λ̄3^α_p − 3) + U(J), the λ̄ the
/// deviatoric principal stretches; stress and tangent from the spectral form of C.
#include <memory>
#include <vector>

#include "material.hpp"

namespace inpact::solver::elements {

/// A strain energy W(C).
class StrainEnergy {
 public:
  virtual ~StrainEnergy() = default;
  virtual double energy(const Eigen::Matrix3d& C) const = 0;
  /// S and ℂ at C (det C > 0).
  virtual void stress_tangent(const Eigen::Matrix3d& C, Vec6& S, Mat6& tangent) const = 0;
  virtual double initial_shear_modulus() const = 0;
  /// K0 = 2/D1 (infinite for an incompressible energy, which the caller never builds).
  virtual double initial_bulk_modulus() const = 0;
};

/// U(J): Σ (1/D_i)(J − 1)^(2i), or Arruda–Boyce's (1/D)((J² − 1)/2 − ln J).
struct VolumetricEnergy {
  enum class Form { Polynomial, ArrudaBoyce };
  Form form = Form::Polynomial;
  std::vector<double> d;  ///< D1, D2, ... (zeros drop their terms)
  double value(double J) const;
  double first(double J) const;   ///< dU/dJ
  double second(double J) const;  ///< d²U/dJ²
};

/// A term c (Ī1 − a)^i (Ī2 − 3)^j of the isochoric energy.
struct InvariantTerm {
  int i = 0, j = 0;
  double c = 0.0;
};

class InvariantEnergy final : public StrainEnergy {
 public:
  /// offset_i1: the a of the terms (3 for the polynomial forms, 0 for Arruda–Boyce).
  InvariantEnergy(std::vector<InvariantTerm> terms, double offset_i1, VolumetricEnergy volumetric);

  /// C10, C01 (Mooney–Rivlin; C01 = 0 is neo-Hooke).
  static InvariantEnergy polynomial(const std::vector<double>& cij, int order, const std::vector<double>& d);
  /// C10, C20, C30 (REDUCED POLYNOMIAL, YEOH).
  static InvariantEnergy reduced_polynomial(const std::vector<double>& ci0, const std::vector<double>& d);
  static InvariantEnergy arruda_boyce(double mu, double lambda_m, double d);

  double energy(const Eigen::Matrix3d& C) const override;
  void stress_tangent(const Eigen::Matrix3d& C, Vec6& S, Mat6& tangent) const override;
  double initial_shear_modulus() const override;
  double initial_bulk_modulus() const override;

 private:
  struct Derivatives {
    double w1 = 0, w2 = 0, w11 = 0, w12 = 0, w22 = 0;  ///< in Ī1, Ī2
  };
  Derivatives isochoric(double i1b, double i2b) const;

  std::vector<InvariantTerm> terms_;
  double offset_i1_ = 3.0;
  VolumetricEnergy volumetric_;
};

class OgdenEnergy final : public StrainEnergy {
 public:
  OgdenEnergy(std::vector<double> mu, std::vector<double> alpha, std::vector<double> d);

  double energy(const Eigen::Matrix3d& C) const override;
  void stress_tangent(const Eigen::Matrix3d& C, Vec6& S, Mat6& tangent) const override;
  double initial_shear_modulus() const override;
  double initial_bulk_modulus() const override;

 private:
  /// Σ_p 2μ_p/α_p² Σ_a λ̄_a^α_p as a function of the principal stretches squared.
  double isochoric(const Eigen::Vector3d& lambda2) const;
  std::vector<double> mu_, alpha_;
  VolumetricEnergy volumetric_;
};

/// The material of an integration point with a hyperelastic energy: F in, S and ℂ out
/// (requires NLGEOM; the strain passed is ignored, C = FᵀF). Stateless. det F ≤ 0 gives NaN
/// stresses (the increment is then cut back).
/// Plane stress: the thickness stretch λ3 is the material's, C33 = λ3² found by a local Newton
/// iteration until S33 = 0 (to 1e-12 of the stress), the tangent condensed for S33 = 0,
/// D − D·₃ D₃· / D₃₃ (the exact derivative of the converged state), zero rows for 33, 13, 23.
class Hyperelastic final : public Material {
 public:
  explicit Hyperelastic(std::shared_ptr<const StrainEnergy> energy, bool plane_stress = false);

  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  /// Plane stress: E33 = (λ3² − 1)/2 of the state update() converges to.
  double plane_stress_thickness_strain(const Vec3& position, const Vec6& strain, const Vec6& stress,
                                       double thermal_strain, double temperature,
                                       std::span<const double> state) const override;
  /// Small-strain constants of the initial moduli μ0, K0 (hourglass control, output).
  const ElasticConstants& elastic() const override { return constants_; }
  const StrainEnergy& energy() const { return *energy_; }

 private:
  /// C33 with S33 = 0 for the in-plane C (its 33 entry the start); writes S and D there.
  double thickness_stretch_squared(Eigen::Matrix3d C, Vec6& stress, Mat6& tangent) const;

  std::shared_ptr<const StrainEnergy> energy_;
  ElasticConstants constants_;
  bool plane_stress_ = false;
};

}  // namespace inpact::solver::elements
