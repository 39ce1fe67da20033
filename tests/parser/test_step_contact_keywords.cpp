// The step-wise contact changes into the model database: *CHANGE FRICTION (Abaqus, CalculiX),
// *CHANGE SURFACE BEHAVIOR (CalculiX) and *MODEL CHANGE, TYPE=CONTACT PAIR, and each bad use
// reported at its file:line:col.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {

/// The one-cube deck with surfaces TOP and BOTTOM, interaction I (μ = 0.1) and the pair
/// TOP/BOTTOM in the model data (and `model_extra`), then a step opened on line 25 (*STEP) and
/// 26 (*STATIC): `step_body` starts on line 27 (without `model_extra`).
std::string deck_with_step(const std::string& step_body, const std::string& more_steps = "",
                           const std::string& model_extra = "") {
  return one_cube_deck("*SURFACE, NAME=TOP\n1, S2\n*SURFACE, NAME=BOTTOM\n1, S1\n"
                       "*SURFACE INTERACTION, NAME=I\n*FRICTION\n0.1\n*CONTACT PAIR, INTERACTION=I\nTOP, BOTTOM\n" +
                       model_extra + "*STEP\n*STATIC\n" +
                       step_body + "*END STEP\n" + more_steps);
}

}  // namespace

TEST(StepContactKeywords, ChangeFrictionHoldsTheFrictionThatFollowsIt) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*CHANGE FRICTION, INTERACTION=i\n*FRICTION, SLIP TOLERANCE=0.01\n0.3\n",
                                   "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=I, RESET\n*END STEP\n"
                                   "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=I, AMPLITUDE=A\n*FRICTION\n0.2, 1e3\n"
                                   "*END STEP\n",
                                   "*AMPLITUDE, NAME=A\n0, 0, 1, 1\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 3u);
  const auto& c1 = r.model.steps[0].friction_changes;
  ASSERT_EQ(c1.size(), 1u);
  EXPECT_EQ(c1[0].interaction, "I");
  EXPECT_FALSE(c1[0].reset);
  ASSERT_TRUE(c1[0].friction);
  EXPECT_DOUBLE_EQ(c1[0].friction->mu, 0.3);
  EXPECT_DOUBLE_EQ(*c1[0].friction->slip_tolerance, 0.01);
  EXPECT_EQ(c1[0].loc.line, 29u);  // after the two *AMPLITUDE lines
  const auto& c2 = r.model.steps[1].friction_changes;
  ASSERT_EQ(c2.size(), 1u);
  EXPECT_TRUE(c2[0].reset);
  EXPECT_FALSE(c2[0].friction);
  const auto& c3 = r.model.steps[2].friction_changes;
  ASSERT_EQ(c3.size(), 1u);
  EXPECT_EQ(c3[0].amplitude, "A");
  EXPECT_DOUBLE_EQ(c3[0].friction->mu, 0.2);
  EXPECT_DOUBLE_EQ(*c3[0].friction->stick_slope, 1e3);  // CalculiX's λ
  // The model data's friction is untouched.
  EXPECT_DOUBLE_EQ(r.model.interactions.at("I").friction->mu, 0.1);
}

TEST(StepContactKeywords, ChangeSurfaceBehaviorHoldsTheBehaviorThatFollowsIt) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*CHANGE SURFACE BEHAVIOR, INTERACTION=I\n"
                                   "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e9\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& c = r.model.steps[0].behavior_changes;
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].interaction, "I");
  ASSERT_TRUE(c[0].behavior);
  EXPECT_EQ(c[0].behavior->pressure_overclosure, model::PressureOverclosure::Linear);
  EXPECT_DOUBLE_EQ(*c[0].behavior->linear_slope, 1e9);
  EXPECT_FALSE(r.model.interactions.at("I").behavior);
}

TEST(StepContactKeywords, ModelChangeRemovesAndAddsBackAContactPair) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\ntop, bottom\n",
                                   "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=CONTACT PAIR, ADD\nTOP, BOTTOM\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps[0].pair_changes.size(), 1u);
  const auto& removal = r.model.steps[0].pair_changes[0];
  EXPECT_EQ(removal.slave, "TOP");
  EXPECT_EQ(removal.master, "BOTTOM");
  EXPECT_FALSE(removal.add);
  EXPECT_EQ(removal.loc.line, 28u);
  ASSERT_EQ(r.model.steps[1].pair_changes.size(), 1u);
  EXPECT_TRUE(r.model.steps[1].pair_changes[0].add);
}

// ---- errors, at the name's file:line:col ----

TEST(StepContactKeywordErrors, UndefinedInteractionIsReportedAtItsName) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*CHANGE FRICTION, INTERACTION=J\n*FRICTION\n0.3\n"
                                   "*CHANGE SURFACE BEHAVIOR, INTERACTION=II\n*SURFACE BEHAVIOR, PENALTY\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:27:31: error: *CHANGE FRICTION: surface interaction 'J' is not defined"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:30:39: error: *CHANGE SURFACE BEHAVIOR: surface interaction 'II' is not "
                                "defined (did you mean 'I'?)"))
      << r.report();
}

TEST(StepContactKeywordErrors, FrictionInAStepMustFollowChangeFriction) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*FRICTION\n0.3\n*SURFACE BEHAVIOR, PENALTY\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:27:1: error: *FRICTION: must follow *SURFACE INTERACTION or *CHANGE FRICTION"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:29:1: error: *SURFACE BEHAVIOR: must follow *SURFACE INTERACTION or *CHANGE "
                                "SURFACE BEHAVIOR"))
      << r.report();
}

TEST(StepContactKeywordErrors, ChangeFrictionChecks) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*CHANGE FRICTION, INTERACTION=I, RESET\n*FRICTION\n0.3\n"
                                   "*CHANGE FRICTION, INTERACTION=I, AMPLITUDE=NONE\n*FRICTION\n0.3\n*FRICTION\n0.4\n"
                                   "*CHANGE FRICTION, INTERACTION=I\n*CHANGE FRICTION, INTERACTION=I, ELSET=E\n*FRICTION\n0.2\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:1: error: *FRICTION: *CHANGE FRICTION, RESET returns the model data's "
                                "friction"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:30:44: error: *CHANGE FRICTION: amplitude 'NONE' is not defined")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:33:1: error: *FRICTION: this *CHANGE FRICTION of 'I' already has a *FRICTION"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:35:1: warning: *CHANGE FRICTION: no *FRICTION follows (nor RESET): the "
                                "friction of 'I' is not changed"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:36:34: error: *CHANGE FRICTION: ELSET is not supported by inpact yet"))
      << r.report();
}

TEST(StepContactKeywordErrors, ChangeKeywordsBelongInAStep) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*SURFACE INTERACTION, NAME=I\n*CHANGE FRICTION, INTERACTION=I\n"
                                  "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nA, B\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:17:1: error: *CHANGE FRICTION: not allowed in the model data")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *MODEL CHANGE: not allowed in the model data")) << r.report();
}

TEST(StepContactKeywordErrors, ModelChangeChecks) {
  DeckDir dir;
  auto r = dir.read(deck_with_step("*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nBOTTOM, TOP\n"
                                   "*MODEL CHANGE, REMOVE\n1\n"
                                   "*MODEL CHANGE, TYPE=CONTACT PAIR\nTOP, BOTTOM\n"
                                   "*MODEL CHANGE, TYPE=CONTACT PAIR, ADD, REMOVE\nTOP, BOTTOM\n"
                                   "*MODEL CHANGE, TYPE=CONTACT PAIR, ADD\nTOP, BOTTOM\n"
                                   "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:1: error: *MODEL CHANGE: no *CONTACT PAIR has slave 'BOTTOM' and master "
                                "'TOP'"))
      << r.report();
  EXPECT_FALSE(has_diagnostic(r, "deck.inp:29:")) << r.report();  // TYPE=ELEMENT, the default: element 1
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:31:1: error: *MODEL CHANGE: one of ADD or REMOVE is required")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:33:40: error: *MODEL CHANGE: ADD, REMOVE and ACTIVATE are mutually exclusive"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:36:1: warning: *MODEL CHANGE: the contact pair TOP/BOTTOM is in force: ADD "
                                "has nothing to reactivate"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:37:1: error: *MODEL CHANGE: data lines are missing")) << r.report();
}

TEST(StepContactKeywords, ModelChangeOfElementsReadsLabelsAndSets) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*ELSET, ELSET=E\n1\n*STEP\n*STATIC\n*MODEL CHANGE, TYPE=ELEMENT, REMOVE\nE, 1\n*END STEP\n"
                                  "*STEP\n*STATIC\n*MODEL CHANGE, ADD=WITH STRAIN\n1\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& removed = r.model.steps[0].element_changes.at(0);
  EXPECT_FALSE(removed.add);
  EXPECT_EQ(removed.elements, std::vector<std::int32_t>{0});  // the set and the label: one element
  const auto& added = r.model.steps[1].element_changes.at(0);
  EXPECT_TRUE(added.add);
  EXPECT_TRUE(added.with_strain);
  auto bad = dir.read(one_cube_deck("*STEP\n*STATIC\n*MODEL CHANGE, REMOVE\n*MODEL CHANGE, ADD\n7\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(bad, "*MODEL CHANGE: data lines are missing: the elements or element sets to remove"))
      << bad.report();
  EXPECT_TRUE(has_diagnostic(bad, "7")) << bad.report();
  EXPECT_FALSE(bad.ok());
}

TEST(StepContactKeywordErrors, ATiedContactPairCannotBeRemoved) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*SURFACE, NAME=TOP\n1, S2\n*SURFACE, NAME=BOTTOM\n1, S1\n"
                                  "*SURFACE INTERACTION, NAME=I\n*CONTACT PAIR, INTERACTION=I, TIED, ADJUST=0.\n"
                                  "TOP, BOTTOM\n*STEP\n*STATIC\n*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nTOP, BOTTOM\n"
                                  "*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:1: error: *MODEL CHANGE: the contact pair TOP/BOTTOM is TIED, and a tied "
                                "contact pair cannot be removed"))
      << r.report();
}
