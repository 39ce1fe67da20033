// Decks in the layout Abaqus/CAE writes (decks/cae/): *Preprint, parts and instances, internal
// surface sets, *Restart, write, frequency=0, *Output, history, variable=PRESELECT, *Contact,
// op=NEW, gravity on the whole model (`, GRAV, ...`). They must run as written, and give the
// closed-form answers their headers state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "verification_fixture.hpp"

namespace inpact::test {
namespace {

std::string cae_deck(const std::string& name) { return std::string(INPACT_SOURCE_DIR) + "/decks/cae/" + name; }

/// Σ RF3 of the last frame of step `step` (1-based): the bottom's reaction, the only z support.
double bottom_reaction(const verification::Run& r, int step) {
  return verification::sum_rf(r, *r.capture.of_step(step).back())[2];
}

TEST(CaeDecks, PairOfTwoBlocksCarriesThePressure) {
  auto r = verification::run_deck(cae_deck("two_blocks_pair.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto* cpress = verification::field(r->capture.last(), "CPRESS");
  ASSERT_NE(cpress, nullptr);
  ASSERT_EQ(cpress->values.size(), 9u);  // the upper block's bottom nodes
  for (double p : cpress->values) EXPECT_NEAR(p, 100.0, 1e-6);
  EXPECT_NEAR(bottom_reaction(*r, 1), 100.0, 1e-8);
}

TEST(CaeDecks, GeneralContactWithWholeModelGravityBalancesEachStep) {
  auto r = verification::run_deck(cae_deck("two_blocks_general_gravity.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double weight = 7.85e-9 * 9810.0 * 1.0;  // ρ g V: both blocks, 1 x 1 x 0.5 each
  EXPECT_NEAR(bottom_reaction(*r, 1), 100.0 + weight, 1e-9);
  EXPECT_NEAR(bottom_reaction(*r, 2), 51.0 + weight, 1e-9);
}

}  // namespace
}  // namespace inpact::test
