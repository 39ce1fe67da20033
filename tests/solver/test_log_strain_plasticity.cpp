// The Lagrangian logarithmic-strain wrapper alone (solver/elements/log_strain_plasticity.hpp):
// its tangent ∂S/∂E against central differences at a rotated plastic point with kinematic
// history and at stretches with repeated eigenvalues (the limits of the divided differences),
// objectivity under a 90° rotation, the same answer as the exponential-map law on a path with
// fixed principal axes, and the Bauschinger effect of kinematic hardening in logarithmic strain.
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "finite_strain_fixtures.hpp"

#include "solver/elements/combined_plasticity.hpp"
#include "solver/elements/finite_strain_mises.hpp"
#include "solver/elements/log_divided_difference.hpp"
#include "solver/elements/log_strain_plasticity.hpp"

using namespace inpact::solver::elements;
using Mat3 = Eigen::Matrix3d;
using namespace inpact::test::finite_strain;

namespace {

constexpr double kE = 200000.0, kNu = 0.3, kSy = 250.0, kC = 1000.0;
const ElasticConstants kElastic{kE, kNu, 0.0};

/// Linear kinematic hardening, C = 1000, in the logarithmic strain.
LogStrainPlasticity kinematic() {
  return LogStrainPlasticity(std::make_shared<MisesPlasticity>(kElastic, MisesHardening{true, {0.0, 10.0}, {kSy, kSy + 10 * kC}}));
}

/// max |tangent − central differences of S| relative to the tangent's largest entry.
double tangent_error(const Material& m, const std::vector<double>& committed, const Mat3& F) {
  const Eval base = evaluate(m, committed, F);
  const Vec6 E = green_lagrange(F);
  const double h = 1e-7;
  Mat6 fd;
  for (int j = 0; j < 6; ++j)
    fd.col(j) = (evaluate(m, committed, stretch_of(E + h * Vec6::Unit(j))).stress -
                 evaluate(m, committed, stretch_of(E - h * Vec6::Unit(j))).stress) / (2 * h);
  return (fd - base.tangent).cwiseAbs().maxCoeff() / base.tangent.cwiseAbs().maxCoeff();
}

}  // namespace

TEST(LogDividedDifference, SecondDifferenceMatchesItsDefinitionAndItsLimits) {
  // Well separated: the definition itself.
  EXPECT_NEAR(log_second_divided_difference(3.0, 2.0, 1.0), ((std::log(3) - std::log(2)) - (std::log(2) - 0.0)) / 2.0, 1e-15);
  // Coincident: ln'' / 2 = −1/(2x²), and symmetric in its arguments.
  EXPECT_NEAR(log_second_divided_difference(2.0, 2.0, 2.0), -0.125, 1e-15);
  // Near-coincident: the expansion about x = 1.3 as reference, ln''/2 + ln'''/6 h1 + ln''''/24 h2
  // (h_k the complete symmetric polynomials of the deviations; the rest is below 1e-10).
  for (double d : {1e-3, 1e-5, 1e-7}) {
    const double x = 1.3, a = x + d, b = x, c = x - 0.5 * d;
    const double da = a - x, dc = c - x;
    const double h1 = da + dc, h2 = da * da + dc * dc + da * dc;
    const double reference = -1 / (2 * x * x) + h1 / (3 * x * x * x) - h2 / (4 * x * x * x * x);
    EXPECT_NEAR(log_second_divided_difference(a, b, c), reference, 1e-9 * std::abs(reference)) << d;
    EXPECT_EQ(log_second_divided_difference(a, b, c), log_second_divided_difference(c, a, b));
  }
}

TEST(LogStrainPlasticity, TangentMatchesCentralDifferencesAtARotatedPlasticPoint) {
  const LogStrainPlasticity m = kinematic();
  const std::vector<double> committed = plastic_history(m);
  ASSERT_GT(committed[MisesStateLayout::equivalent], 1e-3);
  Mat3 U = Mat3::Identity();
  U(0, 0) = 1.05, U(0, 1) = 0.06, U(1, 2) = -0.02, U(1, 1) = 0.985, U(2, 2) = 0.99;
  const Mat3 R = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                 Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Mat3 F = R * U;
  ASSERT_GT(evaluate(m, committed, F).trial[MisesStateLayout::equivalent], committed[MisesStateLayout::equivalent]);
  const double err = tangent_error(m, committed, F);
  std::printf("[log-strain] tangent vs central differences at a rotated plastic point: %.2e\n", err);
  EXPECT_LT(err, 1e-6);
}

TEST(LogStrainPlasticity, TangentIsRightWhereStretchesCoincide) {
  const LogStrainPlasticity m = kinematic();
  Mat3 uniaxial = Mat3::Identity();  // two equal eigenvalues, plastic from the virgin state
  uniaxial(0, 0) = 1.3, uniaxial(1, 1) = uniaxial(2, 2) = 0.88;
  EXPECT_LT(tangent_error(m, initial(m), uniaxial), 1e-6);
  EXPECT_LT(tangent_error(m, initial(m), Mat3::Identity()), 1e-6);  // three equal: the elastic D
  EXPECT_LT(tangent_error(m, plastic_history(m), Mat3::Identity() * 1.0000001), 1e-6);
}

TEST(LogStrainPlasticity, ObjectiveUnderANinetyDegreeRotation) {
  const LogStrainPlasticity m = kinematic();
  const std::vector<double> committed = plastic_history(m);
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.08, F(0, 1) = 0.05, F(1, 1) = 0.97;
  const Eval a = evaluate(m, committed, F);
  const Eval b = evaluate(m, committed, Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix() * F);
  EXPECT_LT((a.stress - b.stress).cwiseAbs().maxCoeff(), 1e-10 * a.stress.cwiseAbs().maxCoeff());
  for (std::size_t k = 0; k < a.trial.size(); ++k) EXPECT_NEAR(a.trial[k], b.trial[k], 1e-13) << k;
}

// With fixed principal axes the logarithmic strain is ln V of the exponential-map law and T its
// Kirchhoff stress: isotropic hardening through the wrapper equals FiniteStrainMises.
TEST(LogStrainPlasticity, EqualsTheExponentialMapLawWithFixedPrincipalAxes) {
  const MisesHardening h{false, {0.0, 0.05, 10.0}, {kSy, 300.0, 400.0}};
  const LogStrainPlasticity wrapped(std::make_shared<MisesPlasticity>(kElastic, h));
  const FiniteStrainMises simo(kElastic, h);
  std::vector<double> a = initial(wrapped), b = initial(simo);
  for (int k = 1; k <= 10; ++k) {
    Mat3 F = Mat3::Zero();
    F(0, 0) = 1 + 0.04 * k, F(1, 1) = 1 - 0.01 * k, F(2, 2) = 1 - 0.013 * k;
    const Eval ea = evaluate(wrapped, a, F), eb = evaluate(simo, b, F);
    EXPECT_LT((ea.stress - eb.stress).cwiseAbs().maxCoeff(), 1e-10 * kSy) << "increment " << k;
    EXPECT_NEAR(ea.trial[MisesStateLayout::equivalent], eb.trial[FiniteStrainMises::kEquivalent], 1e-14);
    a = ea.trial, b = eb.trial;
  }
  EXPECT_GT(a[MisesStateLayout::equivalent], 0.1);
}

// Chaboche hardening wrapped the same way: its tangent is the symmetric part of the consistent
// one (combined_plasticity.hpp), exact with γ = 0.
TEST(LogStrainPlasticity, WrapsCombinedHardening) {
  CombinedHardening h;
  h.backstresses = {{kC, 0.0}};
  h.initial = kSy;
  const LogStrainPlasticity m(std::make_shared<CombinedPlasticity>(kElastic, h));
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.05, F(0, 1) = 0.04, F(1, 1) = 0.98;
  EXPECT_LT(tangent_error(m, plastic_history(m), F), 1e-6);
}
