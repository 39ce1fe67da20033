// The increment controller: the sequence of increment sizes for a given series of attempt
// outcomes, and the notes that end a step. Every expected size is a hand product of the
// initial increment and the factors D_f = 0.25, D_D = 1.5.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "solver/increment_controller.hpp"

using namespace inpact::solver;

namespace {

const auto kNoMarks = [](double, double dt) { return dt; };

IncrementLimits limits(double initial, double period = 1.0) {
  IncrementLimits l;
  l.period = period;
  l.initial = initial;
  l.minimum = 1e-5;
  l.maximum = period;
  return l;
}

/// Runs the step with every attempt converging in `iterations` equilibrium iterations and
/// returns the increment sizes.
std::vector<double> sizes(IncrementController& inc, int iterations, const std::function<double(double, double)>& marks = kNoMarks) {
  std::vector<double> dt;
  while (!inc.step_complete()) {
    EXPECT_FALSE(inc.begin_increment(marks).has_value());
    dt.push_back(inc.size());
    inc.attempt_converged(iterations);
  }
  return dt;
}

}  // namespace

TEST(IncrementController, GrowsAfterTwoEasyIncrementsAndEndsOnThePeriod) {
  IncrementController inc(limits(0.1));
  const std::vector<double> dt = sizes(inc, 2);
  // 0.1, 0.1, then ×1.5 after every easy increment from the second on: 0.15, 0.225, 0.3375;
  // t = 0.9125, the last one takes the remaining 0.0875.
  ASSERT_EQ(dt.size(), 6u);
  EXPECT_DOUBLE_EQ(dt[0], 0.1);
  EXPECT_DOUBLE_EQ(dt[1], 0.1);
  EXPECT_DOUBLE_EQ(dt[2], 0.15);
  EXPECT_DOUBLE_EQ(dt[3], 0.225);
  EXPECT_DOUBLE_EQ(dt[4], 0.3375);
  EXPECT_NEAR(dt[5], 1.0 - 0.9125, 1e-15);
  EXPECT_DOUBLE_EQ(inc.start(), 1.0);
}

TEST(IncrementController, HardIncrementsDoNotGrow) {
  IncrementController inc(limits(0.25));
  const std::vector<double> dt = sizes(inc, 5);  // I_G = 4: five iterations are not easy
  EXPECT_EQ(dt, std::vector<double>(4, 0.25));
}

TEST(IncrementController, CutsBackByTheFactorAndGrowsOnlyAfterTwoEasyIncrements) {
  IncrementController inc(limits(1.0));
  ASSERT_FALSE(inc.begin_increment(kNoMarks));
  Cutback c = inc.attempt_failed(false, false);
  EXPECT_TRUE(c.retry);
  EXPECT_EQ(c.note, "; cutting back to 0.25");
  EXPECT_EQ(inc.attempt(), 2);
  c = inc.attempt_failed(false, false);
  EXPECT_EQ(c.note, "; cutting back to 0.0625");
  EXPECT_DOUBLE_EQ(inc.size(), 0.0625);
  EXPECT_DOUBLE_EQ(inc.end(), 0.0625);
  inc.attempt_converged(1);  // easy, but cut back: it does not count as easy
  const std::vector<double> dt = sizes(inc, 1);
  // 0.0625 twice more (easy 1, easy 2), then 0.09375, 0.140625, 0.2109375, 0.31640625, and the rest.
  ASSERT_GE(dt.size(), 6u);
  EXPECT_DOUBLE_EQ(dt[0], 0.0625);
  EXPECT_DOUBLE_EQ(dt[1], 0.0625);
  EXPECT_DOUBLE_EQ(dt[2], 0.09375);
  EXPECT_DOUBLE_EQ(dt[3], 0.140625);
  EXPECT_DOUBLE_EQ(dt[4], 0.2109375);
  EXPECT_DOUBLE_EQ(dt[5], 0.31640625);
}

TEST(IncrementController, GivesUpAfterTheMostCutbacks) {
  IncrementLimits l = limits(1.0);
  l.max_cutbacks = 2;
  IncrementController inc(l);
  ASSERT_FALSE(inc.begin_increment(kNoMarks));
  EXPECT_TRUE(inc.attempt_failed(false, false).retry);
  EXPECT_TRUE(inc.attempt_failed(false, false).retry);
  const Cutback c = inc.attempt_failed(false, false);  // attempt 3 = 2 cutbacks spent
  EXPECT_FALSE(c.retry);
  EXPECT_EQ(c.note, " — gave up after 2 cutbacks");
}

TEST(IncrementController, StopsWhereACutbackWouldFallBelowTheMinimum) {
  IncrementLimits l = limits(1.0);
  l.minimum = 0.1;
  IncrementController inc(l);
  ASSERT_FALSE(inc.begin_increment(kNoMarks));
  EXPECT_TRUE(inc.attempt_failed(false, false).retry);  // 0.25 ≥ 0.1
  const Cutback c = inc.attempt_failed(false, false);   // 0.0625 < 0.1
  EXPECT_FALSE(c.retry);
  EXPECT_EQ(c.note, " — the increment would fall below the minimum 0.1");
  EXPECT_DOUBLE_EQ(inc.size(), 0.25);
}

TEST(IncrementController, DirectIncrementationNeitherCutsBackNorGrows) {
  IncrementLimits l = limits(0.2);
  l.direct = true;
  IncrementController inc(l);
  const std::vector<double> dt = sizes(inc, 1);
  ASSERT_EQ(dt.size(), 5u);
  for (double d : dt) EXPECT_NEAR(d, 0.2, 1e-15);
  IncrementController failing(l);
  ASSERT_FALSE(failing.begin_increment(kNoMarks));
  const Cutback c = failing.attempt_failed(false, false);
  EXPECT_FALSE(c.retry);
  EXPECT_EQ(c.note, " (DIRECT incrementation cannot cut back)");
}

TEST(IncrementController, ARigidBodyModeStopsUnlessContactMayHoldTheBody) {
  IncrementController alone(limits(1.0));
  ASSERT_FALSE(alone.begin_increment(kNoMarks));
  const Cutback c = alone.attempt_failed(true, false);
  EXPECT_FALSE(c.retry);
  EXPECT_EQ(c.note, "");
  IncrementController held(limits(1.0));
  ASSERT_FALSE(held.begin_increment(kNoMarks));
  EXPECT_TRUE(held.attempt_failed(true, true).retry);
}

TEST(IncrementController, TheIncrementLimitEndsTheStep) {
  IncrementLimits l = limits(0.4);
  l.max_increments = 2;
  IncrementController inc(l);
  for (int i = 0; i < 2; ++i) {
    ASSERT_FALSE(inc.begin_increment(kNoMarks));
    inc.attempt_converged(5);
  }
  const auto stop = inc.begin_increment(kNoMarks);
  ASSERT_TRUE(stop.has_value());
  EXPECT_EQ(*stop, "more increments needed than INC=2 allows, at step time 0.8");
}

TEST(IncrementController, ATimeMarkShortensOneIncrementAndTheChosenSizeResumes) {
  IncrementController inc(limits(0.4));
  const auto mark_at_0_3 = [](double t, double dt) { return t < 0.3 ? std::min(dt, 0.3 - t) : dt; };
  const std::vector<double> dt = sizes(inc, 5, mark_at_0_3);
  // 0.3 (cut short by the mark), then the chosen 0.4 again, then the remaining 0.3.
  ASSERT_EQ(dt.size(), 3u);
  EXPECT_DOUBLE_EQ(dt[0], 0.3);
  EXPECT_DOUBLE_EQ(dt[1], 0.4);
  EXPECT_NEAR(dt[2], 0.3, 1e-15);
}

TEST(IncrementController, ARemainderBelowARoundOffJoinsTheIncrement) {
  IncrementController inc(limits(0.5 - 1e-14));
  const std::vector<double> dt = sizes(inc, 5);
  // 0.5 − 1e-14, then the rest (0.5 + 1e-14, beyond the chosen size): no 1e-14 increment.
  ASSERT_EQ(dt.size(), 2u);
  EXPECT_DOUBLE_EQ(inc.start(), 1.0);
}
