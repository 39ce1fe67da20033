#pragma once
/// Plane stress for a material with state that has only a 3D law (finite-strain plasticity,
/// combined hardening): the thickness strain e33 (ε33, or E33 with NLGEOM, where F33 =
/// √(1 + 2 E33)) is found at each point by a local Newton iteration until the 3D law's
/// S33 = 0 (to 1e-12 of the stress or of 1e-3 E; with NLGEOM in ln λ3), started from the last converged
/// e33, which the state keeps after the law's own. The tangent is the 3D one condensed for S33 = 0,
/// D − D·₃ D₃· / D₃₃ — the exact derivative of the converged plane-stress point when the 3D
/// tangent is exact — with zero rows for 33, 13, 23 as the plane stress elements expect. A local
/// iteration that does not converge gives NaN stresses, so the increment is cut back.
///
/// The transverse shears (13, 23) are zero in a plane stress element; S13 = S23 = 0 follows for
/// an isotropic law, so only e33 is solved for.
#include <memory>

#include "material.hpp"

namespace inpact::solver::elements {

class PlaneStressCondensation final : public Material {
 public:
  explicit PlaneStressCondensation(std::shared_ptr<const Material> law_3d);

  std::size_t state_size() const override { return law_->state_size() + 1; }
  void initial_state(std::span<double> state) const override;
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override;
  const ElasticConstants& elastic() const override { return law_->elastic(); }
  void plastic_output(std::span<const double> state, PointResult& out) const override;
  bool set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const override;
  bool increment_too_large(std::span<const double> committed, std::span<const double> trial) const override;
  /// e33 of the state (the trial state of the last update()).
  double plane_stress_thickness_strain(const Vec3& position, const Vec6& strain, const Vec6& stress,
                                       double thermal_strain, double temperature,
                                       std::span<const double> state) const override;
  bool temperature_dependent() const override { return law_->temperature_dependent(); }

 private:
  std::span<const double> inner(std::span<const double> state) const { return state.first(law_->state_size()); }
  std::span<double> inner(std::span<double> state) const { return state.first(law_->state_size()); }

  std::shared_ptr<const Material> law_;
};

}  // namespace inpact::solver::elements
