// The half-cycle fit of combined hardening (solver/elements/half_cycle_fit.hpp): data sampled
// from α = C/γ (1 − e^{−γε}) + α_1 e^{−γε} give back C and γ; two rows give the linear law;
// linear data give γ = 0; noisy data give the least-squares optimum (no better γ nearby).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "solver/elements/half_cycle_fit.hpp"

using inpact::solver::elements::fit_half_cycle;

namespace {

std::vector<double> sampled(const std::vector<double>& eq, double C, double g, double alpha1) {
  std::vector<double> a;
  for (double e : eq) a.push_back(C / g * (1 - std::exp(-g * e)) + alpha1 * std::exp(-g * e));
  return a;
}

const std::vector<double> kStrains{0.0, 0.001, 0.0025, 0.005, 0.01, 0.02, 0.05};

}  // namespace

TEST(HalfCycleFit, RecoversTheCurveTheDataWereSampledFrom) {
  for (auto [C, g, a1] : {std::tuple{40000.0, 400.0, 0.0}, std::tuple{150000.0, 1500.0, 0.0},
                          std::tuple{8000.0, 20.0, 0.0}, std::tuple{40000.0, 400.0, -30.0}}) {
    const auto fit = fit_half_cycle(kStrains, sampled(kStrains, C, g, a1));
    EXPECT_NEAR(fit.modulus, C, 1e-7 * C) << C << " " << g << " " << a1;
    EXPECT_NEAR(fit.recovery, g, 1e-7 * g) << C << " " << g << " " << a1;
    EXPECT_LT(fit.rms, 1e-9 * C / g);
  }
}

TEST(HalfCycleFit, TwoRowsOrLinearDataGiveLinearKinematicHardening) {
  const auto two = fit_half_cycle(std::vector<double>{0.0, 0.01}, std::vector<double>{0.0, 50.0});
  EXPECT_EQ(two.recovery, 0.0);
  EXPECT_NEAR(two.modulus, 5000.0, 1e-9);
  std::vector<double> linear;
  for (double e : kStrains) linear.push_back(5000.0 * e);
  const auto fit = fit_half_cycle(kStrains, linear);
  EXPECT_EQ(fit.recovery, 0.0);
  EXPECT_NEAR(fit.modulus, 5000.0, 1e-9);
}

TEST(HalfCycleFit, NoisyDataGiveTheLeastSquaresOptimum) {
  std::vector<double> a = sampled(kStrains, 40000.0, 400.0, 0.0);
  for (std::size_t i = 1; i < a.size(); ++i) a[i] += (i % 2 ? 1.5 : -1.0);
  const auto fit = fit_half_cycle(kStrains, a);
  auto sum_of_squares = [&](double C, double g) {
    double s = 0;
    for (std::size_t i = 1; i < a.size(); ++i) s += std::pow(a[i] - C / g * (1 - std::exp(-g * kStrains[i])), 2);
    return s;
  };
  const double best = sum_of_squares(fit.modulus, fit.recovery);
  EXPECT_NEAR(std::sqrt(best / 6.0), fit.rms, 1e-9);
  for (double dC : {-1e-3, 1e-3})
    for (double dg : {-1e-3, 0.0, 1e-3})
      EXPECT_GE(sum_of_squares(fit.modulus * (1 + dC), fit.recovery * (1 + dg)), best);
  EXPECT_NEAR(fit.recovery, 400.0, 0.1 * 400.0);
}
