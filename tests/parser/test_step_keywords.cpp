// *STEP *STATIC *END STEP *CONTROLS into the model's steps.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

TEST(Step, BareStepAndStaticTakeTheAbaqusDefaults) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 1u);
  const auto& s = r.model.steps[0];
  EXPECT_EQ(s.name, "Step-1");
  EXPECT_FALSE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 100);
  EXPECT_EQ(s.amplitude, model::Step::DefaultAmplitude::Ramp);
  EXPECT_EQ(s.extrapolation, model::Step::Extrapolation::Linear);
  ASSERT_TRUE(s.static_procedure);
  const auto& p = *s.static_procedure;
  EXPECT_FALSE(p.direct);
  EXPECT_DOUBLE_EQ(p.time_period, 1.0);
  EXPECT_DOUBLE_EQ(p.initial_increment, 1.0);  // the whole period in one increment
  EXPECT_DOUBLE_EQ(*p.min_increment, 1e-5);    // min(initial, 1e-5 × period)
  EXPECT_DOUBLE_EQ(*p.max_increment, 1.0);     // the period
  EXPECT_EQ(s.loc.line, 16u);
}

TEST(Step, ParametersTitleAndStaticDataLine) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP, NAME=Load, NLGEOM, INC=50, AMPLITUDE=STEP, UNSYMM=YES, EXTRAPOLATION=PARABOLIC\n"
                                  "Pull the block\n*STATIC\n0.1, 2.\n*END STEP\n"
                                  "*STEP, NLGEOM=NO, extrapolation=no\n*STATIC, DIRECT\n0.25, 1., ,\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 2u);
  const auto& a = r.model.steps[0];
  EXPECT_EQ(a.name, "Load");
  EXPECT_EQ(a.description, "Pull the block");
  EXPECT_TRUE(a.nlgeom);
  EXPECT_TRUE(a.unsymm);
  EXPECT_EQ(a.max_increments, 50);
  EXPECT_EQ(a.amplitude, model::Step::DefaultAmplitude::Step);
  EXPECT_EQ(a.extrapolation, model::Step::Extrapolation::Parabolic);
  EXPECT_DOUBLE_EQ(a.static_procedure->initial_increment, 0.1);
  EXPECT_DOUBLE_EQ(a.static_procedure->time_period, 2.0);
  EXPECT_DOUBLE_EQ(*a.static_procedure->min_increment, 2e-5);  // 1e-5 × period < initial
  EXPECT_DOUBLE_EQ(*a.static_procedure->max_increment, 2.0);
  const auto& b = r.model.steps[1];
  EXPECT_EQ(b.name, "Step-2");  // Abaqus numbers unnamed steps by position
  EXPECT_TRUE(b.nlgeom);        // once on, NLGEOM stays on (Abaqus); NLGEOM=NO is a warning
  EXPECT_TRUE(has_diagnostic(r, "NLGEOM=NO after a step with NLGEOM"));
  EXPECT_EQ(b.extrapolation, model::Step::Extrapolation::None);
  EXPECT_TRUE(b.static_procedure->direct);
  EXPECT_DOUBLE_EQ(b.static_procedure->initial_increment, 0.25);
}

// NLGEOM carries into the steps after the one that switches it on (Abaqus and CalculiX alike).
TEST(Step, NlgeomStaysOnInLaterSteps) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n*END STEP\n*STEP, NLGEOM\n*STATIC\n*END STEP\n"
                                  "*STEP\n*STATIC\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 3u);
  EXPECT_FALSE(r.model.steps[0].nlgeom);
  EXPECT_TRUE(r.model.steps[1].nlgeom);
  EXPECT_TRUE(r.model.steps[2].nlgeom);
}

TEST(Step, StaticWithMinimumLargerThanInitialIsAnError) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n0.01, 1., 0.1, 1.\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(
      r, "deck.inp:18:11: error: *STATIC: the minimum time increment 0.1 is larger than the initial increment 0.01"))
      << r.report();
}

TEST(Step, StaticRejectsNonPositiveAndInconsistentIncrements) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n0., 1.\n*END STEP\n*STEP\n*STATIC\n2., 1.\n*END STEP\n"
                                  "*STEP\n*STATIC\n0.5, 1., 1e-5, 0.1\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *STATIC: initial time increment must be positive, found 0"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *STATIC: the initial time increment 2 is larger than the time period 1"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:1: error: *STATIC: the initial time increment 0.5 is larger than the "
                                "maximum increment 0.1"))
      << r.report();
}

TEST(Step, DirectIncrementsMustFitInInc) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP, INC=5\n*STATIC, DIRECT\n0.1, 1.\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *STATIC: DIRECT needs 10 increments of 0.1 to cover the period 1, "
                                "more than INC=5 on *STEP allows"))
      << r.report();
}

TEST(Step, StepKeywordOutsideAStepCitesItsLine) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STATIC\n1., 1.\n*STEP\n*STATIC\n*END STEP\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:1: error: *STATIC: not allowed in the model data; it belongs in *STEP"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:1: error: *END STEP: not allowed in the model data; it belongs in *STEP"))
      << r.report();
}

TEST(Step, MissingEndStepAndMissingProcedure) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP, NAME=First\n*END STEP\n*STEP\n*STATIC\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:1: error: *STEP: step 'First' has no procedure (expected *STATIC)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *STEP: step 'Step-2' has no *END STEP")) << r.report();
}

TEST(Step, StepInsideAStepDuplicateNamesAndPerturbation) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP, NAME=A\n*STATIC\n*STEP, NAME=B\n*END STEP\n*STEP, NAME=a, PERTURBATION\n"
                                  "*STATIC\n*STATIC\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *STEP: not allowed inside *STEP (history data); it belongs in "
                                "model data"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:13: error: *STEP: step 'a' is defined twice (first at line 16)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*STEP: linear perturbation steps are not supported yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *STATIC: step 'a' already has a procedure (*STATIC at line 21)"))
      << r.report();
}

TEST(Controls, FieldsAreKeptByPositionWithTheAugmentationLimit) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n"
                                  "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n, , , , , , , , , , , , 60\n0.25, 0.5\n"
                                  "*CONTROLS, PARAMETERS=FIELD, FIELD=DISPLACEMENT\n0.01, 0.02\n"
                                  "*CONTROLS, PARAMETERS=FIELD\n0.5\n"
                                  "*CONTROLS, PARAMETERS=LINE SEARCH\n5\n"
                                  "*CONTROLS, ANALYSIS=DISCONTINUOUS\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& c = r.model.steps[0].controls;
  ASSERT_TRUE(c.time_incrementation);
  const auto& ti = *c.time_incrementation;
  ASSERT_EQ(ti.line1.size(), 13u);
  EXPECT_FALSE(ti.line1[0]);  // blank: the Abaqus default I0
  EXPECT_DOUBLE_EQ(*ti.max_augmentations(), 60.0);
  ASSERT_EQ(ti.line2.size(), 2u);
  EXPECT_DOUBLE_EQ(*ti.line2[1], 0.5);
  EXPECT_TRUE(ti.line3.empty());
  // FIELD=DISPLACEMENT is more specific than the GLOBAL block after it.
  ASSERT_TRUE(c.field);
  EXPECT_EQ(c.field->field, "DISPLACEMENT");
  EXPECT_DOUBLE_EQ(*c.field->values[0], 0.01);
  ASSERT_TRUE(c.line_search);
  EXPECT_DOUBLE_EQ(*c.line_search->values[0], 5.0);
  EXPECT_TRUE(c.analysis_discontinuous);
  EXPECT_FALSE(c.reset);
}

TEST(Controls, ResetAndMissingSelection) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n*CONTROLS, PARAMETERS=LINE SEARCH\n5\n*CONTROLS, RESET\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_TRUE(r.model.steps[0].controls.reset);
  EXPECT_FALSE(r.model.steps[0].controls.line_search);
  auto bad = dir.read(one_cube_deck("*STEP\n*STATIC\n*CONTROLS\n*CONTROLS, PARAMETERS=TIME INCREMENTATION\n4, x\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(bad, "deck.inp:18:1: error: *CONTROLS: expected PARAMETERS=, ANALYSIS=DISCONTINUOUS or RESET"))
      << bad.report();
  EXPECT_TRUE(has_diagnostic(bad, "deck.inp:20:4: error: *CONTROLS: control value: expected a number, found 'x'"))
      << bad.report();
}

TEST(StepKeywords, SolutionTechniqueIsReadAndQuasiNewtonSaysInpactIteratesWithFullNewton) {
  inpact::test::DeckDir dir;
  auto r = dir.read(inpact::test::one_cube_deck("*STEP\n*STATIC\n*SOLUTION TECHNIQUE, TYPE=QUASI-NEWTON, REFORM KERNEL=8\n"
                                                "*END STEP\n*STEP\n*STATIC\n*SOLUTION TECHNIQUE, TYPE=FULL NEWTON\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_TRUE(inpact::test::has_diagnostic(r, "warning: *SOLUTION TECHNIQUE: TYPE=QUASI-NEWTON: inpact iterates with full "
                                              "Newton"))
      << r.report();
  EXPECT_EQ(r.report().find("FULL NEWTON"), std::string::npos) << r.report();
}
