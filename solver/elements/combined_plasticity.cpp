#include "combined_plasticity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

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

/// σ⁰(ε̄ᵖ) of one table: piecewise linear, constant beyond the last point.
double table_size(const CombinedHardening& h, double eq, double& slope) {
  const std::size_t n = h.table_strain.size();
  slope = 0.0;
  if (eq >= h.table_strain[n - 1]) return h.table_stress[n - 1];
  std::size_t k = 0;
  while (k + 2 < n && eq >= h.table_strain[k + 1]) ++k;
  slope = (h.table_stress[k + 1] - h.table_stress[k]) / (h.table_strain[k + 1] - h.table_strain[k]);
  return h.table_stress[k] + slope * (eq - h.table_strain[k]);
}

void check_sets(const std::vector<CombinedHardening>& sets, const std::vector<double>& temperatures) {
  if (sets.empty() || (sets.size() > 1 && sets.size() != temperatures.size()))
    throw std::invalid_argument("CombinedPlasticity: one set of parameters per temperature");
  for (const CombinedHardening& h : sets) {
    if (h.backstresses.empty() || h.backstresses.size() > CombinedPlasticity::kMaxBackstresses ||
        h.backstresses.size() != sets[0].backstresses.size())
      throw std::invalid_argument("CombinedPlasticity: 1 to 10 backstresses, as many at every temperature");
    if (h.table_strain.empty() != sets[0].table_strain.empty())
      throw std::invalid_argument("CombinedPlasticity: the same kind of yield surface size at every temperature");
    if (!h.table_strain.empty() && (h.table_strain.size() != h.table_stress.size() || h.table_strain[0] != 0.0))
      throw std::invalid_argument("CombinedPlasticity: the table needs points from zero plastic strain");
  }
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
    : CombinedPlasticity(constants, std::vector<CombinedHardening>{std::move(hardening)}, {}) {}

CombinedPlasticity::CombinedPlasticity(const ElasticConstants& constants, std::vector<CombinedHardening> sets,
                                       std::vector<double> temperatures)
    : constants_(constants), sets_(std::move(sets)), temperatures_(std::move(temperatures)),
      D_(elasticity_matrix(model::ElementFamily::Solid3D, constants)) {
  check_sets(sets_, temperatures_);
  if (sets_.size() == 1) temperatures_.clear();
  const double E = constants.youngs_modulus, nu = constants.poissons_ratio;
  shear_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
  first_yield_ = yield_size(0.0, nullptr, temperatures_.empty() ? 0.0 : temperatures_[0]);
  for (double t : temperatures_) first_yield_ = std::min(first_yield_, yield_size(0.0, nullptr, t));
}

CombinedPlasticity::AtTemperature CombinedPlasticity::at(double temperature) const {
  AtTemperature p;
  p.bracket = bracket(temperatures_, temperature);
  const auto& lo = sets_[p.bracket.lower].backstresses;
  const auto& hi = sets_[p.bracket.upper].backstresses;
  for (std::size_t k = 0; k < lo.size(); ++k)
    p.backstresses[k] = {p.bracket.blend(lo[k].modulus, hi[k].modulus), p.bracket.blend(lo[k].recovery, hi[k].recovery)};
  return p;
}

/// A table is interpolated at equal ε̄ᵖ (the rows' values), the exponential law through its
/// parameters, as Abaqus interpolates the data it is given.
double CombinedPlasticity::yield_size(const AtTemperature& p, double eq, double* slope) const {
  const CombinedHardening& lo = sets_[p.bracket.lower];
  const CombinedHardening& hi = sets_[p.bracket.upper];
  const TemperatureBracket& b = p.bracket;
  double d = 0.0, value = 0.0;
  if (lo.table_strain.empty()) {
    const double rate = b.blend(lo.rate, hi.rate), saturation = b.blend(lo.saturation, hi.saturation);
    const double decay = std::exp(-rate * eq);
    value = b.blend(lo.initial, hi.initial) + saturation * (1 - decay);
    d = saturation * rate * decay;
  } else {
    double d_lo = 0.0, d_hi = 0.0;
    value = b.blend(table_size(lo, eq, d_lo), table_size(hi, eq, d_hi));
    d = b.blend(d_lo, d_hi);
  }
  if (slope) *slope = d;
  return value;
}

double CombinedPlasticity::yield_size(double eq, double* slope, double temperature) const {
  return yield_size(at(temperature), eq, slope);
}

CombinedHardening::Backstress CombinedPlasticity::backstress(std::size_t k, double temperature) const {
  return at(temperature).backstresses.at(k);
}

/// r(Δγ) = q(η) − (3G + Σ C_k a_k)Δγ − σ⁰(ε̄ᵖ_n + Δγ) by Newton's method, kept inside the bracket
/// [0, (q_tr + Σ q(α_k,n))/3G] (r > 0 at 0, r < 0 at its top) by bisection.
CombinedPlasticity::Return CombinedPlasticity::solve_return(const AtTemperature& p, const Vec6& s_trial,
                                                            std::span<const Vec6> alpha_n, double eq_n) const {
  const std::size_t nb = alpha_n.size();
  double lo = 0.0, hi = mises(s_trial);
  for (std::size_t k = 0; k < nb; ++k) hi += mises(alpha_n[k]);
  hi /= 3 * shear_;
  const double tolerance = 1e-12 * yield_size(p, eq_n, nullptr);
  Return r;
  for (int it = 0; it < 200; ++it) {
    const double dg = r.dgamma;
    r.eta = s_trial;
    r.b.setZero();
    double stiffness = 3 * shear_, d_stiffness = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      const auto& bs = p.backstresses[k];
      r.a[k] = 1.0 / (1.0 + bs.recovery * dg);
      r.eta -= r.a[k] * alpha_n[k];
      r.b += (bs.recovery * r.a[k] * r.a[k]) * alpha_n[k];
      stiffness += bs.modulus * r.a[k];
      d_stiffness -= bs.modulus * bs.recovery * r.a[k] * r.a[k];
    }
    r.q = mises(r.eta);
    const double residual = r.q - stiffness * dg - yield_size(p, eq_n + dg, &r.slope);
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
  const AtTemperature p = at(in.temperature);
  const std::size_t nb = backstress_count();
  std::array<Vec6, kMaxBackstresses> alpha_n;  // α_k,n = C_k(T) β_k,n
  for (std::size_t k = 0; k < nb; ++k)
    alpha_n[k] = p.backstresses[k].modulus * Eigen::Map<const Vec6>(c.data() + kBackstress + 6 * k);
  Vec6 elastic_strain = in.strain - Eigen::Map<const Vec6>(c.data() + kPlasticStrain);
  elastic_strain.head<3>().array() -= in.thermal_strain;
  stress = D_ * elastic_strain;  // the trial stress
  const Vec6 s_trial = voigt_deviator(stress);
  Vec6 xi = s_trial;
  for (std::size_t k = 0; k < nb; ++k) xi -= alpha_n[k];
  // Elastic, and on the surface to round-off at the converged strain (see MisesPlasticity).
  if (mises(xi) <= yield_size(p, c[kEquivalent], nullptr) * (1 + 1e-12)) return D_;

  const Return r = solve_return(p, s_trial, std::span(alpha_n).first(nb), c[kEquivalent]);
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
  for (std::size_t k = 0; k < nb; ++k) {  // β_k = a_k (β_k,n + 2/3 Δγ n)
    Eigen::Map<Vec6> beta(point.trial.data() + kBackstress + 6 * k);
    beta = r.a[k] * (beta + (2.0 / 3.0 * r.dgamma) * n);
  }
  consistent_tangent(p, r, scratch);
  return scratch;
}

/// dΔγ = 2G n·dε / A, A = 3G + Σ C_k a_k − Σ C_k γ_k a_k² Δγ + H − n:b, and
/// C = D − (2G)²/A n⊗n − 2GΔγ·3/(2q) [2G (I_dev − 2/3 n⊗n) + (b − 2/3 (n:b) n) ⊗ 2G n / A],
/// returned symmetrised (see the header).
void CombinedPlasticity::consistent_tangent(const AtTemperature& p, const Return& r, Mat6& tangent) const {
  const Vec6 n = (1.5 / r.q) * r.eta;
  double A = 3 * shear_ + r.slope - voigt_contract(n, r.b);
  for (std::size_t k = 0; k < backstress_count(); ++k) {
    const auto& bs = p.backstresses[k];
    A += bs.modulus * r.a[k] - bs.modulus * bs.recovery * r.a[k] * r.a[k] * r.dgamma;
  }
  const double G2 = 2 * shear_, c = G2 * r.dgamma * 1.5 / r.q;
  static const Mat6 dev = deviatoric_projection();
  const Vec6 turn = r.b - (2.0 / 3.0 * voigt_contract(n, r.b)) * n;
  tangent = D_ - (G2 * G2 / A) * (n * n.transpose()) - (c * G2) * (dev - 2.0 / 3.0 * (n * n.transpose())) -
            (c * G2 / A) * (turn * n.transpose());
  tangent = 0.5 * (tangent + tangent.transpose()).eval();
}

bool CombinedPlasticity::increment_too_large(std::span<const double> committed, std::span<const double> trial) const {
  return trial[kEquivalent] - committed[kEquivalent] > 50 * first_yield_ / constants_.youngs_modulus;
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
