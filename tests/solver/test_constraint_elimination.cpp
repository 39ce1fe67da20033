// solver/constraint_elimination.hpp: linear rows Σ a u = Σ b u solved for their largest free
// left-hand DOFs (full pivoting), by hand.
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/analysis_error.hpp"
#include "solver/constraint_elimination.hpp"

namespace inpact::solver {
namespace {

using Kind = DofMap::Kind;

double weight_of(const std::vector<MasterTerm>& terms, std::int64_t dof) {
  double w = 0.0;
  for (const auto& t : terms)
    if (t.dof == dof) w += t.weight;
  return w;
}

// One row 2 u0 + u1 = u5: the pivot is u0 (the larger coefficient), u0 = ½ u5 − ½ u1.
TEST(ConstraintElimination, OneRowTakesItsLargestFreeCoefficient) {
  std::vector<Kind> kind(6, Kind::Free);
  std::map<std::int64_t, std::vector<MasterTerm>> dependent;
  eliminate_rows({{{{0, 2.0}, {1, 1.0}}, {{5, 1.0}}}}, kind, dependent, "no pivot");
  ASSERT_EQ(dependent.size(), 1u);
  ASSERT_TRUE(dependent.count(0));
  EXPECT_EQ(kind[0], Kind::Dependent);
  EXPECT_DOUBLE_EQ(weight_of(dependent[0], 5), 0.5);
  EXPECT_DOUBLE_EQ(weight_of(dependent[0], 1), -0.5);
}

// Two rows, u0 + u1 = u4 and u0 − u1 = u5, with u0 prescribed: only u1 and u2 may be pivots, and
// u2 is in neither row, so the second row has none left: an error. Without the prescription the
// solution is u0 = (u4 + u5)/2, u1 = (u4 − u5)/2.
TEST(ConstraintElimination, TwoRowsSolveTogetherOrReportNoPivot) {
  const std::vector<LinearRow> rows = {{{{0, 1.0}, {1, 1.0}}, {{4, 1.0}}}, {{{0, 1.0}, {1, -1.0}}, {{5, 1.0}}}};
  std::vector<Kind> kind(6, Kind::Free);
  std::map<std::int64_t, std::vector<MasterTerm>> dependent;
  eliminate_rows(rows, kind, dependent, "no pivot");
  ASSERT_TRUE(dependent.count(0) && dependent.count(1));
  EXPECT_NEAR(weight_of(dependent[0], 4), 0.5, 1e-15);
  EXPECT_NEAR(weight_of(dependent[0], 5), 0.5, 1e-15);
  EXPECT_NEAR(weight_of(dependent[1], 4), 0.5, 1e-15);
  EXPECT_NEAR(weight_of(dependent[1], 5), -0.5, 1e-15);
  std::vector<Kind> held(6, Kind::Free);
  held[0] = Kind::Prescribed;
  dependent.clear();
  EXPECT_THROW(eliminate_rows(rows, held, dependent, "no pivot"), AnalysisError);
}

}  // namespace
}  // namespace inpact::solver
