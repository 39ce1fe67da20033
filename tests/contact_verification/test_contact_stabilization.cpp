// Contact stabilization (*CONTACT STABILIZATION, *CONTACT CONTROLS, STABILIZE) on the 3D block
// placed on another (decks/contact_verification/contact_*stabiliz*_3d.inp): the upper block is
// held vertically by nothing but the contact and loaded by p = 10 on its top (F = 40 over A = 4),
// so CPRESS = F/A = 10 wherever the blocks touch. With zero gap the stabilised run must dissipate
// under 1 % of its strain energy and give the unstabilised direct answer within 1 %; with a gap of
// 0.001 (a free body until it touches) it must complete and give the right pressure, where the
// unstabilised run stops and says why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "fixtures/deck_fixture.hpp"
#include "solver/stabilization.hpp"
#include "stabilization_checks.hpp"
#include "verification/verification_fixture.hpp"

namespace {

using inpact::verification::run_deck;

std::string deck(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/contact_verification/" + name + ".inp";
}
/// The unstabilised references (the *STATIC, STABILIZE tests' decks).
std::string reference(const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/tests/contact_verification/decks/" + name + ".inp";
}

using inpact::stabilization_checks::cpress;
using inpact::stabilization_checks::history;
using inpact::stabilization_checks::warned;

/// The largest relative error of CPRESS against F/A = 10.
double worst_against_load(const std::vector<double>& p) {
  double worst = 0.0;
  for (double v : p) worst = std::max(worst, std::abs(v - 10.0) / 10.0);
  return worst;
}

/// The block deck with its contact enforced by `behavior` (a *SURFACE BEHAVIOR line, or "": direct).
std::string block_deck(inpact::test::DeckDir& dir, const std::string& behavior) {
  std::ifstream in(deck("contact_stabilization_block_3d"));
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string kw = "*SURFACE INTERACTION, NAME=SMOOTH\n";
  s.replace(s.find(kw), kw.size(), kw + behavior);
  return dir.write(behavior.empty() ? "direct.inp" : "law.inp", s);
}

// Direct multipliers leave the closed nodes no relative normal motion (ALLSD is round-off); the
// penalty law's penetration grows with the load, so its damping dissipates, a little.
class BlockOnBlock : public ::testing::TestWithParam<const char*> {};

std::string label(const std::string& behavior) {
  return behavior.empty() ? "direct" : behavior.substr(std::string("*SURFACE BEHAVIOR, ").size(),
                                                       behavior.size() - std::string("*SURFACE BEHAVIOR, \n").size());
}

TEST_P(BlockOnBlock, DissipatesLittleAndGivesTheDirectAnswer) {
  inpact::test::DeckDir dir;
  const auto plain = run_deck(reference("stabilize_patch_3d_unstabilized"));
  const auto stab = run_deck(block_deck(dir, GetParam()));
  ASSERT_TRUE(plain->outcome.completed) << plain->outcome.message;
  ASSERT_TRUE(stab->outcome.completed) << stab->outcome.message;
  const auto& last = stab->capture.last();
  const double allse = history(last, "ALLSE"), allsd = history(last, "ALLSD");
  EXPECT_GT(allse, 0.0);
  EXPECT_GE(allsd, 0.0);
  EXPECT_LT(allsd, 0.01 * allse);
  EXPECT_FALSE(warned(*stab));
  const auto& p_stab = cpress(last);
  const auto& p_plain = cpress(plain->capture.last());
  ASSERT_EQ(p_stab.size(), p_plain.size());
  ASSERT_FALSE(p_stab.empty());
  double worst_plain = 0.0;
  for (std::size_t i = 0; i < p_stab.size(); ++i)
    worst_plain = std::max(worst_plain, std::abs(p_stab[i] - p_plain[i]) / std::abs(p_plain[i]));
  EXPECT_LT(worst_against_load(p_stab), 0.01);
  EXPECT_LT(worst_plain, 0.01);
  std::printf("[ figures ] zero gap, %s: ALLSE %.6g ALLSD %.3g ALLSD/ALLSE %.3g; CPRESS error vs F/A %.3g, vs "
              "unstabilised direct %.3g\n",
              label(GetParam()).c_str(), allse, allsd, allsd / allse, worst_against_load(p_stab), worst_plain);
}

INSTANTIATE_TEST_SUITE_P(ContactStabilization, BlockOnBlock,
                         ::testing::Values("", "*SURFACE BEHAVIOR, PENALTY\n",
                                           "*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n"));

// Unstabilised, the free body's first increment is singular however small, and the run says which
// pair touches nowhere and what would hold the body; stabilised (either form) it completes.
TEST(ContactStabilization, AFreeBodyWithAGapCompletesOnlyWhenStabilized) {
  const auto plain = run_deck(reference("stabilize_gap_3d_unstabilized"));
  EXPECT_FALSE(plain->outcome.completed);
  EXPECT_NE(plain->outcome.message.find("singular"), std::string::npos) << plain->outcome.message;
  EXPECT_NE(plain->outcome.message.find("touches nowhere"), std::string::npos) << plain->outcome.message;
  EXPECT_NE(plain->outcome.message.find("*CONTACT STABILIZATION"), std::string::npos) << plain->outcome.message;
  for (const char* name : {"contact_stabilization_gap_3d", "contact_controls_stabilize_gap_3d"}) {
    const auto stab = run_deck(deck(name));
    ASSERT_TRUE(stab->outcome.completed) << name << ": " << stab->outcome.message;
    const auto& last = stab->capture.last();
    const double allse = history(last, "ALLSE"), allsd = history(last, "ALLSD");
    EXPECT_GT(allsd, 0.0) << name;  // the damping held the body while it closed the gap
    EXPECT_LT(allsd, 0.01 * allse) << name;
    EXPECT_FALSE(warned(*stab)) << name;
    EXPECT_LT(worst_against_load(cpress(last)), 0.01) << name;
    std::printf("[ figures ] %s: ALLSD/ALLSE %.3g, CPRESS error vs F/A %.3g\n", name, allsd / allse,
                worst_against_load(cpress(last)));
  }
}

// A damping coefficient far above the automatic one, kept to the step's end: the dissipation
// passes the warning ratio and the run says that its answer may be wrong.
TEST(ContactStabilization, LargeDampingKeptToTheStepEndWarns) {
  inpact::test::DeckDir dir;
  std::ifstream in(deck("contact_controls_stabilize_gap_3d"));
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string kw = "*CONTACT CONTROLS, MASTER=MASTER_S, SLAVE=SLAVE_S, STABILIZE\n";
  s.replace(s.find(kw), kw.size(), kw + "1e4, 1\n");
  const auto r = run_deck(dir.write("large.inp", s));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& last = r->capture.last();
  EXPECT_GT(history(last, "ALLSD"), inpact::solver::kAllsdWarningRatio * history(last, "ALLSE"));
  EXPECT_TRUE(warned(*r));
}

}  // namespace
