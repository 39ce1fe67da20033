#include "finite_strain_mises.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "log_divided_difference.hpp"
#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

using Mat3 = Eigen::Matrix3d;
constexpr std::size_t kSmallState = 7;  ///< MisesPlasticity's isotropic layout: εᵖ (6), ε̄ᵖ

/// exp(s·t) of a symmetric tensor t.
Mat3 tensor_exp(const Mat3& t, double s) {
  Eigen::SelfAdjointEigenSolver<Mat3> eig(t);
  const Eigen::Vector3d e = (s * eig.eigenvalues().array()).exp();
  return eig.eigenvectors() * e.asDiagonal() * eig.eigenvectors().transpose();
}

/// ½ ln(b) of a symmetric positive definite tensor b.
Mat3 half_log(const Mat3& b) {
  Eigen::SelfAdjointEigenSolver<Mat3> eig(b);
  const Eigen::Vector3d l = 0.5 * eig.eigenvalues().array().log();
  return eig.eigenvectors() * l.asDiagonal() * eig.eigenvectors().transpose();
}

void store_inverse_plastic(std::span<double> state, const Mat3& cp_inv) {
  const Vec6 v = tensor_to_vec6(cp_inv, false);
  std::copy_n(v.data(), 6, state.begin() + FiniteStrainMises::kInversePlasticCauchyGreen);
}

/// The trial elastic strain ½ ln bᵉ_tr in the eigenbasis of bᵉ_tr = F Cᵖ⁻¹ Fᵀ, which the
/// tangent reuses.
struct TrialElastic {
  Mat3 basis;                 ///< eigenvectors of bᵉ_tr (columns)
  Eigen::Vector3d stretch2;   ///< its eigenvalues λ²
  Mat3 strain;                ///< εᵉ_tr
};

TrialElastic trial_elastic(const Mat3& b) {
  Eigen::SelfAdjointEigenSolver<Mat3> eig(b);
  TrialElastic t{eig.eigenvectors(), eig.eigenvalues(), Mat3::Zero()};
  const Eigen::Vector3d l = 0.5 * t.stretch2.array().log();
  t.strain = t.basis * l.asDiagonal() * t.basis.transpose();
  return t;
}

/// dεᵉ_tr = ½ L[db]: the derivative of ½ ln at bᵉ_tr applied to db (Daleckii–Krein).
Mat3 log_derivative(const TrialElastic& t, const Mat3& db) {
  Mat3 d = t.basis.transpose() * db * t.basis;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) d(a, b) *= 0.5 * log_divided_difference(t.stretch2(a), t.stretch2(b));
  return t.basis * d * t.basis.transpose();
}

}  // namespace

FiniteStrainMises::FiniteStrainMises(const ElasticConstants& constants, MisesHardening hardening)
    : small_(constants, std::move(hardening), model::ElementFamily::Solid3D) {
  if (small_.state_size() != kSmallState)
    throw std::invalid_argument("FiniteStrainMises: isotropic hardening only");
}

void FiniteStrainMises::initial_state(std::span<double> state) const {
  std::fill(state.begin(), state.end(), 0.0);
  store_inverse_plastic(state, Mat3::Identity());
}

const Mat6& FiniteStrainMises::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                      Mat6& scratch) const {
  return in.nlgeom ? update_finite(in, point, stress, scratch) : update_small(in, point, stress, scratch);
}

const Mat6& FiniteStrainMises::update_small(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                            Mat6& scratch) const {
  const Mat6& tangent = small_.update(in, {point.committed.first(kSmallState), point.trial.first(kSmallState)},
                                      stress, scratch);
  const Vec6 ep = Eigen::Map<const Vec6>(point.trial.data() + kPlasticStrain);
  store_inverse_plastic(point.trial, tensor_exp(voigt_to_tensor(ep, true), -2.0));
  return tangent;
}

const Mat6& FiniteStrainMises::update_finite(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                             Mat6& scratch) const {
  const std::span<const double> c = point.committed;
  const Mat3& F = in.F;
  const Mat3 cp_inv = voigt_to_tensor(Eigen::Map<const Vec6>(c.data() + kInversePlasticCauchyGreen), false);
  const TrialElastic trial = trial_elastic(F * cp_inv * F.transpose());

  // The small-strain return on εᵉ_tr, from no plastic strain and the committed ε̄ᵖ.
  std::array<double, kSmallState> from{}, to{};
  from[kEquivalent] = c[kEquivalent];
  const Vec6 trial_strain = tensor_to_vec6(trial.strain, true);
  Vec6 tau;
  const Mat6 D = small_.update({F, trial_strain, in.thermal_strain, in.position, false, in.temperature}, {from, to}, tau, scratch);

  // εᵉ = εᵉ_tr − Δεᵖ is coaxial with εᵉ_tr (the flow is along dev τ_tr): bᵉ = exp(2εᵉ) in its basis.
  const Mat3 elastic = trial.strain - voigt_to_tensor(Eigen::Map<const Vec6>(to.data()), true);
  const Eigen::Vector3d e = (trial.basis.transpose() * elastic * trial.basis).diagonal();
  const Mat3 be = trial.basis * (2.0 * e.array()).exp().matrix().asDiagonal() * trial.basis.transpose();
  const Mat3 F_inv = F.inverse();
  store_inverse_plastic(point.trial, F_inv * be * F_inv.transpose());
  point.trial[kEquivalent] = to[kEquivalent];
  const Vec6 pe = tensor_to_vec6(half_log(F * F.transpose()) - elastic, true);
  std::copy_n(pe.data(), 6, point.trial.begin() + kPlasticStrain);

  const Mat3 S = F_inv * voigt_to_tensor(tau, false) * F_inv.transpose();
  stress = tensor_to_vec6(S, false);

  // ∂S/∂E, one column per unit δE (engineering shear: a unit γ is E_pq = E_qp = ½).
  for (int j = 0; j < 6; ++j) {
    const Mat3 dE = voigt_to_tensor(Vec6::Unit(j), true);
    const Mat3 dF = F_inv.transpose() * dE;
    const Mat3 a = dF * cp_inv * F.transpose();
    const Mat3 d_strain = log_derivative(trial, a + a.transpose());
    const Mat3 d_tau = voigt_to_tensor(D * tensor_to_vec6(d_strain, true), false);
    const Mat3 g = F_inv * dF * S;
    scratch.col(j) = tensor_to_vec6(F_inv * d_tau * F_inv.transpose() - g - g.transpose(), false);
  }
  return scratch;
}

void FiniteStrainMises::plastic_output(std::span<const double> state, PointResult& out) const {
  if (state.size() < state_size()) return;
  std::copy_n(state.begin() + kPlasticStrain, 6, out.plastic_strain.begin());
  out.peeq = state[kEquivalent];
}

bool FiniteStrainMises::set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const {
  std::copy_n(plastic_strain.data(), 6, state.begin() + kPlasticStrain);
  store_inverse_plastic(state, tensor_exp(voigt_to_tensor(plastic_strain, true), -2.0));
  return true;
}

bool FiniteStrainMises::increment_too_large(std::span<const double> committed, std::span<const double> trial) const {
  return small_.increment_too_large(committed.first(kSmallState), trial.first(kSmallState));
}

}  // namespace inpact::solver::elements
