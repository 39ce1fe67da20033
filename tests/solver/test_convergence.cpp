// Convergence criteria as records (value, tolerance, pass) at hand-picked measures around each
// tolerance, per field, and the time-averaged force q̃ they are measured against.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "solver/convergence.hpp"

using namespace inpact::solver;

namespace {

/// r_max = 0.004, q̃ = 1: under R_n = 0.005; c_max = 0.009 against Δu_max = 1: under C_n = 0.01.
IterationMeasures converging() {
  IterationMeasures m;
  m.iteration = 2;
  m.max_residual = {0.004, 0.0};
  m.q = {1.0, 0.0};
  m.max_correction = {0.009, 0.0};
  m.max_increment = {1.0, 0.0};
  return m;
}

const Criterion& named(const ConvergenceCheck& c, std::string_view name) {
  for (const Criterion& k : c.criteria)
    if (k.name == name) return k;
  throw std::logic_error("no criterion named so");
}

}  // namespace

TEST(Convergence, ResidualAndCorrectionUnderTheirTolerancesConverge) {
  const ConvergenceCheck c = check_convergence(converging(), SolutionControls{});
  EXPECT_TRUE(c.converged);
  const Criterion& r = named(c, "residual");
  EXPECT_DOUBLE_EQ(r.value, 0.004);
  EXPECT_DOUBLE_EQ(r.tolerance, 0.005);  // R_n · q̃
  EXPECT_TRUE(r.pass);
  const Criterion& du = named(c, "correction");
  EXPECT_DOUBLE_EQ(du.tolerance, 0.01);  // C_n · Δu_max
  EXPECT_TRUE(du.pass);
  EXPECT_FALSE(named(c, "linear residual").pass);  // 0.004 > 1e-8
}

TEST(Convergence, EachFailingCriterionStopsConvergence) {
  IterationMeasures m = converging();
  m.max_residual[kDisplacementField] = 0.006;
  EXPECT_FALSE(check_convergence(m, {}).converged);
  m = converging();
  m.max_correction[kDisplacementField] = 0.011;
  const ConvergenceCheck c = check_convergence(m, {});
  EXPECT_FALSE(c.converged);
  EXPECT_FALSE(named(c, "correction").pass);
  m = converging();
  m.contact_status_changed = true;
  EXPECT_FALSE(check_convergence(m, {}).converged);
  m = converging();
  m.max_gap_error = 2e-3;  // > 1e-3 · Δu_max + 1e-14
  const ConvergenceCheck g = check_convergence(m, {});
  EXPECT_FALSE(g.converged);
  EXPECT_DOUBLE_EQ(named(g, "contact compatibility").tolerance, 1e-3 + 1e-14);
}

TEST(Convergence, TheFirstPassNeedsTheLinearResidual) {
  IterationMeasures m = converging();
  m.iteration = 0;  // no correction yet: the residual and correction tests cannot pass
  EXPECT_FALSE(check_convergence(m, {}).converged);
  m.max_residual[kDisplacementField] = 0.9e-8;  // ≤ R_l q̃ = 1e-8: accepted without the correction test
  m.max_correction[kDisplacementField] = 1e3;
  const ConvergenceCheck c = check_convergence(m, {});
  EXPECT_TRUE(c.converged);
  EXPECT_TRUE(named(c, "linear residual").pass);
  EXPECT_FALSE(named(c, "correction").pass);
}

TEST(Convergence, NoForceAtAllIsEquilibrium) {
  IterationMeasures m;
  EXPECT_TRUE(check_convergence(m, {}).converged);
  m.contact_status_changed = true;  // but not while contact is still changing
  EXPECT_FALSE(check_convergence(m, {}).converged);
}

// Moments are measured against moments: a moment residual of 0.004 passes against q̃ = 1 of the
// rotation field and stops convergence against q̃ = 0.5, whatever the forces are; a rotation
// correction of 0.02 against a turn of 1 stops it too.
TEST(Convergence, TheRotationFieldIsMeasuredApart) {
  IterationMeasures m = converging();
  m.q = {1e6, 1.0};
  m.max_residual = {0.004, 0.004};
  m.max_increment = {1.0, 1.0};
  m.max_correction = {0.009, 0.009};
  EXPECT_TRUE(check_convergence(m, {}).converged);
  m.q[kRotationField] = 0.5;
  ConvergenceCheck c = check_convergence(m, {});
  EXPECT_FALSE(c.converged);
  EXPECT_FALSE(named(c, "moment residual").pass);
  EXPECT_DOUBLE_EQ(named(c, "moment residual").tolerance, 0.0025);
  EXPECT_TRUE(named(c, "residual").pass);
  m.q[kRotationField] = 1.0;
  m.max_correction[kRotationField] = 0.02;
  c = check_convergence(m, {});
  EXPECT_FALSE(c.converged);
  EXPECT_FALSE(named(c, "rotation correction").pass);
}

TEST(Convergence, TimeAveragedForceCountsTheCurrentIncrementOnce) {
  TimeAveragedForce q;
  EXPECT_DOUBLE_EQ(q.with({4.0, 1.0})[0], 4.0);
  q.add({4.0, 1.0});
  q.add({2.0, 3.0});
  EXPECT_DOUBLE_EQ(q.with({6.0, 5.0})[kDisplacementField], (4.0 + 2.0 + 6.0) / 3);
  EXPECT_DOUBLE_EQ(q.with({6.0, 5.0})[kRotationField], (1.0 + 3.0 + 5.0) / 3);
}

TEST(Convergence, IncrementForceKeepsTheFirstIterationsForceAndContactOnlyWhenPresent) {
  IncrementForce f;
  EXPECT_DOUBLE_EQ(f.update({10.0, 0}, {1000.0, 0})[0], 1000.0);  // a first-iteration contact spike counts now
  EXPECT_DOUBLE_EQ(f.update({1.0, 0}, {1.0, 0})[0], 10.0);        // later the first iteration's q at least
  EXPECT_DOUBLE_EQ(f.update({400.0, 0}, {400.0, 0})[0], 400.0);   // a spike counts while it lasts ...
  EXPECT_DOUBLE_EQ(f.update({12.0, 0}, {12.5, 0})[0], 12.5);      // ... and not after it
  IncrementForce nan_first;
  EXPECT_DOUBLE_EQ(nan_first.update({NAN, 0}, {NAN, 0})[1], 0.0);  // a NaN start is not kept
  EXPECT_DOUBLE_EQ(nan_first.update({3.0, 1.0}, {3.0, 1.0})[0], 3.0);
}

TEST(Convergence, AverageForceOverElementLoadAndContactEntries) {
  AssemblyResult a;
  a.average_force = {2.0, 0.0};
  a.n_force_entries = {3, 0};  // Σ = 6
  const std::vector<double> f_ext{0.0, -4.0, 0.0};  // one load entry, |f| = 4
  const DofMap displacements_only;
  EXPECT_DOUBLE_EQ(average_force(a, displacements_only, f_ext, 5.0, 1)[0], (6.0 + 5.0 + 4.0) / 5);
  EXPECT_DOUBLE_EQ(average_force(AssemblyResult{}, displacements_only, std::vector<double>(2, 0.0), 0.0, 0)[0], 0.0);
}

TEST(Convergence, LargestIncrementIsTheLargestMagnitude) {
  const std::vector<double> u{1.0, -3.0, 2.0}, u0{0.5, 0.0, 2.0};
  EXPECT_DOUBLE_EQ(largest_increment(DofMap{}, u, u0)[kDisplacementField], 3.0);
}
