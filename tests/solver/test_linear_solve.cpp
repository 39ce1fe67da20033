// The Newton correction's solve: CHOLMOD → UMFPACK on a tangent that is not positive definite,
// and the failures a rigid-body mode gives, on 2 × 2 systems solved by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "solver/linear_solve.hpp"

using namespace inpact::solver;

namespace {

/// [[a, b], [b, c]], upper triangle only.
SparseMatrix two_by_two(double a, double b, double c) {
  PatternBuilder pb(2);
  const std::int64_t d[2] = {0, 1};
  pb.add_block(d);
  SparseMatrix m = pb.build(true);
  m.values[m.find(0, 0)] = a;
  m.values[m.find(0, 1)] = b;
  m.values[m.find(1, 1)] = c;
  return m;
}

}  // namespace

TEST(LinearSolve, PositiveDefiniteStaysOnCholmod) {
  LinearSolvers solvers;
  CorrectionSolver solver(solvers);
  // [[2, 1], [1, 2]] x = (3, 3): x = (1, 1).
  std::vector<double> r{3.0, 3.0}, du(2);
  const CorrectionOutcome out = solver.solve(two_by_two(2, 1, 2), false, r, du, 2, 1.0);
  ASSERT_TRUE(out.solved) << out.failure;
  EXPECT_EQ(&solver.current(), solvers.cholmod.get());
  EXPECT_NEAR(du[0], 1.0, 1e-14);
  EXPECT_NEAR(du[1], 1.0, 1e-14);
}

TEST(LinearSolve, AnIndefiniteTangentFallsBackToUmfpackForTheRestOfTheAttempt) {
  LinearSolvers solvers;
  CorrectionSolver solver(solvers);
  // [[1, 2], [2, 1]] (eigenvalues 3 and −1) x = (3, 3): x = (1, 1).
  std::vector<double> r{3.0, 3.0}, du(2);
  const CorrectionOutcome out = solver.solve(two_by_two(1, 2, 1), false, r, du, 2, 1.0);
  ASSERT_TRUE(out.solved) << out.failure;
  EXPECT_EQ(&solver.current(), solvers.umfpack.get());
  EXPECT_NEAR(du[0], 1.0, 1e-14);
  EXPECT_NEAR(du[1], 1.0, 1e-14);
  // The next iteration's tangent is SPD again, and UMFPACK keeps it.
  ASSERT_TRUE(solver.solve(two_by_two(2, 1, 2), false, r, du, 2, 1.0).solved);
  EXPECT_EQ(&solver.current(), solvers.umfpack.get());
  // A new attempt starts on CHOLMOD.
  CorrectionSolver next(solvers);
  ASSERT_TRUE(next.solve(two_by_two(2, 1, 2), false, r, du, 2, 1.0).solved);
  EXPECT_EQ(&next.current(), solvers.cholmod.get());
}

TEST(LinearSolve, ASaddlePointSystemGoesToUmfpack) {
  LinearSolvers solvers;
  CorrectionSolver solver(solvers);
  // [[1, 1], [1, 0]]: a spring and a multiplier holding its DOF; (u, λ) = (0, 2) for r = (2, 0).
  std::vector<double> r{2.0, 0.0}, du(2);
  const CorrectionOutcome out = solver.solve(two_by_two(1, 1, 0), true, r, du, 1, 1.0);
  ASSERT_TRUE(out.solved) << out.failure;
  EXPECT_EQ(&solver.current(), solvers.umfpack.get());
  EXPECT_NEAR(du[0], 0.0, 1e-14);
  EXPECT_NEAR(du[1], 2.0, 1e-14);
}

TEST(LinearSolve, ASingularTangentIsARigidBodyMode) {
  LinearSolvers solvers;
  CorrectionSolver solver(solvers);
  // One unsupported spring between two DOFs: [[1, −1], [−1, 1]] (the translation is free).
  std::vector<double> r{1.0, 0.0}, du(2);
  const CorrectionOutcome out = solver.solve(two_by_two(1, -1, 1), false, r, du, 2, 1.0);
  EXPECT_FALSE(out.solved);
  EXPECT_TRUE(out.singular);
  EXPECT_EQ(out.failure.rfind("the stiffness matrix is singular: a part of the model is free to move as a rigid body", 0), 0u)
      << out.failure;
}

TEST(LinearSolve, TheRigidBodyGuardCatchesARoundOffPivot) {
  LinearSolvers solvers;
  CorrectionSolver solver(solvers);
  // [[1, −1], [−1, 1 + 1e-12]]: positive definite by 1e-12, so it factorises; for r = (1, 0)
  // du = (1e12 + 1, 1e12), beyond 1e8 × the model size 1.
  std::vector<double> r{1.0, 0.0}, du(2);
  const CorrectionOutcome out = solver.solve(two_by_two(1, -1, 1 + 1e-12), false, r, du, 2, 1.0);
  EXPECT_FALSE(out.solved);
  EXPECT_TRUE(out.singular);
  EXPECT_NE(out.failure.find("; the correction was 1e+12, 1e+12 times the model size"), std::string::npos)
      << out.failure;
  // The same system in a model 1e5 long is a soft one, not a rigid mode.
  EXPECT_TRUE(solver.solve(two_by_two(1, -1, 1 + 1e-12), false, r, du, 2, 1e5).solved);
}
