// The Mises plasticity kernel alone (solver/elements/mises_plasticity.hpp): the consistent
// tangent against central differences of the return, the return on the yield surface, the
// uniaxial closed form of linear hardening through loading and unloading, the table's
// piecewise-linear hardening, and the state contract (the committed state is read only).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "solver/elements/mises_plasticity.hpp"

using namespace inpact::solver::elements;
using L = MisesStateLayout;

namespace {

constexpr double kE = 200000.0, kNu = 0.3, kSy = 250.0;
const ElasticConstants kElastic{kE, kNu, 0.0};

/// A table: σ_y = 250 → 350 over ε̄ᵖ 0 → 0.01, → 400 at 0.05, constant beyond.
MisesHardening table_hardening() { return {false, {0.0, 0.01, 0.05}, {kSy, 350.0, 400.0}}; }
/// Linear kinematic: C = (300 − 250)/0.02 = 2500.
MisesHardening kinematic_hardening() { return {true, {0.0, 0.02}, {kSy, 300.0}}; }

struct Eval {
  Vec6 stress;
  Mat6 tangent;
  std::vector<double> trial;
};

Eval evaluate(const Material& m, const std::vector<double>& committed, const Vec6& strain, double thermal = 0.0,
              double temperature = 0.0) {
  Eval e;
  e.trial.assign(committed.size(), -1.0);
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Mat6 scratch;
  MaterialPointInput in{F, strain, thermal};
  in.temperature = temperature;
  e.tangent = m.update(in, {committed, e.trial}, e.stress, scratch);
  return e;
}

/// q(σ − α) of a stress and a state.
double mises_of(const Vec6& stress, const std::vector<double>& state, bool kinematic) {
  Vec6 xi = stress;
  const double mean = (stress(0) + stress(1) + stress(2)) / 3;
  xi.head<3>().array() -= mean;
  if (kinematic) xi -= Eigen::Map<const Vec6>(state.data() + L::backstress);
  return std::sqrt(1.5 * (xi.head<3>().squaredNorm() + 2 * xi.tail<3>().squaredNorm()));
}

/// A committed state with some plastic history (εᵖ deviatoric, ε̄ᵖ, α), as a load path leaves.
std::vector<double> prior_state(const MisesPlasticity& m, bool kinematic) {
  std::vector<double> s(m.state_size(), 0.0);
  const double ep[6] = {1.0e-3, -0.3e-3, -0.7e-3, 0.8e-3, -0.2e-3, 0.5e-3};
  for (int i = 0; i < 6; ++i) s[L::plastic_strain + i] = ep[i];
  s[L::equivalent] = 0.004;
  if (kinematic) {
    const double a[6] = {6.0, -2.0, -4.0, 3.0, -1.0, 1.5};
    for (int i = 0; i < 6; ++i) s[L::backstress + i] = a[i];
  }
  return s;
}

// A strain well past yield from the prior state, not symmetric in any plane.
const Vec6 kStrain = (Vec6() << 3.1e-3, -0.9e-3, -0.4e-3, 2.6e-3, -0.8e-3, 1.7e-3).finished();

void expect_tangent_matches_differences(const MisesPlasticity& m, const std::vector<double>& committed,
                                        const Vec6& strain = kStrain, double temperature = 0.0) {
  const Eval base = evaluate(m, committed, strain, 0.0, temperature);
  ASSERT_GT(base.trial[L::equivalent], committed[L::equivalent]);  // the point yields
  // Central differences inside one smooth piece of the return: truncation O(h²) and round-off
  // |σ| ε_machine / h ≈ 400 · 2e-16 / 1e-8 ≈ 1e-5 against entries ~1e5, i.e. ~1e-10 relative;
  // the tolerance is 1e-6 of the largest entry.
  const double h = 1e-8;
  Mat6 fd;
  for (int j = 0; j < 6; ++j) {
    Vec6 plus = strain, minus = strain;
    plus(j) += h;
    minus(j) -= h;
    fd.col(j) = (evaluate(m, committed, plus, 0.0, temperature).stress -
                 evaluate(m, committed, minus, 0.0, temperature).stress) / (2 * h);
  }
  const double scale = base.tangent.cwiseAbs().maxCoeff();
  const double err = (fd - base.tangent).cwiseAbs().maxCoeff() / scale;
  std::printf("[mises] tangent vs central differences: %.2e relative\n", err);
  EXPECT_LE(err, 1e-6) << "tangent\n" << base.tangent << "\ndifferences\n" << fd;
  // The consistent tangent is symmetric (associated flow) and softer than D.
  EXPECT_LE((base.tangent - base.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_LT(base.tangent(0, 0), m.D()(0, 0));
}

}  // namespace

TEST(MisesPlasticity, StateSizeIsSevenOrThirteenWithBackstress) {
  EXPECT_EQ(MisesPlasticity(kElastic, table_hardening()).state_size(), 7u);
  EXPECT_EQ(MisesPlasticity(kElastic, kinematic_hardening()).state_size(), 13u);
  EXPECT_EQ(MisesPlasticity(kElastic, table_hardening()).as_isotropic_elastic(), nullptr);
}

TEST(MisesPlasticity, TangentIsTheCentralDifferenceOfTheReturn) {
  for (const bool kinematic : {false, true}) {
    SCOPED_TRACE(kinematic ? "kinematic" : "isotropic table");
    const MisesPlasticity m(kElastic, kinematic ? kinematic_hardening() : table_hardening());
    expect_tangent_matches_differences(m, prior_state(m, kinematic));
    expect_tangent_matches_differences(m, std::vector<double>(m.state_size(), 0.0));
  }
  // Perfect plasticity (one point): θ̄ = θ, the tangent is singular along n but still exact.
  const MisesPlasticity perfect(kElastic, {false, {0.0}, {kSy}});
  expect_tangent_matches_differences(perfect, std::vector<double>(7, 0.0));
}

TEST(MisesPlasticity, ReturnLandsOnTheYieldSurface) {
  for (const bool kinematic : {false, true}) {
    const MisesPlasticity m(kElastic, kinematic ? kinematic_hardening() : table_hardening());
    const auto committed = prior_state(m, kinematic);
    for (double scale : {1.0, 3.0, 20.0}) {  // the last crosses two table segments (ε̄ᵖ beyond 0.05)
      const Eval e = evaluate(m, committed, scale * kStrain);
      const double eq = e.trial[L::equivalent];
      ASSERT_GT(eq, committed[L::equivalent]);
      const double q = mises_of(e.stress, e.trial, kinematic);
      const double sy = m.yield_stress(eq);
      EXPECT_LE(std::abs(q - sy), 1e-10 * sy) << "kinematic " << kinematic << " scale " << scale << ": q " << q;
      // Flow is deviatoric: the volumetric plastic strain stays 0, the pressure elastic.
      const double dv = e.trial[0] + e.trial[1] + e.trial[2] - committed[0] - committed[1] - committed[2];
      EXPECT_LE(std::abs(dv), 1e-15);
      // ε̄ᵖ grows by √(2/3 Δεᵖ:Δεᵖ).
      double dot = 0;
      for (int i = 0; i < 6; ++i) {
        const double d = e.trial[i] - committed[i];
        dot += i < 3 ? d * d : 0.5 * d * d;
      }
      EXPECT_NEAR(std::sqrt(2.0 / 3.0 * dot), eq - committed[L::equivalent], 1e-14);
    }
  }
}

TEST(MisesPlasticity, ElasticStepKeepsTheStateAndTheElasticTangent) {
  const MisesPlasticity m(kElastic, table_hardening());
  const auto committed = prior_state(m, false);
  Vec6 strain;
  for (int i = 0; i < 6; ++i) strain(i) = committed[i];
  strain(0) += 1e-4;  // σ = D (ε − εᵖ): 1e-4 of strain is ≈ 27 MPa, well inside the surface
  const Eval e = evaluate(m, committed, strain);
  EXPECT_EQ(e.trial, committed);
  EXPECT_EQ(e.tangent, m.D());
  Vec6 ee = Vec6::Zero();
  ee(0) = 1e-4;
  EXPECT_LE((e.stress - m.D() * ee).norm(), 1e-12 * e.stress.norm());
}

// The state contract: the committed state is read only, and an evaluation's trial state depends
// on the committed state and the strain alone — evaluating at another strain first (a Newton
// iterate, a failed attempt) leaves no trace.
TEST(MisesPlasticity, TrialStateDependsOnlyOnCommittedStateAndStrain) {
  const MisesPlasticity m(kElastic, kinematic_hardening());
  const auto committed = prior_state(m, true);
  const auto kept = committed;
  const Eval direct = evaluate(m, committed, kStrain);
  std::vector<double> trial(committed.size());
  Vec6 s;
  Mat6 scratch;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  m.update({F, 5.0 * kStrain, 0.0}, {committed, trial}, s, scratch);  // an overshooting iterate
  m.update({F, kStrain, 0.0}, {committed, trial}, s, scratch);
  EXPECT_EQ(trial, direct.trial);
  EXPECT_EQ(s, direct.stress);
  EXPECT_EQ(committed, kept);
}

// A bar in uniaxial stress with linear hardening, loaded then unloaded, point by point: the
// lateral strains found by Newton on σ22 = σ33 = 0 with the kernel's tangent, each load step
// committed. Closed form: past ε_y = σ_y/E, σ = σ_y + E_t (ε − ε_y), E_t = E H/(E + H), and
// εᵖ = (σ − σ_y)/H; unloading is elastic, σ = σ_max − E (ε_max − ε) (down to −127 MPa here,
// inside the surface of radius 372.7).
TEST(MisesPlasticity, UniaxialLinearHardeningLoadingAndUnloading) {
  const double H = 20000.0;  // σ_y = 250 + H ε̄ᵖ
  const MisesPlasticity m(kElastic, {false, {0.0, 0.1}, {kSy, kSy + H * 0.1}});
  const double Et = kE * H / (kE + H);
  EXPECT_NEAR(H, kE * Et / (kE - Et), 1e-9 * H);  // the task's H = E Et/(E − Et)
  std::vector<double> committed(7, 0.0);
  double eps_max = 0, sigma_max = 0, lateral = 0;
  const std::vector<double> path = {0.5e-3, 1.0e-3, 2.0e-3, 4.0e-3, 8.0e-3, 7.0e-3, 5.5e-3};
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double eps = path[k];
    Eval e;
    for (int it = 0; it < 20; ++it) {  // lateral strain ε22 = ε33 so that σ22 = σ33 = 0
      Vec6 strain = Vec6::Zero();
      strain << eps, lateral, lateral, 0, 0, 0;
      e = evaluate(m, committed, strain);
      if (std::abs(e.stress(1)) <= 1e-12 * kSy) break;
      lateral -= e.stress(1) / (e.tangent(1, 1) + e.tangent(1, 2));
    }
    const bool loading = k < 5;
    double exact;
    if (loading) {
      exact = eps <= kSy / kE ? kE * eps : kSy + Et * (eps - kSy / kE);
      eps_max = eps;
      sigma_max = exact;
    } else {
      exact = sigma_max - kE * (eps_max - eps);
    }
    EXPECT_NEAR(e.stress(0), exact, 1e-10 * kSy) << "step " << k << " strain " << eps;
    EXPECT_NEAR(e.stress(1), 0.0, 1e-10 * kSy);
    const double ep_exact = std::max(0.0, (sigma_max - kSy) / H);
    EXPECT_NEAR(e.trial[L::plastic_strain], ep_exact, 1e-14) << "step " << k;
    EXPECT_NEAR(e.trial[L::equivalent], ep_exact, 1e-14) << "step " << k;
    EXPECT_NEAR(e.trial[L::plastic_strain + 1], -0.5 * ep_exact, 1e-14);  // isochoric flow
    committed = e.trial;  // the increment converged: commit
  }
}

TEST(MisesPlasticity, TableIsPiecewiseLinearAndConstantBeyondTheLastPoint) {
  const MisesPlasticity m(kElastic, table_hardening());
  EXPECT_DOUBLE_EQ(m.yield_stress(0.0), 250.0);
  EXPECT_DOUBLE_EQ(m.yield_stress(0.005), 300.0);
  EXPECT_DOUBLE_EQ(m.yield_stress(0.03), 375.0);
  EXPECT_DOUBLE_EQ(m.yield_stress(0.05), 400.0);
  EXPECT_DOUBLE_EQ(m.yield_stress(1.0), 400.0);
  const MisesPlasticity kin(kElastic, kinematic_hardening());
  EXPECT_DOUBLE_EQ(kin.yield_stress(0.5), 250.0);  // kinematic: the surface moves, its size stays σ⁰
}

// Kinematic hardening under a strain reversal: the Bauschinger effect. After tension to σ_max,
// reversed yielding starts at σ_max − 2σ⁰ (the surface of radius σ⁰ centred at α = σ_max − σ⁰,
// in uniaxial terms) — not at −σ_max as isotropic hardening would have it.
TEST(MisesPlasticity, KinematicHardeningReversesYieldAtTwiceTheInitialYieldStress) {
  const MisesPlasticity m(kElastic, kinematic_hardening());
  const double C = 2500.0, Et = kE * C / (kE + C);
  std::vector<double> committed(13, 0.0);
  double lateral = 0;
  auto uniaxial = [&](double eps) {
    Eval e;
    for (int it = 0; it < 20; ++it) {
      Vec6 strain;
      strain << eps, lateral, lateral, 0, 0, 0;
      e = evaluate(m, committed, strain);
      if (std::abs(e.stress(1)) <= 1e-12 * kSy) break;
      lateral -= e.stress(1) / (e.tangent(1, 1) + e.tangent(1, 2));
    }
    committed = e.trial;
    return e.stress(0);
  };
  const double eps_max = 5e-3;
  const double s_max = uniaxial(eps_max);
  EXPECT_NEAR(s_max, kSy + Et * (eps_max - kSy / kE), 1e-9 * kSy);
  // Reverse by 2σ⁰/E − a little: still elastic; then by 2σ⁰/E plus 1e-3: reversed plastic flow.
  const double back = 2 * kSy / kE;
  EXPECT_NEAR(uniaxial(eps_max - 0.99 * back), s_max - 0.99 * 2 * kSy, 1e-9 * kSy);
  const double s_rev = uniaxial(eps_max - back - 1e-3);
  EXPECT_NEAR(s_rev, s_max - 2 * kSy - Et * 1e-3, 1e-9 * kSy);
}

// Plane stress: the 3D return inside a local iteration on ε33 (σ33 = 0), the tangent condensed.
TEST(MisesPlasticity, PlaneStressTangentIsTheCentralDifferenceAndSigma33Vanishes) {
  for (const bool kinematic : {false, true}) {
    SCOPED_TRACE(kinematic ? "kinematic" : "isotropic table");
    const MisesPlasticity m(kElastic, kinematic ? kinematic_hardening() : table_hardening(),
                            inpact::model::ElementFamily::PlaneStress);
    ASSERT_EQ(m.state_size(), kinematic ? 14u : 8u);
    std::vector<double> committed(m.state_size(), 0.0);
    const Vec6 strain = (Vec6() << 3.1e-3, -0.9e-3, 0.0, 2.6e-3, 0.0, 0.0).finished();
    const Eval base = evaluate(m, committed, strain);
    const std::size_t thickness = MisesStateLayout::thickness(kinematic);
    ASSERT_GT(base.trial[L::equivalent], 0.0);
    EXPECT_EQ(base.stress(2), 0.0);
    // ε33 = elastic −ν/E (σ11 + σ22) plus the plastic εᵖ33.
    EXPECT_NEAR(base.trial[thickness], -kNu / kE * (base.stress(0) + base.stress(1)) + base.trial[2], 1e-13);
    const double q = mises_of(base.stress, base.trial, kinematic);
    EXPECT_LE(std::abs(q - m.yield_stress(base.trial[L::equivalent])), 1e-9 * kSy);
    const double h = 1e-8;
    Mat6 fd = Mat6::Zero();
    for (int j : {0, 1, 3}) {
      Vec6 plus = strain, minus = strain;
      plus(j) += h;
      minus(j) -= h;
      fd.col(j) = (evaluate(m, committed, plus).stress - evaluate(m, committed, minus).stress) / (2 * h);
    }
    const double err = (fd - base.tangent).cwiseAbs().maxCoeff() / base.tangent.cwiseAbs().maxCoeff();
    std::printf("[mises] plane stress tangent vs central differences: %.2e relative\n", err);
    EXPECT_LE(err, 1e-6) << "tangent\n" << base.tangent << "\ndifferences\n" << fd;
  }
}

// Plane stress uniaxial (σ22 = 0 by Newton on ε22, σ33 = 0 by the kernel): the 1D closed form.
TEST(MisesPlasticity, PlaneStressUniaxialLinearHardening) {
  const double H = 20000.0, Et = kE * H / (kE + H);
  const MisesPlasticity m(kElastic, {false, {0.0, 0.1}, {kSy, kSy + H * 0.1}}, inpact::model::ElementFamily::PlaneStress);
  std::vector<double> committed(8, 0.0);
  double lateral = 0;
  for (double eps : {1.0e-3, 2.0e-3, 5.0e-3}) {
    Eval e;
    for (int it = 0; it < 30; ++it) {
      Vec6 strain = Vec6::Zero();
      strain << eps, lateral, 0, 0, 0, 0;
      e = evaluate(m, committed, strain);
      if (std::abs(e.stress(1)) <= 1e-12 * kSy) break;
      lateral -= e.stress(1) / e.tangent(1, 1);
    }
    const double exact = eps <= kSy / kE ? kE * eps : kSy + Et * (eps - kSy / kE);
    EXPECT_NEAR(e.stress(0), exact, 1e-9 * kSy) << eps;
    EXPECT_NEAR(e.trial[L::equivalent], std::max(0.0, (exact - kSy) / H), 1e-13) << eps;
    committed = e.trial;
  }
}

namespace {

/// Two temperatures: at 20, 250 → 300 over ε̄ᵖ 0 → 0.1; at 400, 150 → 160 at 0.02 → 200 at 0.2.
MisesHardening two_temperatures() {
  using Point = inpact::model::Plastic::Point;
  const std::vector<Point> rows = {{250.0, 0.0, 20.0}, {300.0, 0.1, 20.0},
                                   {150.0, 0.0, 400.0}, {160.0, 0.02, 400.0}, {200.0, 0.2, 400.0}};
  return isotropic_hardening(rows);
}

/// σ_y of the data by hand: each temperature's curve at ε̄ᵖ, then linear in T between them.
double by_hand(double eq, double temperature) {
  const double low = eq >= 0.1 ? 300.0 : 250.0 + 500.0 * eq;
  const double high = eq >= 0.2 ? 200.0 : eq <= 0.02 ? 150.0 + 500.0 * eq : 160.0 + (eq - 0.02) * 40.0 / 0.18;
  const double s = std::clamp((temperature - 20.0) / 380.0, 0.0, 1.0);
  return (1 - s) * low + s * high;
}

}  // namespace

// *PLASTIC with a temperature column: one strain grid for both curves, the yield stress the
// bilinear interpolation of the data, constant outside the temperature range.
TEST(MisesPlasticity, TemperatureTablesInterpolateLinearlyAtEqualPlasticStrain) {
  const MisesHardening h = two_temperatures();
  EXPECT_EQ(h.plastic_strain, (std::vector<double>{0.0, 0.02, 0.1, 0.2}));
  EXPECT_EQ(h.temperatures, (std::vector<double>{20.0, 400.0}));
  ASSERT_EQ(h.yield_stress.size(), 8u);
  const MisesPlasticity m(kElastic, h);
  EXPECT_TRUE(m.temperature_dependent());
  for (double T : {-50.0, 20.0, 100.0, 210.0, 399.0, 400.0, 900.0})
    for (double eq : {0.0, 0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.5})
      EXPECT_NEAR(m.yield_stress(eq, T), by_hand(eq, T), 1e-12 * kSy) << "T " << T << " eq " << eq;
  EXPECT_FALSE(MisesPlasticity(kElastic, table_hardening()).temperature_dependent());
}

// The return at a point's temperature lands on that temperature's surface, and its tangent is
// the central difference of the return there.
TEST(MisesPlasticity, ReturnAtATemperatureLandsOnItsSurfaceWithTheConsistentTangent) {
  const MisesPlasticity m(kElastic, two_temperatures());
  const std::vector<double> committed = prior_state(m, false);
  const Vec6 strain = (Vec6() << 4.0e-3, -1.2e-3, -0.9e-3, 2.2e-3, -0.8e-3, 1.1e-3).finished();
  const double T = 250.0;
  const Eval base = evaluate(m, committed, strain, 0.0, T);
  ASSERT_GT(base.trial[L::equivalent], committed[L::equivalent]);
  EXPECT_NEAR(mises_of(base.stress, base.trial, false), by_hand(base.trial[L::equivalent], T), 1e-10 * kSy);
  expect_tangent_matches_differences(m, committed, strain, T);
}
