// *MPC TIE (parser/kw_equation.cpp): the translations of each dependent node equal its
// independent node's. Reference (decks/verification/mpc_tie_c3d8.inp): two unit cubes stacked
// with coincident nodes tied, pulled by 100 (E = 1000, ν = 0): the top rises by 0.2 exactly and
// each tied pair moves as one.
#include "verification_fixture.hpp"

#include <cmath>

namespace inpact::verification {
namespace {

// Measured: U3 of the top 0.2 to 1.1e-16, the tied pairs equal to 0.
TEST(Mpc, TiedCubesCarryTheLoadAsOneColumn) {
  const auto r = run_deck(deck_path("mpc_tie_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  EXPECT_EQ(m.equations.size(), 12u);  // 4 pairs × 3 DOFs
  double worst_top = 0.0, worst_pair = 0.0;
  for (std::int32_t n : nset(m, "TOP")) worst_top = std::max(worst_top, std::abs(nodal(f, "U", n, 2) - 0.2));
  const auto upper = nset(m, "UPPER_BOTTOM"), lower = nset(m, "LOWER_TOP");
  ASSERT_EQ(upper.size(), lower.size());
  for (std::size_t i = 0; i < upper.size(); ++i)
    for (int c = 0; c < 3; ++c) worst_pair = std::max(worst_pair, std::abs(nodal(f, "U", upper[i], c) - nodal(f, "U", lower[i], c)));
  report("mpc tie: |U3(top) - 0.2|", worst_top);
  report("mpc tie: |U(upper) - U(lower)| over the tied pairs", worst_pair);
  EXPECT_LE(worst_top, 1e-12);
  EXPECT_LE(worst_pair, 1e-15);
}

}  // namespace
}  // namespace inpact::verification
