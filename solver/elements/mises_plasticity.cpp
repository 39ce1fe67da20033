#include "mises_plasticity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "temperature_bracket.hpp"
#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

using L = MisesStateLayout;

/// ξ : ξ of a symmetric tensor in Voigt form (tensor components): the shears count twice.
double contract(const Vec6& a) { return a.head<3>().squaredNorm() + 2.0 * a.tail<3>().squaredNorm(); }

/// σ_y(ε̄ᵖ) of the curve `sy` on the grid `strain`: linear between the points, constant beyond
/// the last (Abaqus); σ⁰ = sy[0] with kinematic hardening (the surface moves, its size stays).
double yield_on(const std::vector<double>& strain, std::span<const double> sy, bool kinematic, double eq) {
  const std::size_t n = strain.size();
  if (kinematic) return sy[0];
  if (eq >= strain[n - 1]) return sy[n - 1];
  std::size_t k = 0;
  while (k + 2 < n && eq >= strain[k + 1]) ++k;
  const double slope = (sy[k + 1] - sy[k]) / (strain[k + 1] - strain[k]);
  return sy[k] + slope * (eq - strain[k]);
}

}  // namespace

MisesHardening isotropic_hardening(std::span<const model::Plastic::Point> rows) {
  MisesHardening h;
  for (const auto& r : rows) {
    h.plastic_strain.push_back(r.plastic_strain);
    if (h.temperatures.empty() || r.temperature != h.temperatures.back()) h.temperatures.push_back(r.temperature);
  }
  std::ranges::sort(h.plastic_strain);
  h.plastic_strain.erase(std::unique(h.plastic_strain.begin(), h.plastic_strain.end()), h.plastic_strain.end());
  for (std::size_t first = 0; first < rows.size();) {  // one block: rows [first, last)
    std::size_t last = first + 1;
    while (last < rows.size() && rows[last].temperature == rows[first].temperature) ++last;
    std::size_t k = first;  // the block's segment [k, k + 1] holding the grid point
    for (double eq : h.plastic_strain) {
      while (k + 1 < last && eq >= rows[k + 1].plastic_strain) ++k;
      if (k + 1 == last) {
        h.yield_stress.push_back(rows[k].yield_stress);  // constant beyond the block's last point
        continue;
      }
      const double s = (eq - rows[k].plastic_strain) / (rows[k + 1].plastic_strain - rows[k].plastic_strain);
      h.yield_stress.push_back(rows[k].yield_stress + s * (rows[k + 1].yield_stress - rows[k].yield_stress));
    }
    first = last;
  }
  if (h.temperatures.size() == 1) h.temperatures.clear();
  return h;
}

MisesPlasticity::MisesPlasticity(const ElasticConstants& constants, MisesHardening hardening,
                                 model::ElementFamily family)
    : constants_(constants), hardening_(std::move(hardening)), plane_stress_(family == model::ElementFamily::PlaneStress),
      D_(elasticity_matrix(model::ElementFamily::Solid3D, constants)) {
  const auto& h = hardening_;
  const std::size_t rows = std::max<std::size_t>(h.temperatures.size(), 1);
  if (h.plastic_strain.empty() || h.yield_stress.size() != rows * h.plastic_strain.size() || h.plastic_strain[0] != 0.0)
    throw std::invalid_argument("MisesPlasticity: the table needs points from zero plastic strain, a row a temperature");
  if (h.kinematic && rows > 1)
    throw std::invalid_argument("MisesPlasticity: kinematic hardening takes one temperature");
  const double E = constants.youngs_modulus, nu = constants.poissons_ratio;
  shear_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
  if (h.kinematic && h.yield_stress.size() > 1)
    kinematic_modulus_ = (h.yield_stress[1] - h.yield_stress[0]) / (h.plastic_strain[1] - h.plastic_strain[0]);
  first_yield_ = h.yield_stress[0];
  for (std::size_t t = 1; t < rows; ++t) first_yield_ = std::min(first_yield_, h.yield_stress[t * h.plastic_strain.size()]);
}

std::span<const double> MisesPlasticity::curve_at(double temperature, std::vector<double>& buffer) const {
  const auto& h = hardening_;
  const std::size_t m = h.plastic_strain.size();
  const std::span<const double> all(h.yield_stress);
  const TemperatureBracket b = bracket(h.temperatures, temperature);
  if (b.lower == b.upper) return all.subspan(b.lower * m, m);
  buffer.resize(m);
  for (std::size_t k = 0; k < m; ++k) buffer[k] = b.blend(all[b.lower * m + k], all[b.upper * m + k]);
  return buffer;
}

double MisesPlasticity::yield_stress(double eq, double temperature) const {
  std::vector<double> buffer;
  return yield_on(hardening_.plastic_strain, curve_at(temperature, buffer), hardening_.kinematic, eq);
}

/// q_tr − (3G + C)Δγ − σ_y(ε̄ᵖ_n + Δγ) = 0, σ_y linear on each segment: the segment that holds
/// the root is found by walking from the one that holds ε̄ᵖ_n (g decreases in Δγ while
/// 3G + C + H > 0).
MisesPlasticity::Return MisesPlasticity::solve_return(double q_trial, double eq_n, std::span<const double> sy) const {
  const double stiff = 3 * shear_ + kinematic_modulus_;
  const auto& strain = hardening_.plastic_strain;
  const std::size_t n = strain.size();
  if (hardening_.kinematic || n == 1) return {(q_trial - sy[0]) / stiff, kinematic_modulus_};
  std::size_t k = 0;
  while (k + 1 < n && eq_n >= strain[k + 1]) ++k;
  for (;; ++k) {
    const bool last = k + 1 >= n;  // beyond the table: σ_y constant
    const double slope = last ? 0.0 : (sy[k + 1] - sy[k]) / (strain[k + 1] - strain[k]);
    const double sy_n = sy[k] + slope * (eq_n - strain[k]);  // segment k's line at ε̄ᵖ_n
    const double dgamma = (q_trial - sy_n) / (stiff + slope);
    if (last || eq_n + dgamma <= strain[k + 1]) return {dgamma, slope + kinematic_modulus_};
  }
}

const Mat6& MisesPlasticity::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                    Mat6& scratch) const {
  if (plane_stress_) return update_plane_stress(in, point, stress, scratch);
  return update_3d(in.strain, in, point, stress, scratch);
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
    tangent = &update_3d(strain, in, point, stress, scratch);
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

const Mat6& MisesPlasticity::update_3d(const Vec6& strain, const MaterialPointInput& in, const PointHistory& point,
                                       Vec6& stress, Mat6& scratch) const {
  const std::span<const double> c = point.committed;
  std::copy(c.begin(), c.end(), point.trial.begin());
  const Eigen::Map<const Vec6> ep_n(c.data() + L::plastic_strain);
  Vec6 elastic_strain = strain - ep_n;
  elastic_strain.head<3>().array() -= in.thermal_strain;
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
  std::vector<double> buffer;  // σ_y at this temperature (stays empty without dependence)
  const std::span<const double> curve = curve_at(in.temperature, buffer);
  if (q_trial <= yield_on(hardening_.plastic_strain, curve, hardening_.kinematic, eq_n) * (1 + 1e-12)) return D_;

  const Return r = solve_return(q_trial, eq_n, curve);
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
  const double first_yield = first_yield_ / constants_.youngs_modulus;
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
