// CHOLMOD and UMFPACK behind LinearSolver: exact solutions of small systems, reuse of the
// symbolic analysis, and the statuses that the Newton loop turns into diagnostics.
#include <cmath>

#include <gtest/gtest.h>

#include "solver/linear/linear_solver.hpp"

using namespace inpact::solver;

namespace {

/// A chain of n nodes joined by unit springs (interior diagonal 2, end diagonals 1) with a
/// spring k from the first node to ground: SPD for k > 0, singular (rigid translation) for k = 0.
SparseMatrix laplacian(std::int64_t n, bool upper_only, double k = 0.0) {
  PatternBuilder pb(n);
  for (std::int64_t i = 0; i + 1 < n; ++i) {
    const std::int64_t d[2] = {i, i + 1};
    pb.add_block(d);
  }
  SparseMatrix a = pb.build(upper_only);
  for (std::int64_t i = 0; i + 1 < n; ++i) {
    a.values[a.find(i, i)] += 1.0;
    a.values[a.find(i + 1, i + 1)] += 1.0;
    a.values[a.find(i, i + 1)] -= 1.0;
    if (!upper_only) a.values[a.find(i + 1, i)] -= 1.0;
  }
  a.values[a.find(0, 0)] += k;
  return a;
}

}  // namespace

TEST(SparseMatrix, PatternHoldsTheDiagonalAndUpperTriangleOnly) {
  SparseMatrix a = laplacian(4, true, 1.0);
  EXPECT_EQ(a.nnz(), 4u + 3u);
  EXPECT_EQ(a.find(1, 0), a.find(0, 1));  // the lower entry maps to the stored upper one
  EXPECT_EQ(a.find(0, 3), -1);
  std::vector<double> x{1, 1, 1, 1}, y(4);
  a.multiply(x, y);  // row sums: k, then zeros
  EXPECT_DOUBLE_EQ(y[0], 1.0);
  EXPECT_DOUBLE_EQ(y[1], 0.0);
  EXPECT_DOUBLE_EQ(y[3], 0.0);
}

// A mesh's blocks repeat each coupling once per element that shares it; the builder compacts
// its columns as they fill. The pattern must be the same as from each block once: a 1D chain of
// 3-node blocks [i, i+1, i+2] added 40 times over (a column receives up to 240 entries, compacted
// several times on the way); its full form mirrors the upper triangle.
TEST(SparseMatrix, RepeatedBlocksGiveTheSamePatternAsEachOnce) {
  const std::int64_t n = 30;
  PatternBuilder once(n), repeated(n), repeated_full(n);
  for (std::int64_t i = 0; i + 2 < n; ++i) {
    const std::int64_t block[3] = {i + 2, i, i + 1};  // any order
    once.add_block(block);
    for (int r = 0; r < 40; ++r) {
      repeated.add_block(block);
      repeated_full.add_block(block);
    }
  }
  const SparseMatrix a = once.build(true), b = repeated.build(true);
  EXPECT_EQ(a.col_ptr, b.col_ptr);
  EXPECT_EQ(a.row_idx, b.row_idx);
  EXPECT_EQ(a.nnz(), static_cast<std::size_t>(n + (n - 1) + (n - 2)));  // diagonal, first and second neighbours
  const SparseMatrix full = repeated_full.build(false);
  EXPECT_FALSE(full.upper_only);
  EXPECT_EQ(full.nnz(), static_cast<std::size_t>(n + 2 * (n - 1) + 2 * (n - 2)));
  EXPECT_GE(full.find(5, 3), 0);
  EXPECT_GE(full.find(3, 5), 0);
  EXPECT_EQ(full.find(3, 6), -1);
}

TEST(Cholmod, SolvesTheGroundedChainExactly) {
  // Grounded at node 0 with unit spring, unit load at the free end: u_i = i + 1 (hand solution:
  // the load passes through every spring, each stretching by 1).
  const std::int64_t n = 200;
  SparseMatrix a = laplacian(n, true, 1.0);
  auto solver = make_cholmod_solver();
  ASSERT_EQ(solver->factorize(a), FactorStatus::Ok);
  std::vector<double> b(n, 0.0), x(n);
  b[n - 1] = 1.0;
  solver->solve(b, x);
  for (std::int64_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], static_cast<double>(i + 1), 1e-9 * n);
}

TEST(Cholmod, KeepsTheAnalysisWhileThePatternHolds) {
  auto solver = make_cholmod_solver();
  SparseMatrix a = laplacian(50, true, 1.0);
  ASSERT_EQ(solver->factorize(a), FactorStatus::Ok);
  for (double& v : a.values) v *= 2.0;  // new values, same pattern
  ASSERT_EQ(solver->factorize(a), FactorStatus::Ok);
  EXPECT_EQ(solver->analyses(), 1);
  std::vector<double> b(50, 0.0), x(50);
  b[49] = 2.0;
  solver->solve(b, x);
  EXPECT_NEAR(x[49], 50.0, 1e-9);
  ASSERT_EQ(solver->factorize(laplacian(51, true, 1.0)), FactorStatus::Ok);
  EXPECT_EQ(solver->analyses(), 2);
}

TEST(Cholmod, ReportsARigidModeAsNotPositiveDefinite) {
  auto solver = make_cholmod_solver();
  EXPECT_EQ(solver->factorize(laplacian(10, true, 0.0)), FactorStatus::NotPositiveDefinite);
  EXPECT_GE(solver->failed_equation(), 0);
}

TEST(Umfpack, SolvesASaddlePointSystem) {
  // min ½ u·K u − f·u subject to u0 = 0.5 through a multiplier λ (row/col 3):
  // [K  e0; e0ᵀ 0] [u; λ] = [f; 0.5] with K the free 3-node chain, f = (0, 0, 1).
  PatternBuilder pb(4);
  const std::int64_t e01[2] = {0, 1}, e12[2] = {1, 2};
  pb.add_block(e01);
  pb.add_block(e12);
  pb.add_pair(0, 3);
  SparseMatrix a = pb.build(false);
  auto add = [&](std::int64_t r, std::int64_t c, double v) { a.values[a.find(r, c)] += v; };
  for (auto [i, j] : {std::pair{0, 1}, std::pair{1, 2}}) {
    add(i, i, 1); add(j, j, 1); add(i, j, -1); add(j, i, -1);
  }
  add(0, 3, 1);
  add(3, 0, 1);
  auto solver = make_umfpack_solver();
  ASSERT_EQ(solver->factorize(a), FactorStatus::Ok);
  std::vector<double> b{0, 0, 1, 0.5}, x(4);
  solver->solve(b, x);
  EXPECT_NEAR(x[0], 0.5, 1e-12);
  EXPECT_NEAR(x[1], 1.5, 1e-12);
  EXPECT_NEAR(x[2], 2.5, 1e-12);
  // Row 0 reads (u0 − u1) + λ = 0, so λ = 1: the constraint pushes node 0 with −λ = −1,
  // balancing the unit load.
  EXPECT_NEAR(x[3], 1.0, 1e-12);
}

TEST(Umfpack, ExpandsAnUpperTriangleAndAgreesWithCholmod) {
  SparseMatrix a = laplacian(30, true, 0.5);
  auto chol = make_cholmod_solver();
  auto lu = make_umfpack_solver();
  ASSERT_EQ(chol->factorize(a), FactorStatus::Ok);
  ASSERT_EQ(lu->factorize(a), FactorStatus::Ok);
  std::vector<double> b(30), x1(30), x2(30);
  for (int i = 0; i < 30; ++i) b[i] = std::sin(i);
  chol->solve(b, x1);
  lu->solve(b, x2);
  for (int i = 0; i < 30; ++i) EXPECT_NEAR(x1[i], x2[i], 1e-10 * (1 + std::abs(x1[i])));
}

TEST(Umfpack, ReportsASingularMatrix) {
  auto lu = make_umfpack_solver();
  EXPECT_EQ(lu->factorize(laplacian(10, false, 0.0)), FactorStatus::Singular);
}
