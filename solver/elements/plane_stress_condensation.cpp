#include "plane_stress_condensation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace inpact::solver::elements {

PlaneStressCondensation::PlaneStressCondensation(std::shared_ptr<const Material> law_3d) : law_(std::move(law_3d)) {}

void PlaneStressCondensation::initial_state(std::span<double> state) const {
  law_->initial_state(inner(state));
  state.back() = 0.0;
}

const Mat6& PlaneStressCondensation::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                            Mat6& scratch) const {
  const PointHistory own{inner(point.committed), inner(point.trial)};
  Eigen::Matrix3d F = in.F;
  F(0, 2) = F(1, 2) = F(2, 0) = F(2, 1) = 0.0;
  Vec6 strain = in.strain;
  strain(4) = strain(5) = 0.0;
  // The unknown: ε33, or with NLGEOM κ = ln λ3 (E33 = (e^{2κ} − 1)/2), in which the Kirchhoff
  // stress τ33 = λ3² S33 is close to linear: Newton then converges from far away (a point whose
  // in-plane stretch doubles in one iteration), where a step in E33 could take λ3² below zero.
  const double committed = point.committed.back();
  double unknown = in.nlgeom ? 0.5 * std::log1p(2 * committed) : committed, previous = unknown;
  Mat6 full;
  for (int it = 0; it < 50; ++it) {
    const double l2 = in.nlgeom ? std::exp(2 * unknown) : 1.0;  // λ3²
    strain(2) = in.nlgeom ? 0.5 * (l2 - 1) : unknown;
    F(2, 2) = in.nlgeom ? std::exp(unknown) : in.F(2, 2);
    full = law_->update({F, strain, in.thermal_strain, in.position, in.nlgeom, in.temperature}, own, stress, scratch);
    // Converged to 1e-12 of the stress, of 1e-3 E near zero stress (a finite-strain law
    // computes S to about 1e-16 E through its logarithms), or where Newton's step is round-off.
    const double scale = std::max(stress.cwiseAbs().maxCoeff(), 1e-3 * elastic().youngs_modulus);
    if (!std::isfinite(stress(2)) || !std::isfinite(full(2, 2))) break;
    const double last_step = it == 0 ? 1.0 : std::abs(unknown - previous);
    if (std::abs(stress(2)) <= 1e-12 * scale || last_step <= 1e-15 * (1 + std::abs(unknown))) {
      point.trial.back() = strain(2);
      scratch.setZero();  // dS_ij = (D_ij − D_i3 D_3j / D_33) dE_j (i, j in 11, 22, 12)
      for (int i : {0, 1, 3})
        for (int j : {0, 1, 3}) scratch(i, j) = full(i, j) - full(i, 2) * full(2, j) / full(2, 2);
      stress(2) = stress(4) = stress(5) = 0.0;
      return scratch;
    }
    // dτ33/dκ = 2 λ3² S33 + λ3⁴ D33 (dE33/dκ = λ3²); small strain: dσ33/dε33 = D33.
    const double slope = in.nlgeom ? 2 * l2 * stress(2) + l2 * l2 * full(2, 2) : full(2, 2);
    if (!(slope > 0)) break;  // τ33 rises with λ3 for a stable material
    const double step = (in.nlgeom ? l2 * stress(2) : stress(2)) / slope;
    previous = unknown;
    unknown -= in.nlgeom ? std::clamp(step, -0.5, 0.5) : step;
  }
  stress.setConstant(std::numeric_limits<double>::quiet_NaN());  // the increment is cut back
  scratch.setConstant(std::numeric_limits<double>::quiet_NaN());
  return scratch;
}

void PlaneStressCondensation::plastic_output(std::span<const double> state, PointResult& out) const {
  if (state.size() == state_size()) law_->plastic_output(inner(state), out);
}

bool PlaneStressCondensation::set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const {
  return law_->set_plastic_strain(inner(state), plastic_strain);
}

bool PlaneStressCondensation::increment_too_large(std::span<const double> committed,
                                                  std::span<const double> trial) const {
  return law_->increment_too_large(inner(committed), inner(trial));
}

double PlaneStressCondensation::plane_stress_thickness_strain(const Vec3& x, const Vec6& strain, const Vec6& stress,
                                                              double thermal_strain, double temperature,
                                                              std::span<const double> state) const {
  if (state.size() == state_size()) return state.back();
  return Material::plane_stress_thickness_strain(x, strain, stress, thermal_strain, temperature, state);
}

}  // namespace inpact::solver::elements
