// contact::resolve_interactions: the values the analysis enforces per interaction and step,
// against hand values of the patch-test decks (decks/contact/patch_2d_*.inp: E = 1000, ν = 0.3,
// slave facets 0.5 long on elements 0.5 thick, so k_e = M / 0.5 and l_char = 0.5).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact/initial_adjustment.hpp"
#include "contact/patch_test.hpp"
#include "contact/resolved_interaction.hpp"
#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

constexpr double kKe = kM / kSlaveElementHeight;

struct Resolved {
  parser::ReadResult deck;
  std::vector<std::vector<contact::ResolvedInteraction>> steps;
};

Resolved resolve_text(const DeckDir& dir, const std::string& text) {
  Resolved r;
  r.deck = dir.read(text);
  EXPECT_TRUE(r.deck.ok()) << r.deck.report();
  contact::apply_adjust(r.deck.model);
  r.steps = solver::build_analysis_model(r.deck.model).interactions;
  return r;
}

Resolved resolve_deck(const std::string& name) {
  const DeckDir dir;
  return resolve_text(dir, read_text(contact_deck(name)));
}

TEST(ResolvedInteraction, PenaltyPairTakesTenTimesKeAndHalfAFacetAsHcrit) {
  const Resolved r = resolve_deck("patch_2d_penalty.inp");
  ASSERT_EQ(r.steps.size(), 1u);
  ASSERT_EQ(r.steps[0].size(), 1u);
  const contact::ResolvedInteraction& i = r.steps[0][0];
  EXPECT_EQ(i.name, "SLAVE_S/MASTER_S");
  EXPECT_EQ(i.enforcement, contact::EnforcementKind::PenaltyLaw);
  EXPECT_NEAR(i.ke, kKe, 1e-12 * kKe);
  EXPECT_NEAR(i.l_char, kSlaveFacet, 1e-15);
  ASSERT_TRUE(i.law);
  EXPECT_NEAR(i.law->stiffness(), 10.0 * kKe, 1e-12 * kKe);
  EXPECT_NEAR(i.hcrit, 0.5 * kSlaveFacet, 1e-15);
  EXPECT_FALSE(i.friction);
  EXPECT_EQ(i.weight, 1.0);
  // The one text check, run, the results file and the .dat header show: the values above.
  EXPECT_EQ(contact::describe(i),
            "contact pair SLAVE_S/MASTER_S: node to surface, finite sliding; hard contact; linear penalty (given in "
            "*SURFACE BEHAVIOR); linear penalty, k = 2.692e+04, c0 = 0; no Lagrange multipliers (slope <= 1000 k_e); "
            "k_e = 2692.31, characteristic length 0.5; HCRIT 0.25; frictionless");
}

TEST(ResolvedInteraction, DirectPairHasNoLawAndAugmentedLagrangeItsTolerance) {
  const Resolved direct = resolve_deck("patch_2d_direct.inp");
  EXPECT_EQ(direct.steps[0][0].enforcement, contact::EnforcementKind::DirectMultipliers);
  EXPECT_FALSE(direct.steps[0][0].law);
  const Resolved al = resolve_deck("patch_2d_augmented.inp");
  const contact::ResolvedInteraction& i = al.steps[0][0];
  EXPECT_EQ(i.enforcement, contact::EnforcementKind::AugmentedLagrange);
  EXPECT_TRUE(i.augmented);
  EXPECT_NEAR(i.tolerance, 0.001 * kSlaveFacet, 1e-15);  // 0.1 % of l_char [AX p.782]
}

TEST(ResolvedInteraction, AStiffSlaveTakesTheSofterMastersModulus) {
  // The upper (slave) block has E = 1e9, the lower 1000: k_e = M_lower / h_slave, not 1e6 times it.
  const Resolved r = resolve_deck("patch_2d_s2s_augmented_stiff_slave.inp");
  const contact::ResolvedInteraction& i = r.steps[0][0];
  EXPECT_NEAR(i.ke, kKe, 1e-12 * kKe);
  ASSERT_TRUE(i.law);
  EXPECT_NEAR(i.law->stiffness(), 1000.0 * kKe, 1e-12 * kKe);
}

TEST(ResolvedInteraction, GeneralContactIsTwoHalfWeightRowsWithTheMeanOfBothScales) {
  const Resolved r = resolve_deck("patch_2d_general.inp");
  ASSERT_EQ(r.steps[0].size(), 2u);
  const auto& a = r.steps[0][0];
  const auto& b = r.steps[0][1];
  EXPECT_TRUE(a.general);
  EXPECT_EQ(a.weight, 0.5);
  EXPECT_EQ(b.weight, 0.5);
  EXPECT_EQ(a.ke, b.ke);  // one law for both rows
  EXPECT_EQ(a.l_char, b.l_char);
  // ALL EXTERIOR: each body's whole exterior. Lower body, 3 × 2 elements of 2/3 × 1/2: six
  // top and bottom facets 2/3 long on 1/2 thickness (k_e = 2 M), four side facets 1/2 long on
  // 2/3 (1.5 M); medians 2 M and 2/3. Upper body, 4 × 2 elements of 1/2 × 1/2: 2 M and 1/2.
  EXPECT_NEAR(a.ke, kKe, 1e-12 * kKe);
  EXPECT_NEAR(a.l_char, 0.5 * (2.0 / 3.0 + 0.5), 1e-10);  // (the deck's 12-digit coordinates)
  EXPECT_EQ(a.enforcement, contact::EnforcementKind::PenaltyLaw);
}

/// patch_2d_penalty.inp with a second step whose *CONTACT CONTROLS scale the stiffness by 1000:
/// 10 k_e × 1000 exceeds 1000 k_e, so table 38.1.21 puts the law on multipliers in that step.
std::string two_step_deck(const std::string& second_step_controls) {
  std::string text = read_text(contact_deck("patch_2d_penalty.inp"));
  text += "*STEP, NAME=HOLD\n*STATIC\n1.0, 1.0\n" + second_step_controls + "*END STEP\n";
  return text;
}

TEST(ResolvedInteraction, StepContactControlsChangeTheLawOfThatStepOnly) {
  const DeckDir dir;
  const Resolved r = resolve_text(dir, two_step_deck("*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=1000\n"));
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_EQ(r.steps[0][0].enforcement, contact::EnforcementKind::PenaltyLaw);
  EXPECT_EQ(r.steps[1][0].enforcement, contact::EnforcementKind::LawWithMultipliers);
  EXPECT_NEAR(r.steps[1][0].law->stiffness(), 1e4 * kKe, 1e-12 * 1e4 * kKe);
  EXPECT_NE(contact::describe(r.steps[0][0]), contact::describe(r.steps[1][0]));
}

TEST(ResolvedInteraction, ControlsCarryOverToLaterStepsUntilReset) {
  const DeckDir dir;
  std::string text = two_step_deck("*CONTACT CONTROLS, STIFFNESS SCALE FACTOR=1000\n");
  text += "*STEP, NAME=KEEP\n*STATIC\n1.0, 1.0\n*END STEP\n";
  text += "*STEP, NAME=RESET\n*STATIC\n1.0, 1.0\n*CONTACT CONTROLS, RESET\n*END STEP\n";
  const Resolved r = resolve_text(dir, text);
  ASSERT_EQ(r.steps.size(), 4u);
  EXPECT_EQ(r.steps[2][0].enforcement, contact::EnforcementKind::LawWithMultipliers);  // carried over
  EXPECT_EQ(contact::describe(r.steps[2][0]), contact::describe(r.steps[1][0]));
  EXPECT_EQ(r.steps[3][0].enforcement, contact::EnforcementKind::PenaltyLaw);  // back to the defaults
  EXPECT_EQ(contact::describe(r.steps[3][0]), contact::describe(r.steps[0][0]));
}

TEST(ResolvedInteraction, RoughFrictionWithoutElementStiffnessNamesThePair) {
  // A TIED pair brings ROUGH friction of its own (no *FRICTION in the deck): without k_e the
  // error cites the pair's line instead of a friction line that does not exist.
  const DeckDir dir;
  std::string text = read_text(contact_deck("patch_2d_direct.inp"));
  const std::string pair = "*CONTACT PAIR, INTERACTION=SMOOTH";
  ASSERT_NE(text.find(pair), std::string::npos);
  text.insert(text.find(pair) + pair.size(), ", ADJUST=0., TIED");
  auto deck = dir.read(text);
  ASSERT_TRUE(deck.ok()) << deck.report();
  contact::apply_adjust(deck.model);
  deck.model.materials.begin()->second.elastic.reset();
  try {
    solver::build_analysis_model(deck.model);
    ADD_FAILURE() << "expected a deck error";
  } catch (const solver::AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("error: *CONTACT PAIR: pair SLAVE_S/MASTER_S: ROUGH friction needs the element "
                                         "stiffness k_e"),
              std::string::npos)
        << e.what();
  }
}

TEST(ResolvedInteraction, DefaultPenaltyWithoutElasticSurfaceIsADeckError) {
  // Neither surface lies on an element with an elastic material: no k_e for the default
  // penalty stiffness, and the pair's data line (66) is named.
  const DeckDir dir;
  auto deck = dir.read(read_text(contact_deck("patch_2d_penalty.inp")));
  ASSERT_TRUE(deck.ok()) << deck.report();
  deck.model.materials.begin()->second.elastic.reset();
  try {
    solver::build_analysis_model(deck.model);
    ADD_FAILURE() << "expected a deck error";
  } catch (const solver::AnalysisError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("deck.inp:66:1: error: *CONTACT PAIR: pair SLAVE_S/MASTER_S: the default penalty stiffness "
                        "needs an element-based surface with an elastic material"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace inpact::test
