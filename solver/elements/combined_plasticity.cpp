#include "combined_plasticity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

constexpr std::size_t kMaxBackstresses = 10;  // Abaqus's limit

double mises(const Vec6& deviator) { return std::sqrt(1.5 * voigt_contract(deviator, deviator)); }

/// The matrix that takes an engineering strain to the tensor components of its deviator.
Mat6 deviatoric_projection() {
  Mat6 m = Mat6::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = (i == j ? 1.0 : 0.0) - 1.0 / 3.0;
    m(i + 3, i + 3) = 0.5;
  }
  return m;
}

}  // namespace

/// The converged return: Δγ, η = dev σ_tr − Σ a_k α_k,n and what the tangent needs.
struct CombinedPlasticity::Return {
  double dgamma = 0.0;
  double q = 0.0;      ///< q(η)
  double slope = 0.0;  ///< dσ⁰/dε̄ᵖ at the returned point
  Vec6 eta = Vec6::Zero();
  Vec6 b = Vec6::Zero();  ///< dη/dΔγ = Σ γ_k a_k² α_k,n
  std::array<double, kMaxBackstresses> a{};
  bool converged = false;
};

CombinedPlasticity::CombinedPlasticity(const ElasticConstants& constants, CombinedHardening hardening)
    : constants_(constants), hardening_(std::move(hardening)),
      D_(elasticity_matrix(model::ElementFamily::Solid3D, constants)) {
  const auto& h = hardening_;
  if (h.backstresses.empty() || h.backstresses.size() > kMaxBackstresses)
    throw std::invalid_argument("CombinedPlasticity: 1 to 10 backstresses");
  if (!h.table_strain.empty() && (h.table_strain.size() != h.table_stress.size() || h.table_strain[0] != 0.0))
    throw std::invalid_argument("CombinedPlasticity: the table needs points from zero plastic strain");
  const double E = constants.youngs_modulus, nu = constants.poissons_ratio;
  shear_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
}

double CombinedPlasticity::yield_size(double eq, double* slope) const {
  const auto& h = hardening_;
  double d = 0.0, value = 0.0;
  if (h.table_strain.empty()) {
    const double decay = std::exp(-h.rate * eq);
    value = h.initial + h.saturation * (1 - decay);
    d = h.saturation * h.rate * decay;
  } else {
    const std::size_t n = h.table_strain.size();
    if (eq >= h.table_strain[n - 1]) {
      value = h.table_stress[n - 1];
    } else {
      std::size_t k = 0;
      while (k + 2 < n && eq >= h.table_strain[k + 1]) ++k;
      d = (h.table_stress[k + 1] - h.table_stress[k]) / (h.table_strain[k + 1] - h.table_strain[k]);
      value = h.table_stress[k] + d * (eq - h.table_strain[k]);
    }
  }
  if (slope) *slope = d;
  return value;
}

/// r(Δγ) = q(η) − (3G + Σ C_k a_k)Δγ − σ⁰(ε̄ᵖ_n + Δγ) by Newton's method, kept inside the bracket
/// [0, (q_tr + Σ q(α_k,n))/3G] (r > 0 at 0, r < 0 at its top) by bisection.
CombinedPlasticity::Return CombinedPlasticity::solve_return(const Vec6& s_trial, std::span<const double> c) const {
  const auto& bs = hardening_.backstresses;
  const std::size_t nb = bs.size();
  auto alpha_n = [&](std::size_t k) { return Eigen::Map<const Vec6>(c.data() + kBackstress + 6 * k); };
  const double eq_n = c[kEquivalent];
  double lo = 0.0, hi = mises(s_trial);
  for (std::size_t k = 0; k < nb; ++k) hi += mises(alpha_n(k));
  hi /= 3 * shear_;
  const double tolerance = 1e-12 * yield_size(eq_n);
  Return r;
  for (int it = 0; it < 200; ++it) {
    const double dg = r.dgamma;
    r.eta = s_trial;
    r.b.setZero();
    double stiffness = 3 * shear_, d_stiffness = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      r.a[k] = 1.0 / (1.0 + bs[k].recovery * dg);
      r.eta -= r.a[k] * alpha_n(k);
      r.b += (bs[k].recovery * r.a[k] * r.a[k]) * alpha_n(k);
      stiffness += bs[k].modulus * r.a[k];
      d_stiffness -= bs[k].modulus * bs[k].recovery * r.a[k] * r.a[k];
    }
    r.q = mises(r.eta);
    const double residual = r.q - stiffness * dg - yield_size(eq_n + dg, &r.slope);
    if (std::abs(residual) <= tolerance) {
      r.converged = true;
      return r;
    }
    (residual > 0 ? lo : hi) = dg;
    const double derivative = 1.5 * voigt_contract(r.eta, r.b) / r.q - stiffness - d_stiffness * dg - r.slope;
    double next = derivative < 0 ? dg - residual / derivative : -1.0;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    r.dgamma = next;
  }
  return r;
}

const Mat6& CombinedPlasticity::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                       Mat6& scratch) const {
  const std::span<const double> c = point.committed;
  std::copy(c.begin(), c.end(), point.trial.begin());
  Vec6 elastic_strain = in.strain - Eigen::Map<const Vec6>(c.data() + kPlasticStrain);
  elastic_strain.head<3>().array() -= in.thermal_strain;
  stress = D_ * elastic_strain;  // the trial stress
  const Vec6 s_trial = voigt_deviator(stress);
  Vec6 xi = s_trial;
  for (std::size_t k = 0; k < hardening_.backstresses.size(); ++k) xi -= Eigen::Map<const Vec6>(c.data() + kBackstress + 6 * k);
  // Elastic, and on the surface to round-off at the converged strain (see MisesPlasticity).
  if (mises(xi) <= yield_size(c[kEquivalent]) * (1 + 1e-12)) return D_;

  const Return r = solve_return(s_trial, c);
  if (!r.converged) {
    stress.setConstant(std::nan(""));  // the increment is cut back
    return D_;
  }
  const Vec6 n = (1.5 / r.q) * r.eta;
  stress -= (2 * shear_ * r.dgamma) * n;
  Eigen::Map<Vec6> ep(point.trial.data() + kPlasticStrain);
  ep.head<3>() += r.dgamma * n.head<3>();
  ep.tail<3>() += (2 * r.dgamma) * n.tail<3>();  // engineering shear
  point.trial[kEquivalent] = c[kEquivalent] + r.dgamma;
  for (std::size_t k = 0; k < hardening_.backstresses.size(); ++k) {
    Eigen::Map<Vec6> alpha(point.trial.data() + kBackstress + 6 * k);
    alpha = r.a[k] * (alpha + (2.0 / 3.0 * hardening_.backstresses[k].modulus * r.dgamma) * n);
  }
  consistent_tangent(r, scratch);
  return scratch;
}

/// dΔγ = 2G n·dε / A, A = 3G + Σ C_k a_k − Σ C_k γ_k a_k² Δγ + H − n:b, and
/// C = D − (2G)²/A n⊗n − 2GΔγ·3/(2q) [2G (I_dev − 2/3 n⊗n) + (b − 2/3 (n:b) n) ⊗ 2G n / A],
/// returned symmetrised (see the header).
void CombinedPlasticity::consistent_tangent(const Return& r, Mat6& tangent) const {
  const auto& bs = hardening_.backstresses;
  const Vec6 n = (1.5 / r.q) * r.eta;
  double A = 3 * shear_ + r.slope - voigt_contract(n, r.b);
  for (std::size_t k = 0; k < bs.size(); ++k)
    A += bs[k].modulus * r.a[k] - bs[k].modulus * bs[k].recovery * r.a[k] * r.a[k] * r.dgamma;
  const double G2 = 2 * shear_, c = G2 * r.dgamma * 1.5 / r.q;
  static const Mat6 dev = deviatoric_projection();
  const Vec6 turn = r.b - (2.0 / 3.0 * voigt_contract(n, r.b)) * n;
  tangent = D_ - (G2 * G2 / A) * (n * n.transpose()) - (c * G2) * (dev - 2.0 / 3.0 * (n * n.transpose())) -
            (c * G2 / A) * (turn * n.transpose());
  tangent = 0.5 * (tangent + tangent.transpose()).eval();
}

bool CombinedPlasticity::increment_too_large(std::span<const double> committed, std::span<const double> trial) const {
  const double first_yield = yield_size(0.0) / constants_.youngs_modulus;
  return trial[kEquivalent] - committed[kEquivalent] > 50 * first_yield;
}

bool CombinedPlasticity::set_plastic_strain(std::span<double> state, const Vec6& plastic_strain) const {
  std::copy_n(plastic_strain.data(), 6, state.begin() + kPlasticStrain);
  return true;
}

void CombinedPlasticity::plastic_output(std::span<const double> state, PointResult& out) const {
  if (state.size() < state_size()) return;
  std::copy_n(state.begin() + kPlasticStrain, 6, out.plastic_strain.begin());
  out.peeq = state[kEquivalent];
}

}  // namespace inpact::solver::elements
