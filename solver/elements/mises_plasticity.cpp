#include "mises_plasticity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

using L = MisesStateLayout;

/// ξ : ξ of a symmetric tensor in Voigt form (tensor components): the shears count twice.
double contract(const Vec6& a) { return a.head<3>().squaredNorm() + 2.0 * a.tail<3>().squaredNorm(); }

}  // namespace

MisesPlasticity::MisesPlasticity(const ElasticConstants& constants, MisesHardening hardening,
                                 model::ElementFamily family)
    : constants_(constants), hardening_(std::move(hardening)), plane_stress_(family == model::ElementFamily::PlaneStress),
      D_(elasticity_matrix(model::ElementFamily::Solid3D, constants)) {
  const auto& h = hardening_;
  if (h.yield_stress.empty() || h.yield_stress.size() != h.plastic_strain.size() || h.plastic_strain[0] != 0.0)
    throw std::invalid_argument("MisesPlasticity: the table needs points from zero plastic strain");
  const double E = constants.youngs_modulus, nu = constants.poissons_ratio;
  shear_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
  if (h.kinematic && h.yield_stress.size() > 1)
    kinematic_modulus_ = (h.yield_stress[1] - h.yield_stress[0]) / (h.plastic_strain[1] - h.plastic_strain[0]);
}

double MisesPlasticity::yield_stress(double eq) const {
  const auto& h = hardening_;
  if (h.kinematic) return h.yield_stress[0];
  const std::size_t n = h.plastic_strain.size();
  if (eq >= h.plastic_strain[n - 1]) return h.yield_stress[n - 1];  // constant beyond the table (Abaqus)
  std::size_t k = 0;
  while (k + 2 < n && eq >= h.plastic_strain[k + 1]) ++k;
  const double slope = (h.yield_stress[k + 1] - h.yield_stress[k]) / (h.plastic_strain[k + 1] - h.plastic_strain[k]);
  return h.yield_stress[k] + slope * (eq - h.plastic_strain[k]);
}

/// q_tr − (3G + C)Δγ − σ_y(ε̄ᵖ_n + Δγ) = 0, σ_y linear on each segment: the segment that holds
/// the root is found by walking from the one that holds ε̄ᵖ_n (g decreases in Δγ while
/// 3G + C + H > 0).
MisesPlasticity::Return MisesPlasticity::solve_return(double q_trial, double eq_n) const {
  const double stiff = 3 * shear_ + kinematic_modulus_;
  const auto& h = hardening_;
  const std::size_t n = h.plastic_strain.size();
  if (h.kinematic || n == 1) return {(q_trial - h.yield_stress[0]) / stiff, kinematic_modulus_};
  std::size_t k = 0;
  while (k + 1 < n && eq_n >= h.plastic_strain[k + 1]) ++k;
  for (;; ++k) {
    const bool last = k + 1 >= n;  // beyond the table: σ_y constant
    const double slope =
        last ? 0.0 : (h.yield_stress[k + 1] - h.yield_stress[k]) / (h.plastic_strain[k + 1] - h.plastic_strain[k]);
    const double sy_n = h.yield_stress[k] + slope * (eq_n - h.plastic_strain[k]);  // segment k's line at ε̄ᵖ_n
    const double dgamma = (q_trial - sy_n) / (stiff + slope);
    if (last || eq_n + dgamma <= h.plastic_strain[k + 1]) return {dgamma, slope + kinematic_modulus_};
  }
}

const Mat6& MisesPlasticity::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                    Mat6& scratch) const {
  if (plane_stress_) return update_plane_stress(in, point, stress, scratch);
  return update_3d(in.strain, in.thermal_strain, point, stress, scratch);
}

const Mat6& MisesPlasticity::update_plane_stress(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                                 Mat6& scratch) const {
  const std::size_t thickness = L::thickness(hardening_.kinematic);
  Vec6 strain = in.strain;
  strain(4) = strain(5) = 0.0;
  strain(2) = point.committed[thickness];
  const Mat6* tangent = nullptr;
  bool converged = false;
  for (int it = 0; it < 50 && !converged; ++it) {
    tangent = &update_3d(strain, in.thermal_strain, point, stress, scratch);
    const double scale = std::max(stress.cwiseAbs().maxCoeff(), hardening_.yield_stress[0]);
    converged = std::abs(stress(2)) <= 1e-12 * scale;
    if (!converged) strain(2) -= stress(2) / (*tangent)(2, 2);
  }
  point.trial[thickness] = strain(2);
  if (!converged) stress.setConstant(std::nan(""));  // the increment is cut back
  // Condensed for σ33 = 0: dσ_ij = (C_ij − C_i3 C_3j / C_33) dε_j (i, j in 11, 22, 12).
  const Mat6 full = *tangent;  // may be scratch itself
  scratch.setZero();
  for (int i : {0, 1, 3})
    for (int j : {0, 1, 3}) scratch(i, j) = full(i, j) - full(i, 2) * full(2, j) / full(2, 2);
  stress(2) = stress(4) = stress(5) = 0.0;
  return scratch;
}

const Mat6& MisesPlasticity::update_3d(const Vec6& strain, double thermal_strain, const PointHistory& point,
                                       Vec6& stress, Mat6& scratch) const {
  const std::span<const double> c = point.committed;
  std::copy(c.begin(), c.end(), point.trial.begin());
  const Eigen::Map<const Vec6> ep_n(c.data() + L::plastic_strain);
  Vec6 elastic_strain = strain - ep_n;
  elastic_strain.head<3>().array() -= thermal_strain;
  stress = D_ * elastic_strain;  // the trial stress
  Vec6 xi = voigt_deviator(stress);
  if (hardening_.kinematic) xi -= Eigen::Map<const Vec6>(c.data() + L::backstress);
  const double norm = std::sqrt(contract(xi));
  const double q_trial = std::sqrt(1.5) * norm;
  const double eq_n = c[L::equivalent];
  // Elastic: the committed state stays. A point evaluated at its converged strain (the first
  // iteration of an increment) is on the surface to round-off and must stay elastic: the
  // elastic tangent there is what lets an unloading increment converge at once, where the
  // elastic–plastic one overshoots into reversed yielding and Newton cycles about the kink.
  if (q_trial <= yield_stress(eq_n) * (1 + 1e-12)) return D_;

  const Return r = solve_return(q_trial, eq_n);
  const Vec6 n = xi / norm;                    // unit normal (tensor components)
  const double flow = std::sqrt(1.5) * r.dgamma;  // |Δεᵖ| as a tensor norm
  stress -= (2 * shear_ * flow) * n;
  Eigen::Map<Vec6> ep(point.trial.data() + L::plastic_strain);
  ep.head<3>() += flow * n.head<3>();
  ep.tail<3>() += (2 * flow) * n.tail<3>();  // engineering shear
  point.trial[L::equivalent] = eq_n + r.dgamma;
  if (hardening_.kinematic)
    Eigen::Map<Vec6>(point.trial.data() + L::backstress) += (2.0 / 3.0 * kinematic_modulus_ * flow) * n;

  // C = K 1⊗1 + 2Gθ I_dev − 2Gθ̄ n⊗n on engineering shear strains (I_dev's shear diagonal ½).
  const double theta = 1 - 3 * shear_ * r.dgamma / q_trial;
  const double theta_bar = 1 / (1 + r.slope / (3 * shear_)) - (1 - theta);
  scratch.setZero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) scratch(i, j) = bulk_ - 2 * shear_ * theta / 3;
    scratch(i, i) += 2 * shear_ * theta;
    scratch(i + 3, i + 3) = shear_ * theta;
  }
  scratch.noalias() -= (2 * shear_ * theta_bar) * (n * n.transpose());
  return scratch;
}

bool MisesPlasticity::increment_too_large(std::span<const double> committed, std::span<const double> trial) const {
  const double first_yield = hardening_.yield_stress[0] / constants_.youngs_modulus;
  return trial[L::equivalent] - committed[L::equivalent] > 50 * first_yield;
}

bool MisesPlasticity::set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const {
  std::copy_n(plastic_strain.data(), 6, state.begin() + L::plastic_strain);
  return true;
}

void MisesPlasticity::plastic_output(std::span<const double> state, PointResult& out) const {
  if (state.size() < state_size()) return;
  std::copy_n(state.begin() + L::plastic_strain, 6, out.plastic_strain.begin());
  out.peeq = state[L::equivalent];
  // Plane stress: the elastic formula of point_output misses the plastic part of ε33.
  if (plane_stress_) out.strain[2] = state[L::thickness(hardening_.kinematic)];
}

}  // namespace inpact::solver::elements
