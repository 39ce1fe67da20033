// The combined (nonlinear kinematic, Chaboche) hardening kernel alone
// (solver/elements/combined_plasticity.hpp): the return lands on the yield surface, the
// one-increment uniaxial closed form of the backward-Euler update, saturation of the backstress
// at C/γ, the Bauschinger effect on reversal, the tangent against central differences (its
// symmetric part; exact for γ = 0), linear-kinematic equivalence with MisesPlasticity, the
// state contract, and temperature dependence (parameters interpolated, the backstress carried
// with C(T)).
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "solver/elements/combined_plasticity.hpp"
#include "solver/elements/mises_plasticity.hpp"

using namespace inpact::solver::elements;
using CP = CombinedPlasticity;

namespace {

constexpr double kE = 200000.0, kNu = 0.3, kS0 = 250.0;
const ElasticConstants kElastic{kE, kNu, 0.0};

/// Two backstresses (C1 = 40000, γ1 = 400; C2 = 5000, γ2 = 20) and a Voce surface Q∞ = 80, b = 10.
CombinedHardening chaboche() {
  CombinedHardening h;
  h.backstresses = {{40000.0, 400.0}, {5000.0, 20.0}};
  h.initial = kS0, h.saturation = 80.0, h.rate = 10.0;
  return h;
}

struct Eval {
  Vec6 stress;
  Mat6 tangent;
  std::vector<double> trial;
};

Eval evaluate(const Material& m, const std::vector<double>& committed, const Vec6& strain, double temperature = 0.0) {
  Eval e;
  e.trial.assign(committed.size(), -1.0);
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Mat6 scratch;
  e.tangent = m.update({F, strain, 0.0, nullptr, false, temperature}, {committed, e.trial}, e.stress, scratch);
  return e;
}

Vec6 deviator(const Vec6& s) {
  Vec6 d = s;
  d.head<3>().array() -= (s(0) + s(1) + s(2)) / 3;
  return d;
}

double mises(const Vec6& d) { return std::sqrt(1.5 * (d.head<3>().squaredNorm() + 2 * d.tail<3>().squaredNorm())); }

/// α = Σ C_k β_k: the state keeps β_k = α_k / C_k.
Vec6 total_backstress(const CP& m, const std::vector<double>& s, double temperature = 0.0) {
  Vec6 a = Vec6::Zero();
  for (std::size_t k = 0; k < m.backstress_count(); ++k)
    a += m.backstress(k, temperature).modulus * Eigen::Map<const Vec6>(s.data() + CP::kBackstress + 6 * k);
  return a;
}

/// The uniaxial strain that, from the virgin state in one increment, gives Δγ = dg under
/// uniaxial stress: σ = σ⁰(Δγ) + X, X = Σ C_k Δγ/(1 + γ_k Δγ) (X = 3/2 α11), ε = σ/E + Δγ (1, −½, −½)
/// plus the elastic lateral −νσ/E.
Vec6 uniaxial_strain(const CombinedHardening& h, double dg, double& sigma, double& x) {
  x = 0;
  for (const auto& b : h.backstresses) x += b.modulus * dg / (1 + b.recovery * dg);
  sigma = h.initial + h.saturation * (1 - std::exp(-h.rate * dg)) + x;
  Vec6 e = Vec6::Zero();
  e(0) = sigma / kE + dg;
  e(1) = e(2) = -kNu * sigma / kE - dg / 2;
  return e;
}

}  // namespace

TEST(CombinedPlasticity, OneUniaxialIncrementFollowsTheBackwardEulerClosedForm) {
  const CP m(kElastic, chaboche());
  const std::vector<double> virgin(m.state_size(), 0.0);
  for (double dg : {1e-4, 2e-3, 0.05}) {
    double sigma = 0, x = 0;
    const Eval e = evaluate(m, virgin, uniaxial_strain(chaboche(), dg, sigma, x));
    EXPECT_NEAR(e.stress(0), sigma, 1e-10 * sigma) << dg;
    EXPECT_NEAR(e.stress(1), 0.0, 1e-10 * sigma) << dg;
    EXPECT_NEAR(e.trial[CP::kEquivalent], dg, 1e-12) << dg;
    EXPECT_NEAR(1.5 * total_backstress(m, e.trial)(0), x, 1e-10 * sigma) << dg;
    // On the yield surface: q(σ − α) = σ⁰(ε̄ᵖ).
    EXPECT_NEAR(mises(deviator(e.stress) - total_backstress(m, e.trial)), m.yield_size(dg), 1e-10 * sigma);
  }
}

namespace {

/// Uniaxial stress at axial strain e11 from `state`: the lateral strain found by Newton's method
/// on σ22 = 0 (σ33 = σ22 by symmetry).
Eval uniaxial(const CP& m, const std::vector<double>& state, double e11, double& lateral) {
  Vec6 e = Vec6::Zero();
  e(0) = e11;
  Eval r{Vec6::Zero(), Mat6::Zero(), {}};
  for (int it = 0; it < 50; ++it) {
    e(1) = e(2) = lateral;
    r = evaluate(m, state, e);
    if (std::abs(r.stress(1)) < 1e-11 * kS0) break;
    lateral -= r.stress(1) / (r.tangent(1, 1) + r.tangent(1, 2));
  }
  return r;
}

}  // namespace

TEST(CombinedPlasticity, BackstressSaturatesAtCOverGammaAndReversalShowsTheBauschingerEffect) {
  CombinedHardening h;
  h.backstresses = {{20000.0, 200.0}};  // X → C/γ = 100
  h.initial = kS0;                       // a surface of constant size
  const CP m(kElastic, h);
  std::vector<double> state(m.state_size(), 0.0);
  double lateral = 0, e11 = 0;
  Eval r{Vec6::Zero(), Mat6::Zero(), state};
  while (state[CP::kEquivalent] < 0.05) {  // γ ε̄ᵖ = 10: saturated to e^-10
    e11 += 1e-4;
    r = uniaxial(m, state, e11, lateral);
    state = r.trial;
  }
  const double x = 1.5 * total_backstress(m, state)(0);
  EXPECT_NEAR(x, 100.0, 1e-3 * 100.0);
  EXPECT_NEAR(r.stress(0), kS0 + x, 1e-9 * kS0);
  // Reversal: elastic down to X − σ⁰ = −150 (isotropic hardening would wait for −350), then yield.
  const double top = r.stress(0);
  double lat = lateral;
  const Eval elastic = uniaxial(m, state, e11 - (top + 149.0) / kE, lat);
  EXPECT_NEAR(elastic.stress(0), -149.0, 1e-6);
  EXPECT_EQ(elastic.trial[CP::kEquivalent], state[CP::kEquivalent]);
  lat = lateral;
  const Eval yielding = uniaxial(m, state, e11 - (top + 151.0) / kE, lat);
  EXPECT_GT(yielding.trial[CP::kEquivalent], state[CP::kEquivalent]);
  EXPECT_GT(yielding.stress(0), -151.0);  // the plastic flow relaxes the compressive stress
}

namespace {

/// A committed state with nonproportional plastic history (two increments along different paths).
std::vector<double> history(const CP& m, double temperature = 0.0) {
  std::vector<double> s(m.state_size(), 0.0);
  Vec6 e;
  e << 3e-3, -1e-3, -1e-3, 2e-3, 0.0, 0.5e-3;
  s = evaluate(m, s, e, temperature).trial;
  e << 2e-3, -0.5e-3, -1.2e-3, 4e-3, 1e-3, -0.5e-3;
  return evaluate(m, s, e, temperature).trial;
}

void check_tangent(const CP& m, bool symmetric_exact, double temperature = 0.0) {
  const std::vector<double> c = history(m, temperature);
  ASSERT_GT(c[CP::kEquivalent], 1e-4);
  Vec6 e;
  e << 3.5e-3, -0.2e-3, -1.5e-3, 5e-3, 0.8e-3, 0.2e-3;
  const Eval base = evaluate(m, c, e, temperature);
  ASSERT_GT(base.trial[CP::kEquivalent], c[CP::kEquivalent]);
  Mat6 fd;
  const double h = 1e-8;
  for (int j = 0; j < 6; ++j)
    fd.col(j) = (evaluate(m, c, e + h * Vec6::Unit(j), temperature).stress -
                 evaluate(m, c, e - h * Vec6::Unit(j), temperature).stress) / (2 * h);
  const double scale = fd.cwiseAbs().maxCoeff();
  const Mat6 sym = 0.5 * (fd + fd.transpose());
  EXPECT_LT((base.tangent - sym).cwiseAbs().maxCoeff(), 1e-6 * scale);
  if (symmetric_exact) EXPECT_LT((fd - fd.transpose()).cwiseAbs().maxCoeff(), 1e-6 * scale);
  else EXPECT_GT((fd - fd.transpose()).cwiseAbs().maxCoeff(), 1e-4 * scale);  // the dropped skew part exists
}

}  // namespace

TEST(CombinedPlasticity, TangentIsTheSymmetricPartOfCentralDifferences) { check_tangent(CP(kElastic, chaboche()), false); }

TEST(CombinedPlasticity, WithoutRecoveryTheTangentIsExactAndSymmetric) {
  CombinedHardening h = chaboche();
  for (auto& b : h.backstresses) b.recovery = 0.0;
  check_tangent(CP(kElastic, h), true);
}

// γ = 0, one backstress, a constant surface: Prager–Ziegler, MisesPlasticity's KINEMATIC law
// (σ⁰ = 250, C = (300 − 250)/0.02 = 2500), whose state has the same layout with α = C β.
TEST(CombinedPlasticity, LinearKinematicCaseIsMisesKinematicHardening) {
  CombinedHardening h;
  h.backstresses = {{2500.0, 0.0}};
  h.initial = kS0;
  const CP combined(kElastic, h);
  const MisesPlasticity mises_law(kElastic, {true, {0.0, 0.02}, {kS0, 300.0}});
  ASSERT_EQ(combined.state_size(), mises_law.state_size());
  const std::vector<double> c = history(combined);
  std::vector<double> c_mises = c;
  for (std::size_t k = CP::kBackstress; k < c.size(); ++k) c_mises[k] *= 2500.0;
  Vec6 e;
  e << 1e-3, 2.5e-3, -1.5e-3, -3e-3, 0.8e-3, 0.2e-3;
  const Eval a = evaluate(combined, c, e), b = evaluate(mises_law, c_mises, e);
  EXPECT_LT((a.stress - b.stress).cwiseAbs().maxCoeff(), 1e-10 * kS0);
  EXPECT_LT((a.tangent - b.tangent).cwiseAbs().maxCoeff(), 1e-10 * kE);
  for (std::size_t k = 0; k < a.trial.size(); ++k)
    EXPECT_NEAR(a.trial[k] * (k >= CP::kBackstress ? 2500.0 : 1.0), b.trial[k], 1e-12) << k;
}

TEST(CombinedPlasticity, NeverWritesTheCommittedState) {
  const CP m(kElastic, chaboche());
  const std::vector<double> c = history(m);
  const std::vector<double> copy = c;
  Vec6 e;
  e << 6e-3, -2e-3, -2e-3, 1e-3, 0.0, 0.0;
  evaluate(m, c, e);
  EXPECT_EQ(c, copy);
}

namespace {

/// chaboche() at T = 100 and a hotter, softer set at T = 300 (other C, γ, Voce parameters).
CP two_temperatures() {
  CombinedHardening hot = chaboche();
  hot.backstresses = {{20000.0, 300.0}, {3000.0, 10.0}};
  hot.initial = 150.0, hot.saturation = 40.0, hot.rate = 20.0;
  return CP(kElastic, {chaboche(), hot}, {100.0, 300.0});
}

}  // namespace

// Every parameter linear in T between the sets (the Voce law through its parameters), constant
// outside: checked at T = 150 (a quarter of the way) and beyond both ends.
TEST(CombinedPlasticity, ParametersAreInterpolatedLinearlyInTemperature) {
  const CP m = two_temperatures();
  EXPECT_TRUE(m.temperature_dependent());
  EXPECT_NEAR(m.backstress(0, 150.0).modulus, 0.75 * 40000.0 + 0.25 * 20000.0, 1e-9);
  EXPECT_NEAR(m.backstress(1, 150.0).recovery, 0.75 * 20.0 + 0.25 * 10.0, 1e-12);
  const double q = 0.75 * 80.0 + 0.25 * 40.0, b = 0.75 * 10.0 + 0.25 * 20.0, eq = 0.03;
  EXPECT_NEAR(m.yield_size(eq, nullptr, 150.0), 0.75 * kS0 + 0.25 * 150.0 + q * (1 - std::exp(-b * eq)), 1e-10);
  EXPECT_EQ(m.yield_size(eq, nullptr, 20.0), m.yield_size(eq, nullptr, 100.0));
  EXPECT_EQ(m.backstress(0, 500.0).modulus, 20000.0);
}

// Abaqus's term (1/C)(dC/dT) α Ṫ: heated without plastic flow, α_k = C_k(T) β_k follows C_k.
// A point loaded plastically at T = 100, then evaluated at T = 200 at a strain elastic there:
// the backstress is C(200)/C(100) times the one it had, component by component.
TEST(CombinedPlasticity, TheBackstressIsCarriedWithItsModulusWhenTheTemperatureChanges) {
  const CP m = two_temperatures();
  std::vector<double> state(m.state_size(), 0.0);
  Vec6 e;
  e << 3e-3, -1e-3, -1e-3, 2e-3, 0.0, 0.5e-3;
  state = evaluate(m, state, e, 100.0).trial;
  ASSERT_GT(state[CP::kEquivalent], 1e-4);
  // At the strain that makes σ = α(200) (the centre of the surface there): elastic, state unchanged.
  const Mat6 D = elasticity_matrix(inpact::model::ElementFamily::Solid3D, kElastic);
  const Vec6 centre = Eigen::Map<const Vec6>(state.data() + CP::kPlasticStrain) + D.inverse() * total_backstress(m, state, 200.0);
  const Eval hot = evaluate(m, state, centre, 200.0);
  EXPECT_EQ(hot.trial, state);
  for (std::size_t k = 0; k < 2; ++k) {
    const Eigen::Map<const Vec6> beta(state.data() + CP::kBackstress + 6 * k);
    const double ratio = m.backstress(k, 200.0).modulus / m.backstress(k, 100.0).modulus;
    EXPECT_NE(ratio, 1.0);
    const Vec6 alpha_cold = m.backstress(k, 100.0).modulus * beta, alpha_hot = m.backstress(k, 200.0).modulus * beta;
    EXPECT_LT((alpha_hot - ratio * alpha_cold).cwiseAbs().maxCoeff(), 1e-12 * alpha_cold.cwiseAbs().maxCoeff());
  }
  // And the return there lands on the surface of T = 200: q(σ − α(200)) = σ⁰(ε̄ᵖ, 200).
  const Eval yielded = evaluate(m, state, 1.5 * e, 200.0);
  ASSERT_GT(yielded.trial[CP::kEquivalent], state[CP::kEquivalent]);
  const double surface = m.yield_size(yielded.trial[CP::kEquivalent], nullptr, 200.0);
  EXPECT_NEAR(mises(deviator(yielded.stress) - total_backstress(m, yielded.trial, 200.0)), surface, 1e-10 * surface);
}

TEST(CombinedPlasticity, TangentBetweenTemperaturesIsTheSymmetricPartOfCentralDifferences) {
  check_tangent(two_temperatures(), false, 180.0);
}
