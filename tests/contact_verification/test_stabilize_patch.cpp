// *STATIC, STABILIZE on the 3D contact patch test (tests/contact_verification/decks): the upper
// block is held vertically by nothing but the contact. The stabilised run must complete, dissipate
// under 1 % of its strain energy, and give CPRESS = p = 10 (the load over the area) within 1 %,
// as the unstabilised run does; a large damping factor must say that its answer may be wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <cmath>
#include <string>

#include "fixtures/deck_fixture.hpp"
#include "solver/stabilization.hpp"
#include "stabilization_checks.hpp"
#include "verification/verification_fixture.hpp"

namespace {

using inpact::verification::run_deck;

std::string stabilize_deck(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/tests/contact_verification/decks/" + name + ".inp";
}

using inpact::stabilization_checks::cpress;
using inpact::stabilization_checks::history;
using inpact::stabilization_checks::warned;

TEST(StabilizePatch, CompletesWithSmallDissipationAndTheExactPressure) {
  const auto plain = run_deck(stabilize_deck("stabilize_patch_3d_unstabilized"));
  const auto stab = run_deck(stabilize_deck("stabilize_patch_3d"));
  ASSERT_TRUE(plain->outcome.completed) << plain->outcome.message;
  ASSERT_TRUE(stab->outcome.completed) << stab->outcome.message;
  const auto& last = stab->capture.last();
  const double allse = history(last, "ALLSE"), allsd = history(last, "ALLSD");
  EXPECT_GT(allse, 0.0);
  EXPECT_GT(allsd, 0.0);  // increments 2-4 are damped
  EXPECT_LT(allsd, 0.01 * allse);
  std::printf("[ figures ] ALLSE %.6g ALLSD %.6g ALLSD/ALLSE %.3g\n", allse, allsd, allsd / allse);
  EXPECT_FALSE(warned(*stab));

  const auto& p_stab = cpress(last);
  const auto& p_plain = cpress(plain->capture.last());
  ASSERT_EQ(p_stab.size(), p_plain.size());
  double worst_load = 0.0, worst_plain = 0.0;
  for (std::size_t i = 0; i < p_stab.size(); ++i) {
    worst_load = std::max(worst_load, std::abs(p_stab[i] - 10.0) / 10.0);
    worst_plain = std::max(worst_plain, std::abs(p_stab[i] - p_plain[i]) / std::abs(p_plain[i]));
  }
  EXPECT_LT(worst_load, 0.01);   // p = F/A
  EXPECT_LT(worst_plain, 0.01);  // the unstabilised direct answer
  std::printf("[ figures ] CPRESS error vs F/A %.3g, vs unstabilised %.3g\n", worst_load, worst_plain);
}

TEST(StabilizePatch, ALargeDampingFactorWarns) {
  const auto r = run_deck(stabilize_deck("stabilize_patch_3d_large_factor"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& last = r->capture.last();
  EXPECT_GT(history(last, "ALLSD"), inpact::solver::kAllsdWarningRatio * history(last, "ALLSE"));
  EXPECT_TRUE(warned(*r));
}

}  // namespace

namespace {

// A gap of 0.001 between the blocks: until the contact closes the upper block is a rigid body
// vertically. Unstabilised, the first increment is singular however small; stabilised it starts
// (the first, undamped attempt fails and damping starts from the tangent's diagonal).
TEST(StabilizePatch, ABodyHeldOnlyByContactStarts) {
  const auto plain = run_deck(stabilize_deck("stabilize_gap_3d_unstabilized"));
  EXPECT_FALSE(plain->outcome.completed);
  EXPECT_NE(plain->outcome.message.find("singular"), std::string::npos) << plain->outcome.message;
  const auto stab = run_deck(stabilize_deck("stabilize_gap_3d"));
  ASSERT_TRUE(stab->outcome.completed) << stab->outcome.message;
  const auto& last = stab->capture.last();
  const double allse = history(last, "ALLSE"), allsd = history(last, "ALLSD");
  EXPECT_LT(allsd, 0.01 * allse);
  double worst = 0.0;
  for (double p : cpress(last)) worst = std::max(worst, std::abs(p - 10.0) / 10.0);
  EXPECT_LT(worst, 0.01);
  std::printf("[ figures ] gap: ALLSD/ALLSE %.3g, CPRESS error vs F/A %.3g\n", allsd / allse, worst);
}

}  // namespace

namespace {

// ALLSDTOL (inpact's adaptive scheme): the same large FACTOR, but c is lowered after each
// increment whose ALLSD passes tol·ALLSE, so the step ends with less dissipation than with the
// constant factor, and the last increments dissipate little.
TEST(StabilizePatch, AllsdtolLowersALargeFactor) {
  const auto constant = run_deck(stabilize_deck("stabilize_patch_3d_large_factor"));
  const auto adaptive = run_deck(stabilize_deck("stabilize_patch_3d_adaptive"));
  ASSERT_TRUE(adaptive->outcome.completed) << adaptive->outcome.message;
  const auto ratio = [](const inpact::verification::Run& r) {
    return history(r.capture.last(), "ALLSD") / history(r.capture.last(), "ALLSE");
  };
  EXPECT_LT(ratio(*adaptive), ratio(*constant));
  std::printf("[ figures ] FACTOR=2000: ALLSD/ALLSE %.3g constant, %.3g with ALLSDTOL=0.05\n", ratio(*constant),
              ratio(*adaptive));
}

}  // namespace

namespace {

// CONTINUE=YES: a second step starts with the damping factor the first ended with, so its first
// increment is damped already (ALLSD grows in it); without it the second step's first increment
// is undamped again and sets its own factor.
TEST(StabilizePatch, ContinueCarriesTheFactorIntoTheNextStep) {
  std::ifstream in(stabilize_deck("stabilize_patch_3d"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string step2 = "*STEP, NAME=MORE\n*STATIC, STABILIZE{}\n0.25, 1.0\n*DSLOAD\nTOP_S, P, 20\n*END STEP\n";
  inpact::test::DeckDir dir;
  const auto run_with = [&](const std::string& extra) {
    std::string deck = text.str() + step2;
    deck.replace(deck.find("{}"), 2, extra);
    return run_deck(dir.write(extra.empty() ? "fresh.inp" : "continued.inp", deck));
  };
  const auto continued = run_with(", CONTINUE=YES");
  const auto fresh = run_with("");
  ASSERT_TRUE(continued->outcome.completed) << continued->outcome.message;
  ASSERT_TRUE(fresh->outcome.completed) << fresh->outcome.message;
  // ALLSD accumulates over the steps: the fresh step's undamped first increment adds nothing.
  const auto first_of_step2 = [](const inpact::verification::Run& r) {
    return history(*r.capture.of_step(2).front(), "ALLSD") - history(*r.capture.of_step(1).back(), "ALLSD");
  };
  EXPECT_GT(first_of_step2(*continued), 0.0);
  EXPECT_EQ(first_of_step2(*fresh), 0.0);
}

}  // namespace
