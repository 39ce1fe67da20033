// The pressure-overclosure laws (contact/pressure_overclosure/, built through
// contact::PressureOverclosure::from as the solver builds them): each law's p(h) against hand
// computations (below h_zero, at the kinks, beyond the last tabular point), dp/dh against central
// finite differences, the inverse h(p) against the law, max_slope and h_zero; the
// augmented-Lagrange shift of the linear penalty and the continuity of the nonlinear penalty.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "contact/pressure_overclosure.hpp"

namespace inpact::test {
namespace {

using contact::PressureOverclosure;
using contact::PressureValue;
using contact::ResolvedNormalBehavior;
using model::EnforcementMethod;
using Kind = PressureOverclosure::Kind;
using LawType = model::PressureOverclosure;

constexpr double kKe = 2.0e5;  // underlying element stiffness (unused when the deck gives k)
constexpr double kLChar = 1.0;

/// Hard contact with a penalty-type method and the deck's stiffness `k` and clearance `c0`.
PressureOverclosure penalty(EnforcementMethod method, double k, double c0) {
  ResolvedNormalBehavior r;
  r.method = method;
  r.given_stiffness = k;
  r.deck.clearance_at_zero_pressure = c0;
  return PressureOverclosure::from(r, kKe, kLChar);
}

/// A softened (directly enforced) law of `type`, its data set by `fill`.
template <class Fill>
PressureOverclosure softened(LawType type, Fill fill) {
  ResolvedNormalBehavior r;
  r.law = type;
  r.deck.pressure_overclosure = type;
  fill(r.deck);
  return PressureOverclosure::from(r, kKe, kLChar);
}

// Linear penalty k = 1000, c0 = 0.01. Nonlinear penalty: K_f = 1e4, K_i = 0.01 K_f = 100,
// c0 = 0.002, s_d = 0.03 L_char, s_e = s_d / 3 = 0.01 (Abaqus's defaults, L_char = 1).
PressureOverclosure linear_penalty() { return penalty(EnforcementMethod::PenaltyLinear, 1000.0, 0.01); }
PressureOverclosure nonlinear_penalty() { return penalty(EnforcementMethod::PenaltyNonlinear, 1e4, 0.002); }
PressureOverclosure exponential() {  // c0 = 0.01, p0 = 10
  return softened(LawType::Exponential, [](model::SurfaceBehavior& b) {
    b.exponential_c0 = 0.01;
    b.exponential_p0 = 10.0;
  });
}
PressureOverclosure linear_softened() {  // k = 500
  return softened(LawType::Linear, [](model::SurfaceBehavior& b) { b.linear_slope = 500.0; });
}
PressureOverclosure tabular() {  // (p, h) = (0, −0.005), (2, 0), (12, 0.01): slopes 400, 1000
  return softened(LawType::Tabular, [](model::SurfaceBehavior& b) { b.table = {{0, -0.005}, {2, 0}, {12, 0.01}}; });
}
PressureOverclosure tied() {  // k = 1e6
  return softened(LawType::Tied, [](model::SurfaceBehavior& b) { b.tied_slope = 1e6; });
}

/// p, dp/dh and activity of `law` at h (λ = `lambda`) equal the hand values (relative 1e-14).
void expect_value(const PressureOverclosure& law, double h, double p, double dp, bool active, double lambda = 0.0) {
  const PressureValue v = law.eval(h, lambda);
  EXPECT_NEAR(v.p, p, 1e-14 * std::abs(p) + 1e-300) << law.describe() << " at h = " << h << ", λ = " << lambda;
  EXPECT_NEAR(v.dp, dp, 1e-14 * std::abs(dp)) << law.describe() << " at h = " << h << ", λ = " << lambda;
  EXPECT_EQ(v.active, active) << law.describe() << " at h = " << h << ", λ = " << lambda;
}

/// dp/dh at each h of `hs` (none within `step` of a kink) against the central difference with
/// step `step`: relative 1e-6.
void expect_slope_is_the_derivative(const PressureOverclosure& law, const std::vector<double>& hs, double step,
                                    double lambda = 0.0) {
  for (const double h : hs) {
    const double fd = (law.eval(h + step, lambda).p - law.eval(h - step, lambda).p) / (2.0 * step);
    const double dp = law.eval(h, lambda).dp;
    EXPECT_NEAR(dp, fd, 1e-6 * std::abs(dp)) << law.describe() << " at h = " << h << ", λ = " << lambda;
  }
}

/// inverse(p(h)) gives h back (relative 1e-12 of h or of its distance from the law's onset,
/// whichever is larger) and the slope of the law there (relative 1e-12).
void expect_inverse_gives_h_back(const PressureOverclosure& law, const std::vector<double>& hs, double onset,
                                 double lambda = 0.0) {
  for (const double h : hs) {
    const PressureValue v = law.eval(h, lambda);
    ASSERT_GT(v.p, 0.0) << law.describe() << " at h = " << h;
    double h_back = std::nan("");
    const PressureValue w = law.inverse(v.p, lambda, &h_back);
    const double scale = std::max(std::abs(h), std::abs(h - onset));
    EXPECT_NEAR(h_back, h, 1e-12 * scale) << law.describe() << " p = " << v.p << ", λ = " << lambda;
    EXPECT_NEAR(w.p, v.p, 1e-12 * v.p) << law.describe() << " at h = " << h;
    EXPECT_NEAR(w.dp, v.dp, 1e-12 * v.dp) << law.describe() << " at h = " << h;
    EXPECT_TRUE(w.active);
  }
}

TEST(PressureOverclosureFrom, DirectHardContactHasNoLaw) {
  ResolvedNormalBehavior r;  // hard contact, direct enforcement
  EXPECT_THROW(PressureOverclosure::from(r, kKe, kLChar), std::invalid_argument);
}

TEST(PressureOverclosureFrom, MapsEachBehaviourToItsLaw) {
  EXPECT_EQ(linear_penalty().kind(), Kind::LinearPenalty);
  EXPECT_EQ(penalty(EnforcementMethod::AugmentedLagrange, 1000.0, 0.0).kind(), Kind::LinearPenalty);
  EXPECT_EQ(nonlinear_penalty().kind(), Kind::NonlinearPenalty);
  EXPECT_EQ(exponential().kind(), Kind::Exponential);
  EXPECT_EQ(linear_softened().kind(), Kind::Linear);
  EXPECT_EQ(tabular().kind(), Kind::Tabular);
  EXPECT_EQ(tied().kind(), Kind::Tied);
  // stiffness(): linear penalty k, nonlinear K_f, LINEAR and TIED slope, else 0.
  EXPECT_EQ(linear_penalty().stiffness(), 1000.0);
  EXPECT_EQ(nonlinear_penalty().stiffness(), 1e4);
  EXPECT_EQ(exponential().stiffness(), 0.0);
  EXPECT_EQ(linear_softened().stiffness(), 500.0);
  EXPECT_EQ(tabular().stiffness(), 0.0);
  EXPECT_EQ(tied().stiffness(), 1e6);
  // Without a given stiffness: default factor × k_e × scale factor.
  ResolvedNormalBehavior r;
  r.method = EnforcementMethod::PenaltyLinear;
  r.default_factor = 10.0;
  r.scale_factor = 0.5;
  EXPECT_EQ(PressureOverclosure::from(r, kKe, kLChar).stiffness(), 10.0 * kKe * 0.5);
}

TEST(PressureOverclosureFrom, DescribesEachLaw) {
  EXPECT_EQ(linear_penalty().describe(), "linear penalty, k = 1000, c0 = 0.01");
  EXPECT_EQ(nonlinear_penalty().describe(),
            "nonlinear penalty, K_i = 100, K_f = 1e+04, quadratic for 0.01 ≤ h + c0 ≤ 0.03");
  EXPECT_EQ(exponential().describe(), "exponential, c0 = 0.01, p0 = 10");
  EXPECT_EQ(linear_softened().describe(), "linear softened, k = 500");
  EXPECT_EQ(tabular().describe(), "tabular, 3 points");
  EXPECT_EQ(tied().describe(), "tied (CalculiX), k = 1e+06, tension included");
}

// p = k (h + c0) from h = −c0 (touching: active at zero pressure), 0 below.
TEST(LinearPenaltyLaw, IsKTimesOverclosurePlusClearance) {
  const auto law = linear_penalty();
  expect_value(law, -0.02, 0.0, 0.0, false);
  expect_value(law, -0.01, 0.0, 1000.0, true);
  expect_value(law, 0.0, 10.0, 1000.0, true);
  expect_value(law, 0.005, 15.0, 1000.0, true);
  EXPECT_EQ(law.h_zero(), -0.01);
  EXPECT_EQ(law.max_slope(0.0), 1000.0);
  EXPECT_EQ(law.max_slope(1.0), 1000.0);
  expect_slope_is_the_derivative(law, {-0.009, 0.0, 0.3}, 1e-6);
  expect_inverse_gives_h_back(law, {-0.0099, -0.005, 0.0, 0.02, 3.0}, -0.01);
}

// Augmented Lagrange: p = ⟨λ + k (h + c0)⟩, acting where λ + k (h + c0) > 0; the inverse starts
// its bracket at h = −c0 − λ/k.
TEST(LinearPenaltyLaw, AugmentedLagrangeMultiplierShiftsThePressure) {
  const auto law = penalty(EnforcementMethod::AugmentedLagrange, 1000.0, 0.01);
  expect_value(law, -0.012, 3.0, 1000.0, true, 5.0);   // 5 + 1000 (−0.002)
  expect_value(law, -0.016, 0.0, 0.0, false, 5.0);     // 5 − 6 < 0
  expect_value(law, -0.02, 0.0, 0.0, false, 5.0);      // 5 − 10 < 0
  expect_value(law, 0.0, 15.0, 1000.0, true, 5.0);     // 5 + 10
  expect_value(law, 0.0, 7.0, 1000.0, true, -3.0);     // a tensile multiplier: −3 + 10
  expect_value(law, -0.008, 0.0, 0.0, false, -3.0);    // −3 + 2 < 0 although h + c0 > 0
  double h = 0.0;
  const PressureValue v = law.inverse(8.0, 5.0, &h);  // (8 − 5)/1000 − 0.01
  EXPECT_NEAR(h, -0.007, 1e-12 * 0.007);
  EXPECT_NEAR(v.p, 8.0, 1e-12 * 8.0);
  EXPECT_EQ(v.dp, 1000.0);
  expect_slope_is_the_derivative(law, {-0.014, -0.01, 0.1}, 1e-6, 5.0);
  expect_inverse_gives_h_back(law, {-0.0149, -0.012, 0.0, 0.05}, -0.015, 5.0);
}

// s = h + c0: p = K_i s up to s_e = 0.01, quadratic to s_d = 0.03, slope K_f beyond:
// p(s_e) = 1, p(0.02) = 2 + 9900 · 0.01² / 0.04 = 26.75 (slope 100 + 9900/2 = 5050),
// p(s_d) = 3 + 9900 · 0.02² / 0.04 = 102, then 102 + 1e4 (s − 0.03).
TEST(NonlinearPenaltyLaw, IsLinearQuadraticLinearInTheClearance) {
  const auto law = nonlinear_penalty();
  const double c0 = 0.002;
  expect_value(law, -0.003, 0.0, 0.0, false);
  expect_value(law, -c0, 0.0, 100.0, true);
  expect_value(law, 0.005 - c0, 0.5, 100.0, true);
  expect_value(law, 0.01 - c0, 1.0, 100.0, true);      // s_e
  expect_value(law, 0.02 - c0, 26.75, 5050.0, true);
  expect_value(law, 0.03 - c0, 102.0, 1e4, true);      // s_d
  expect_value(law, 0.05 - c0, 302.0, 1e4, true);
  EXPECT_EQ(law.h_zero(), -c0);
  EXPECT_EQ(law.max_slope(0.0), 1e4);
  const std::vector<double> away_from_kinks{0.004 - c0, 0.012 - c0, 0.02 - c0, 0.028 - c0, 0.04 - c0, 1.0};
  expect_slope_is_the_derivative(law, away_from_kinks, 1e-7);
  expect_inverse_gives_h_back(law, {0.001 - c0, 0.01 - c0, 0.015 - c0, 0.03 - c0, 0.2}, -c0);
}

// p and dp/dh are continuous where the quadratic part starts (s_e) and ends (s_d): the jumps
// across ±δ are those of the smooth side, |Δp| ≤ 2δ K_f and |Δdp| ≤ 2δ (K_f − K_i)/(s_d − s_e).
TEST(NonlinearPenaltyLaw, PressureAndSlopeAreContinuousAtTheQuadraticEnds) {
  const auto law = nonlinear_penalty();
  const double c0 = 0.002, delta = 1e-10, curvature = (1e4 - 100.0) / 0.02;
  for (const double s : {0.01, 0.03}) {
    const PressureValue below = law.eval(s - c0 - delta), at = law.eval(s - c0), above = law.eval(s - c0 + delta);
    EXPECT_LE(std::abs(above.p - below.p), 2.0 * delta * 1e4 * (1.0 + 1e-6)) << "s = " << s;
    EXPECT_LE(std::abs(above.dp - below.dp), 2.0 * delta * curvature * (1.0 + 1e-6) + 1e-9) << "s = " << s;
    EXPECT_NEAR(at.p, below.p, delta * 1e4 * (1.0 + 1e-6)) << "s = " << s;
    EXPECT_NEAR(at.dp, above.dp, delta * curvature * (1.0 + 1e-6) + 1e-9) << "s = " << s;
  }
}

// ŝ = h/c0 + 1: p = p0/(e−1) ŝ (exp ŝ − 1), so p(−c0) = 0, p(0) = p0, p(c0) = 2 p0 (e + 1);
// dp/dh = p0/((e−1) c0) (exp ŝ − 1 + ŝ exp ŝ): 0 at −c0, p0 (2e − 1)/((e − 1) c0) at 0.
TEST(ExponentialLaw, PassesThroughP0AtZeroClearance) {
  const auto law = exponential();
  const double c0 = 0.01, p0 = 10.0, e = std::numbers::e;
  expect_value(law, -0.011, 0.0, 0.0, false);
  expect_value(law, -c0, 0.0, 0.0, true);
  expect_value(law, 0.0, p0, p0 * (2.0 * e - 1.0) / ((e - 1.0) * c0), true);
  expect_value(law, c0, 2.0 * p0 * (e + 1.0), p0 * (e * e - 1.0 + 2.0 * e * e) / ((e - 1.0) * c0), true);
  EXPECT_EQ(law.h_zero(), -c0);
  EXPECT_EQ(law.max_slope(0.0), law.eval(0.0).dp);  // the slope grows: its value at h_max
  EXPECT_EQ(law.max_slope(c0), law.eval(c0).dp);
  EXPECT_EQ(law.max_slope(-1.0), 0.0);  // below −c0: the slope at −c0
  expect_slope_is_the_derivative(law, {-0.009, -0.005, 0.0, 0.01, 0.03}, 1e-7);
  expect_inverse_gives_h_back(law, {-c0 + 1e-8, -0.0099, -0.005, 0.0, 0.01, 0.05}, -c0);
}

// p = k h for h ≥ 0 (active from touching on), 0 below.
TEST(LinearSoftenedLaw, IsKTimesOverclosure) {
  const auto law = linear_softened();
  expect_value(law, -0.001, 0.0, 0.0, false);
  expect_value(law, 0.0, 0.0, 500.0, true);
  expect_value(law, 0.002, 1.0, 500.0, true);
  EXPECT_EQ(law.h_zero(), 0.0);
  EXPECT_EQ(law.max_slope(0.0), 500.0);
  expect_slope_is_the_derivative(law, {0.001, 0.5}, 1e-6);
  expect_inverse_gives_h_back(law, {1e-6, 0.002, 10.0}, 0.0);
}

// Through (−0.005, 0), (0, 2), (0.01, 12): slopes 400 then 1000, continued beyond the last
// point; at a kink the segment to its right applies.
TEST(TabularLaw, InterpolatesThePointsAndContinuesTheLastSlope) {
  const auto law = tabular();
  expect_value(law, -0.006, 0.0, 0.0, false);
  expect_value(law, -0.005, 0.0, 400.0, true);
  expect_value(law, -0.0025, 1.0, 400.0, true);
  expect_value(law, 0.0, 2.0, 1000.0, true);      // the kink
  expect_value(law, 0.005, 7.0, 1000.0, true);
  expect_value(law, 0.01, 12.0, 1000.0, true);    // the last point
  expect_value(law, 0.02, 22.0, 1000.0, true);    // beyond it
  EXPECT_EQ(law.h_zero(), -0.005);
  EXPECT_EQ(law.max_slope(0.0), 1000.0);
  expect_slope_is_the_derivative(law, {-0.004, -0.001, 0.001, 0.009, 0.5}, 1e-7);
  expect_inverse_gives_h_back(law, {-0.004, -0.0025, 0.0, 0.005, 0.01, 0.3}, -0.005);
}

// One point: the constant p_0 from h_0 on, slope 0; no segment, so max_slope is 0.
TEST(TabularLaw, OnePointIsAConstantPressure) {
  const auto law = softened(LawType::Tabular, [](model::SurfaceBehavior& b) { b.table = {{3.0, 0.001}}; });
  expect_value(law, 0.0, 0.0, 0.0, false);
  expect_value(law, 0.001, 3.0, 0.0, true);
  expect_value(law, 1.0, 3.0, 0.0, true);
  EXPECT_EQ(law.h_zero(), 0.001);
  EXPECT_EQ(law.max_slope(1.0), 0.0);
}

// p = k h for every h, tension included (a bonded spring).
TEST(TiedLaw, IsASpringInTensionAndCompression) {
  const auto law = tied();
  expect_value(law, -0.001, -1000.0, 1e6, true);
  expect_value(law, 0.0, 0.0, 1e6, true);
  expect_value(law, 0.002, 2000.0, 1e6, true);
  EXPECT_EQ(law.h_zero(), 0.0);
  EXPECT_EQ(law.max_slope(0.0), 1e6);
  expect_slope_is_the_derivative(law, {-0.01, 0.0, 0.01}, 1e-6);
  expect_inverse_gives_h_back(law, {1e-6, 0.002, 1.0}, 0.0);
}

}  // namespace
}  // namespace inpact::test
