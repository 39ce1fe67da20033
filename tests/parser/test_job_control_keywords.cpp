// *PREPRINT and *RESTART: the job-control lines of every Abaqus/CAE input file, read so that such
// a deck runs; what inpact cannot do (print the echo tables, write or read restart files) is said.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {
std::string with_step(const std::string& model_data, const std::string& step) {
  return model_data + one_cube_deck("*STEP\n*STATIC\n" + step + "*END STEP\n");
}
}  // namespace

TEST(JobControl, AbaqusCaeLinesAreReadWithoutADiagnostic) {
  DeckDir dir;
  auto r = dir.read(with_step("*Heading\n*Preprint, echo=NO, model=NO, history=NO, contact=NO\n",
                              "*Restart, write, frequency=0\n*Output, field, variable=PRESELECT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.report().find("warning"), std::string::npos) << r.report();
}

TEST(JobControl, WhatInpactDoesNotWriteIsAWarning) {
  DeckDir dir;
  auto r = dir.read(with_step("*PREPRINT, ECHO=YES\n*RESTART, WRITE, FREQUENCY=5\n", ""));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:1:17: warning: *PREPRINT: ECHO=YES: inpact's .dat does not print"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:2:1: warning: *RESTART: inpact writes no restart files")) << r.report();
}

TEST(JobControl, ARestartReadIsADeckError) {
  DeckDir dir;
  auto r = dir.read(with_step("*RESTART, READ, STEP=1\n", ""));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:1:11: error: *RESTART: READ (a restart analysis")) << r.report();
  auto neither = dir.read(with_step("*RESTART\n", ""));
  EXPECT_TRUE(has_diagnostic(neither, "*RESTART: expected READ or WRITE")) << neither.report();
}

TEST(JobControl, PreprintTakesOnlyYesOrNo) {
  DeckDir dir;
  auto r = dir.read(with_step("*PREPRINT, MODEL=MAYBE\n", ""));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "MODEL")) << r.report();
}

TEST(JobControl, MonitorPrintEnergyOutputAndFileFormat) {
  DeckDir dir;
  auto r = dir.read(with_step("*FILE FORMAT, ASCII\n", "*MONITOR, NODE=7, DOF=3, FREQUENCY=1\n*PRINT, SOLVE=NO\n"
                                                       "*OUTPUT, HISTORY\n*ENERGY OUTPUT\nALLSE, ALLWK\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "warning: *MONITOR: inpact's .sta does not show a monitored degree of freedom"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "warning: *ENERGY OUTPUT: energy history output")) << r.report();
  EXPECT_FALSE(has_diagnostic(r, "*PRINT")) << r.report();
  EXPECT_FALSE(has_diagnostic(r, "*FILE FORMAT")) << r.report();
  // A monitored DOF is one node's, 1 to 6.
  auto bad = dir.read(with_step("", "*MONITOR, NODE=ALL, DOF=3\n*MONITOR, NODE=7, DOF=9\n"));
  EXPECT_TRUE(has_diagnostic(bad, "the monitored node must be exactly one node")) << bad.report();
  EXPECT_TRUE(has_diagnostic(bad, "*MONITOR: expected a degree of freedom from 1 to 6")) << bad.report();
}
