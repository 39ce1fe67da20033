#pragma once
/// A small-strain elastic–plastic law at finite strain (NLGEOM) through the Lagrangian
/// logarithmic strain (Miehe, Apel & Lambrecht, CMAME 191 (2002) 5383; Code_Aster's GDEF_LOG):
///
///   E_log = ½ ln C (C = FᵀF),  T, 𝔻 = the small-strain law at E_log (additive plastic strain),
///   S = P : T,  P = ∂E_log/∂E  (T is the stress work-conjugate to E_log).
///
/// The small law runs unchanged, state and all, so kinematic and combined hardening (whose
/// backstress needs a frame) live in the reference configuration and are objective by
/// construction: a superposed rotation leaves C, hence everything, unchanged. On paths with
/// fixed principal axes (a bar, a thick tube) T is the Kirchhoff stress and the model equals the
/// exponential-map one of FiniteStrainMises; it differs from Abaqus's hypoelastic Jaumann-rate
/// model on rotating paths, like FiniteStrainMises does.
///
/// Tangent, exact: dS = P : 𝔻 : P : dE + D²ln(C)[T, 2dE] with the first and second
/// Daleckii–Krein derivatives of the tensor logarithm in the eigenbasis of C
/// (log_divided_difference.hpp). PE is the Lagrangian logarithmic plastic strain, PEEQ the law's.
/// 3D, plane strain and axisymmetric elements (plane stress: not supported).
#include <memory>

#include "material.hpp"

namespace inpact::solver::elements {

class LogStrainPlasticity final : public Material {
 public:
  explicit LogStrainPlasticity(std::shared_ptr<const Material> small_strain_law);

  std::size_t state_size() const override { return small_->state_size(); }
  void initial_state(std::span<double> state) const override { small_->initial_state(state); }
  /// Without NLGEOM (a step of a model whose other steps have it) the small law itself.
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return small_->elastic(); }
  void plastic_output(std::span<const double> state, PointResult& out) const override {
    small_->plastic_output(state, out);
  }
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override {
    return small_->set_plastic_strain(state, plastic_strain);
  }
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override {
    return small_->increment_too_large(committed, trial);
  }
  bool temperature_dependent() const override { return small_->temperature_dependent(); }

 private:
  std::shared_ptr<const Material> small_;
};

}  // namespace inpact::solver::elements
