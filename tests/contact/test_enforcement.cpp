// The enforcement methods (contact/enforcement.hpp), each alone on one slave node: status
// updates, the force and tangent coefficients, the constraint row of the methods with
// multipliers, the pressure and the output. Hand values on a linear law p = k (h + c0).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/enforcement/direct.hpp"
#include "contact/enforcement/law_multipliers.hpp"
#include "contact/enforcement/penalty.hpp"
#include "contact/resolved_interaction.hpp"

namespace inpact::contact {
namespace {

constexpr double kStiffness = 100.0;  // the penalty law's k (pressure per length)
constexpr StatusLimits kLimits{-1e-6, 1e-9};

/// A linear penalty law p = k (h + c0), as resolve_interactions builds it from *SURFACE BEHAVIOR.
PressureOverclosure linear_law(double k, double c0 = 0.0) {
  ResolvedNormalBehavior b;
  b.method = model::EnforcementMethod::PenaltyLinear;
  b.given_stiffness = k;
  b.deck.clearance_at_zero_pressure = c0;
  return PressureOverclosure::from(b, 1.0, 1.0);
}

NodeGap gap(double g) { return {true, g}; }

TEST(DirectMultipliers, ClosesOnPenetrationAndOpensOnTension) {
  const DirectMultipliers direct(false);
  SlaveState s;
  EXPECT_FALSE(direct.update_status(s, gap(0.01), kLimits).closed);  // open, not touching
  const StatusUpdate touch = direct.update_status(s, gap(-1e-3), kLimits);
  EXPECT_TRUE(touch.closed);
  EXPECT_TRUE(touch.contributes);
  s.closed = true;
  s.lambda = -5.0;  // pressure 5
  EXPECT_TRUE(direct.update_status(s, gap(0.0), kLimits).closed);
  EXPECT_DOUBLE_EQ(direct.pressure(s, gap(0.0)), 5.0);
  EXPECT_DOUBLE_EQ(direct.normal_force(s, gap(0.0)).coefficient, -5.0);  // f_c = A λ ∇g
  EXPECT_DOUBLE_EQ(direct.normal_force(s, gap(0.0)).stiffness, 0.0);
  s.lambda = 1e-3;  // tensile beyond round-off: opens, the multiplier is dropped
  EXPECT_FALSE(direct.update_status(s, gap(0.0), kLimits).closed);
  EXPECT_EQ(s.lambda, 0.0);
  EXPECT_TRUE(direct.uses_multipliers());
  EXPECT_EQ(direct.constraint_overclosure(s), 0.0);
}

TEST(DirectMultipliers, NoSeparationKeepsATensileNodeClosedAndReportsItsTension) {
  const DirectMultipliers bonded(true);
  SlaveState s;
  s.closed = true;
  s.lambda = 2.0;  // tension 2
  EXPECT_TRUE(bonded.update_status(s, gap(0.0), kLimits).closed);
  EXPECT_EQ(bonded.pressure(s, gap(0.0)), 0.0);         // friction sees no pressure
  EXPECT_DOUBLE_EQ(bonded.output(s, gap(0.0)).pressure, -2.0);  // CPRESS shows the tension
  EXPECT_FALSE(bonded.update_status(s, NodeGap{false, 0.0}, kLimits).closed);  // lost its master
}

TEST(PenaltyLaw, PressureAndSlopeOfTheLawAtTheOverclosure) {
  const PenaltyLaw penalty(linear_law(kStiffness), {});
  SlaveState s;
  const StatusUpdate u = penalty.update_status(s, gap(-0.02), kLimits);
  EXPECT_TRUE(u.closed);
  EXPECT_TRUE(u.contributes);
  EXPECT_DOUBLE_EQ(penalty.pressure(s, gap(-0.02)), 2.0);  // p = k h
  const NormalForce f = penalty.normal_force(s, gap(-0.02));
  EXPECT_DOUBLE_EQ(f.coefficient, -2.0);  // f_c = −A p ∇g
  EXPECT_DOUBLE_EQ(f.stiffness, kStiffness);
  EXPECT_DOUBLE_EQ(penalty.pressure_slope(s, gap(-0.02)), kStiffness);
  EXPECT_FALSE(penalty.uses_multipliers());
}

TEST(PenaltyLaw, AnOpenNodeTouchingWithinRoundOffBringsTheFirstSlope) {
  const PenaltyLaw penalty(linear_law(kStiffness), {});
  SlaveState s;
  const StatusUpdate open = penalty.update_status(s, gap(0.1), kLimits);
  EXPECT_FALSE(open.closed);
  EXPECT_FALSE(open.contributes);
  const StatusUpdate touching = penalty.update_status(s, gap(1e-12), kLimits);
  EXPECT_FALSE(touching.closed);
  EXPECT_TRUE(touching.contributes);
  EXPECT_DOUBLE_EQ(penalty.normal_force(s, gap(1e-12)).stiffness, kStiffness);
  EXPECT_EQ(penalty.normal_force(s, gap(1e-12)).coefficient, 0.0);
  EXPECT_EQ(penalty.pressure(s, NodeGap{false, 0.0}), 0.0);
}

TEST(PenaltyLaw, ClearanceShiftsTheLawAndTiedLawIsClosedInTension) {
  const PenaltyLaw offset(linear_law(kStiffness, 0.01), {});
  SlaveState s;
  EXPECT_DOUBLE_EQ(offset.pressure(s, gap(0.0)), 1.0);  // p = k (0 + c0)
  EXPECT_DOUBLE_EQ(offset.h_zero(), -0.01);
  ResolvedNormalBehavior tied;
  tied.law = model::PressureOverclosure::Tied;
  tied.deck.tied_slope = kStiffness;
  PenaltyOptions options;
  options.tied_law = true;
  const PenaltyLaw bonded(PressureOverclosure::from(tied, 1.0, 1.0), options);
  const NodePressure out = bonded.output(s, gap(0.03));
  EXPECT_TRUE(out.closed);
  EXPECT_DOUBLE_EQ(out.pressure, -3.0);  // p = k h, tension included
}

TEST(PenaltyLaw, UserAdaptiveScalesPressureAndSlope) {
  PenaltyOptions options;
  options.user_adaptive = true;
  PenaltyLaw adaptive(linear_law(kStiffness), options);
  adaptive.set_adaptive_scale(0.01);
  SlaveState s;
  EXPECT_DOUBLE_EQ(adaptive.pressure(s, gap(-0.02)), 0.02);
  EXPECT_DOUBLE_EQ(adaptive.normal_force(s, gap(-0.02)).stiffness, 1.0);
  adaptive.set_adaptive_scale(1.0);
  EXPECT_DOUBLE_EQ(adaptive.pressure(s, gap(-0.02)), 2.0);
}

TEST(AugmentedLagrange, TheMultiplierShiftsTheLawAndAnOpenNodeLeavesTheTangent) {
  PenaltyOptions options;
  options.augmented = true;
  const PenaltyLaw augmented(linear_law(kStiffness), options);
  SlaveState s;
  s.lambda = 3.0;
  EXPECT_TRUE(augmented.augmented());
  EXPECT_DOUBLE_EQ(augmented.pressure(s, gap(-0.02)), 5.0);  // p = ⟨λ + k h⟩
  EXPECT_DOUBLE_EQ(augmented.pressure(s, gap(0.01)), 2.0);   // λ holds it closed a little beyond zero gap
  EXPECT_EQ(augmented.pressure(s, gap(0.05)), 0.0);
  EXPECT_DOUBLE_EQ(augmented.penetration(gap(-0.02)), 0.02);
  SlaveState next = s;
  augmented.augment(next, gap(-0.02));  // λ ← p
  EXPECT_DOUBLE_EQ(next.lambda, 5.0);
  // However often it crossed the law's kink, an open node has the law's tangent: none
  // (solver/newton.cpp limits the corrections that would make it bounce).
  s.flips = 5;
  const StatusUpdate open = augmented.update_status(s, gap(0.05), kLimits);
  EXPECT_FALSE(open.closed);
  EXPECT_FALSE(open.contributes);
}

TEST(LawWithMultipliers, ClosesAtTheLawsPressureAndItsRowIsTheLawsInverse) {
  const double ke = 1.0, l_char = 1.0;
  const LawWithMultipliers stiff(linear_law(kStiffness, 0.01), false, false, l_char, ke);
  SlaveState s;
  const StatusUpdate u = stiff.update_status(s, gap(-0.02), kLimits);
  EXPECT_TRUE(u.closed);
  EXPECT_DOUBLE_EQ(s.multiplier, -3.0);  // starts at the law's pressure k (h + c0)
  s.closed = true;
  EXPECT_DOUBLE_EQ(stiff.pressure(s, gap(-0.02)), 3.0);
  // The row −A (g + h(p)): h(p) = p / k − c0 = 0.02, and the diagonal −A / p'(h) = −A / k.
  EXPECT_NEAR(stiff.constraint_overclosure(s), 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(stiff.compliance_slope(s), kStiffness);
  EXPECT_DOUBLE_EQ(stiff.normal_force(s, gap(-0.02)).coefficient, -3.0);
  // A tensile multiplier continues the law linearly below its first pressure.
  s.multiplier = 1.0;
  EXPECT_NEAR(stiff.constraint_overclosure(s), -1.0 / kStiffness - 0.01, 1e-14);
  EXPECT_DOUBLE_EQ(stiff.pressure_round_off(), 1e-4 * kStiffness * l_char);
  EXPECT_EQ(stiff.multiplier(), &SlaveState::multiplier);
}

TEST(MakeEnforcement, EachResolvedKindGetsItsType) {
  ResolvedInteraction r;
  r.law = linear_law(kStiffness);
  r.enforcement = EnforcementKind::DirectMultipliers;
  EXPECT_NE(dynamic_cast<DirectMultipliers*>(make_enforcement(r).get()), nullptr);
  r.enforcement = EnforcementKind::PenaltyLaw;
  EXPECT_NE(dynamic_cast<PenaltyLaw*>(make_enforcement(r).get()), nullptr);
  r.enforcement = EnforcementKind::AugmentedLagrange;
  r.augmented = true;
  EXPECT_TRUE(make_enforcement(r)->augmented());
  r.enforcement = EnforcementKind::LawWithMultipliers;
  EXPECT_NE(dynamic_cast<LawWithMultipliers*>(make_enforcement(r).get()), nullptr);
}

}  // namespace
}  // namespace inpact::contact
