// The finite-strain Mises kernel alone (solver/elements/finite_strain_mises.hpp): the material
// tangent ∂S/∂E against central differences at a plastic point with plastic history, objectivity
// under a 90° rotation, the uniaxial closed form at large strain (one increment and many), Hencky
// elasticity below yield, and the state contract (committed state read only, Cᵖ⁻¹ = I at start).
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "finite_strain_fixtures.hpp"

#include "solver/elements/finite_strain_mises.hpp"

using namespace inpact::solver::elements;
using Mat3 = Eigen::Matrix3d;
using namespace inpact::test::finite_strain;

namespace {

constexpr double kE = 200000.0, kNu = 0.3, kSy = 250.0, kH = 1000.0;
const ElasticConstants kElastic{kE, kNu, 0.0};

/// Linear hardening σ_y = 250 + 1000 ε̄ᵖ, tabulated far enough to stay linear.
FiniteStrainMises material() { return FiniteStrainMises(kElastic, {false, {0.0, 10.0}, {kSy, kSy + 10 * kH}}); }

Mat3 rotation_z(double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

}  // namespace

TEST(FiniteStrainMises, TangentMatchesCentralDifferencesAtAPlasticPoint) {
  const FiniteStrainMises m = material();
  const std::vector<double> committed = plastic_history(m);
  ASSERT_GT(committed[FiniteStrainMises::kEquivalent], 1e-3);
  // Further loading with a rotation R: F = R U.
  Mat3 F0 = Mat3::Identity();
  F0(0, 0) = 1.05, F0(0, 1) = 0.06, F0(1, 2) = -0.02, F0(1, 1) = 0.985, F0(2, 2) = 0.99;
  const Mat3 R = rotation_z(0.4) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Mat3 F = R * F0;
  const Eval base = evaluate(m, committed, F);
  ASSERT_GT(base.trial[FiniteStrainMises::kEquivalent], committed[FiniteStrainMises::kEquivalent]);
  const Mat3 Eb = 0.5 * (F.transpose() * F - Mat3::Identity());
  Vec6 E;
  E << Eb(0, 0), Eb(1, 1), Eb(2, 2), 2 * Eb(0, 1), 2 * Eb(0, 2), 2 * Eb(1, 2);
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    // S depends on C only: perturb E and rebuild F = R √C.
    const Vec6 ep = E + h * Vec6::Unit(j), em = E - h * Vec6::Unit(j);
    const Vec6 dS = (evaluate(m, committed, R * stretch_of(ep)).stress - evaluate(m, committed, R * stretch_of(em)).stress) / (2 * h);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(base.tangent(i, j), dS(i), 1e-6 * base.tangent.cwiseAbs().maxCoeff()) << i << "," << j;
  }
  // A potential exists (τ is Kirchhoff): the tangent is symmetric.
  EXPECT_LT((base.tangent - base.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-8 * base.tangent.cwiseAbs().maxCoeff());
}

TEST(FiniteStrainMises, ObjectiveUnderANinetyDegreeRotation) {
  const FiniteStrainMises m = material();
  const std::vector<double> committed = plastic_history(m);
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.08, F(0, 1) = 0.05, F(1, 1) = 0.97;
  const Eval a = evaluate(m, committed, F);
  const Eval b = evaluate(m, committed, rotation_z(M_PI / 2) * F);
  EXPECT_LT((a.stress - b.stress).cwiseAbs().maxCoeff(), 1e-10 * a.stress.cwiseAbs().maxCoeff());
  EXPECT_LT((a.tangent - b.tangent).cwiseAbs().maxCoeff(), 1e-10 * a.tangent.cwiseAbs().maxCoeff());
  for (std::size_t k = FiniteStrainMises::kEquivalent; k < a.trial.size(); ++k) EXPECT_NEAR(a.trial[k], b.trial[k], 1e-13);
}

namespace {

/// The uniaxial closed form: at ε̄ᵖ, τ11 = σ_y = 250 + 1000 ε̄ᵖ, εᵉ = τ/E (1, −ν, −ν), and
/// LE = εᵉ + ε̄ᵖ (1, −½, −½): the stretches that produce it.
Mat3 uniaxial_stretch(double eq, double& tau) {
  tau = kSy + kH * eq;
  Mat3 F = Mat3::Zero();
  F(0, 0) = std::exp(tau / kE + eq);
  F(1, 1) = F(2, 2) = std::exp(-kNu * tau / kE - eq / 2);
  return F;
}

}  // namespace

TEST(FiniteStrainMises, UniaxialClosedFormAtLargeStrainInOneAndInManyIncrements) {
  const FiniteStrainMises m = material();
  double tau = 0.0;
  const Mat3 F = uniaxial_stretch(0.4, tau);  // LE11 ≈ 0.40
  const Eval one = evaluate(m, initial(m), F);
  EXPECT_NEAR(one.stress(0) * F(0, 0) * F(0, 0), tau, 1e-12 * tau);  // S11 = τ11 / λ1²
  EXPECT_NEAR(one.stress(1), 0.0, 1e-12 * tau);
  EXPECT_NEAR(one.stress(2), 0.0, 1e-12 * tau);
  EXPECT_NEAR(one.trial[FiniteStrainMises::kEquivalent], 0.4, 1e-14);
  EXPECT_NEAR(one.trial[FiniteStrainMises::kPlasticStrain + 0], 0.4, 1e-14);  // PE11
  EXPECT_NEAR(one.trial[FiniteStrainMises::kPlasticStrain + 1], -0.2, 1e-14);
  // Proportional: twenty increments along the same path end in the same state.
  std::vector<double> state = initial(m);
  Eval step;
  for (int k = 1; k <= 20; ++k) {
    double t = 0.0;
    step = evaluate(m, state, uniaxial_stretch(0.4 * k / 20, t));
    state = step.trial;
  }
  EXPECT_NEAR(step.stress(0), one.stress(0), 1e-11 * one.stress(0));
  for (std::size_t k = 0; k < state.size(); ++k) EXPECT_NEAR(state[k], one.trial[k], 1e-12) << k;
}

TEST(FiniteStrainMises, BelowYieldItIsHenckyElasticity) {
  const FiniteStrainMises m = material();
  Mat3 U = Mat3::Identity();
  U(0, 0) = 1.0006, U(1, 1) = 0.9998, U(0, 1) = U(1, 0) = 0.0002;
  const Mat3 F = rotation_z(1.1) * U;  // large rotation, small strain
  const Eval e = evaluate(m, initial(m), F);
  // τ = λ tr(ln V) I + 2μ ln V with ln V = R ln U Rᵀ; S = F⁻¹ τ F⁻ᵀ = U⁻¹ (ln U-based τ) U⁻¹.
  Eigen::SelfAdjointEigenSolver<Mat3> eig(U);
  const Mat3 lnU = eig.eigenvectors() * eig.eigenvalues().array().log().matrix().asDiagonal() * eig.eigenvectors().transpose();
  const double mu = kE / (2 * (1 + kNu)), lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
  const Mat3 tau = lambda * lnU.trace() * Mat3::Identity() + 2 * mu * lnU;
  const Mat3 S = U.inverse() * tau * U.inverse();
  const Vec6 expected = (Vec6() << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(0, 2), S(1, 2)).finished();
  EXPECT_LT((e.stress - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
  EXPECT_EQ(e.trial[FiniteStrainMises::kEquivalent], 0.0);
}

TEST(FiniteStrainMises, StartsFromTheIdentityAndNeverWritesTheCommittedState) {
  const FiniteStrainMises m = material();
  const std::vector<double> s0 = initial(m);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s0[FiniteStrainMises::kInversePlasticCauchyGreen + k], k < 3 ? 1.0 : 0.0);
  const std::vector<double> committed = plastic_history(m);
  const std::vector<double> copy = committed;
  double tau = 0.0;
  evaluate(m, committed, uniaxial_stretch(0.1, tau));
  EXPECT_EQ(committed, copy);
}
