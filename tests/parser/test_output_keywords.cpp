// *OUTPUT with its sub-options, the print keywords and CalculiX's *... FILE keywords.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;
using Kind = model::OutputRequest::Kind;

namespace {
/// The cube with a two-surface contact-like setup and an open step; `step` goes inside it.
std::string cube_step(const std::string& step) {
  return one_cube_deck("*SURFACE, NAME=TOP\nCUBE, S2\n*SURFACE, NAME=BOTTOM\nCUBE, S1\n*STEP\n*STATIC\n" + step +
                       "*END STEP\n");
}
}  // namespace

TEST(Output, FieldAndHistoryRequestsWithTheirSubOptions) {
  DeckDir dir;
  auto r = dir.read(cube_step("*OUTPUT, FIELD, FREQUENCY=2\n*NODE OUTPUT\nU, RF\n"
                              "*ELEMENT OUTPUT, ELSET=CUBE, POSITION=CENTROIDAL\nS, E, MISES\n"
                              "*CONTACT OUTPUT, SECONDARY=TOP, MAIN=BOTTOM\nCPRESS, COPEN, CSTATUS\n"
                              "*OUTPUT, HISTORY, VARIABLE=PRESELECT\n*NODE OUTPUT, NSET=ALL\nU3, RF3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& out = r.model.steps[0].output;
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[0].kind, Kind::NodeField);
  EXPECT_EQ(out[0].variables, (std::vector<std::string>{"U", "RF"}));
  EXPECT_EQ(out[0].frequency, 2);
  EXPECT_TRUE(out[0].set.empty());
  EXPECT_FALSE(out[0].preselect);
  EXPECT_EQ(out[1].kind, Kind::ElementField);
  EXPECT_EQ(out[1].set, "CUBE");
  EXPECT_EQ(out[1].position, model::OutputRequest::Position::Centroidal);
  EXPECT_EQ(out[1].variables, (std::vector<std::string>{"S", "E", "MISES"}));
  EXPECT_EQ(out[2].kind, Kind::ContactField);
  EXPECT_EQ(out[2].surface, "TOP");
  EXPECT_EQ(out[2].master, "BOTTOM");
  EXPECT_EQ(out[2].variables.size(), 3u);
  // *OUTPUT, HISTORY, VARIABLE=PRESELECT is a request of its own; history FREQUENCY defaults to 1.
  EXPECT_EQ(out[3].kind, Kind::ModelHistory);
  EXPECT_TRUE(out[3].preselect);
  EXPECT_EQ(out[3].frequency, 1);
  EXPECT_EQ(out[4].kind, Kind::NodeHistory);
  EXPECT_EQ(out[4].set, "ALL");
  EXPECT_EQ(out[4].variables, (std::vector<std::string>{"U3", "RF3"}));
}

TEST(Output, NumberIntervalTimeMarksAndOpAreRecorded) {
  DeckDir dir;
  auto r = dir.read(cube_step("*OUTPUT, FIELD, NUMBER INTERVAL=10, TIME MARKS=YES, OP=NEW, VARIABLE=ALL\n"
                              "*ELEMENT OUTPUT, VARIABLE=PRESELECT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& out = r.model.steps[0].output;
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].kind, Kind::ModelField);
  EXPECT_TRUE(out[0].all);
  for (const auto& o : out) {
    EXPECT_EQ(o.number_interval, 10);
    EXPECT_TRUE(o.time_marks);
    EXPECT_EQ(o.op, model::OutputRequest::Op::New);
  }
  EXPECT_TRUE(out[1].preselect);
}

TEST(Output, PrintAndFileRequests) {
  DeckDir dir;
  auto r = dir.read(cube_step("*NODE PRINT, NSET=ALL, FREQUENCY=0, TOTALS=YES, SUMMARY=NO\nU,\nRF\n"
                              "*EL PRINT, ELSET=CUBE, POSITION=AVERAGED AT NODES\nS, PEEQ\n"
                              "*CONTACT PRINT, SLAVE=TOP\n*NODE FILE\nU, PU\n*EL FILE\nS, SDV\n"
                              "*CONTACT FILE\nCDIS, CSTR\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& out = r.model.steps[0].output;
  ASSERT_EQ(out.size(), 6u);
  EXPECT_EQ(out[0].kind, Kind::NodePrint);
  EXPECT_EQ(out[0].frequency, 0);
  EXPECT_TRUE(out[0].totals);
  EXPECT_FALSE(out[0].summary);
  EXPECT_EQ(out[0].variables, (std::vector<std::string>{"U", "RF"}));
  EXPECT_EQ(out[1].kind, Kind::ElementPrint);
  EXPECT_EQ(out[1].position, model::OutputRequest::Position::AveragedAtNodes);
  EXPECT_EQ(out[2].kind, Kind::ContactPrint);
  EXPECT_TRUE(out[2].preselect);  // no data lines: the default contact variables
  EXPECT_EQ(out[2].surface, "TOP");
  EXPECT_EQ(out[3].kind, Kind::NodeFile);
  EXPECT_EQ(out[3].variables, (std::vector<std::string>{"U", "PU"}));
  EXPECT_EQ(out[4].kind, Kind::ElementFile);
  EXPECT_EQ(out[5].kind, Kind::ContactFile);
  EXPECT_EQ(out[5].variables, (std::vector<std::string>{"CDIS", "CSTR"}));
}

// CalculiX reads the first four letters of its contact keys (its beamcontact.inp asks for CSTRE)
// and takes NOE for "no error estimate"; Abaqus's CSTRESS and CDISP keep their names.
TEST(Output, CalculixSpellingsOfContactAndErrorKeys) {
  DeckDir dir;
  auto r = dir.read(cube_step("*EL FILE\nS, NOE\n*CONTACT FILE\nCDIS, CSTRE\n*OUTPUT, FIELD\n*CONTACT OUTPUT\nCSTRESS, CDISP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& out = r.model.steps[0].output;
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].variables, (std::vector<std::string>{"S", "NOE"}));
  EXPECT_EQ(out[1].variables, (std::vector<std::string>{"CDIS", "CSTR"}));
  EXPECT_EQ(out[2].variables, (std::vector<std::string>{"CSTRESS", "CDISP"}));
}

TEST(Output, UnknownVariableSuggestsTheClosestName) {
  DeckDir dir;
  auto r = dir.read(cube_step("*OUTPUT, FIELD\n*CONTACT OUTPUT\nCPRESS, CPRES\n*NODE OUTPUT\nU, S\n*EL PRINT\nMISES, SXX\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:9: error: *CONTACT OUTPUT: unknown contact output variable 'CPRES' (did you "
                                "mean CPRESS?)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:4: error: *NODE OUTPUT: unknown node output variable 'S' (S is an element "
                                "variable: request it with *ELEMENT OUTPUT / *EL PRINT / *EL FILE)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:8: error: *EL PRINT: unknown element output variable 'SXX'")) << r.report();
}

// *ELEMENT OUTPUT's optional first data line of section point numbers (Abaqus: up to 16 on it):
// sorted and unique; a request without it keeps the default (empty).
TEST(Output, ElementOutputReadsASectionPointLine) {
  DeckDir dir;
  auto r = dir.read(cube_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\n5, 1, 3, 3\nS, E\n*ELEMENT OUTPUT\nS\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& out = r.model.steps[0].output;
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].section_points, (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(out[0].variables, (std::vector<std::string>{"S", "E"}));
  EXPECT_TRUE(out[1].section_points.empty());
  auto bad = dir.read(cube_step("*OUTPUT, FIELD\n*ELEMENT OUTPUT\n0, 2.5\nS\n*ELEMENT OUTPUT\n"
                                "1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17\nS\n"));
  EXPECT_TRUE(has_diagnostic(bad, "deck.inp:24:1: error: *ELEMENT OUTPUT: a section point is a positive integer, found '0'"))
      << bad.report();
  EXPECT_TRUE(has_diagnostic(bad, "error: *ELEMENT OUTPUT: a section point is a positive integer, found '2.5'"))
      << bad.report();
  EXPECT_TRUE(has_diagnostic(bad, "deck.inp:27:56: error: *ELEMENT OUTPUT: at most 16 section points on a line"))
      << bad.report();
}

TEST(Output, SubOptionsNeedOutputAndEveryRequestIsStepData) {
  DeckDir dir;
  auto r = dir.read(cube_step("*NODE OUTPUT\nU\n*OUTPUT\n*OUTPUT, FIELD\n*NODE OUTPUT, NSET=NOPE\nU\n*ELEMENT OUTPUT\n"
                              "*CONTACT OUTPUT, SLAVE=TOPP\nCSTATUS\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *NODE OUTPUT: must follow *OUTPUT")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:1: error: *OUTPUT: give exactly one of FIELD and HISTORY")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:26:20: error: *NODE OUTPUT: node set 'NOPE' is not defined")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:1: error: *ELEMENT OUTPUT: list the output variables on data lines, or give "
                                "VARIABLE=PRESELECT or ALL"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:29:24: error: *CONTACT OUTPUT: surface 'TOPP' is not defined (did you mean 'TOP'?)"))
      << r.report();
  auto model_level = dir.read(one_cube_deck("*NODE PRINT\nU\n"));
  EXPECT_TRUE(has_diagnostic(model_level, "deck.inp:16:1: error: *NODE PRINT: not allowed in the model data; it belongs "
                                          "in *STEP"))
      << model_level.report();
}

TEST(Output, AbaqusVariablesInpactDoesNotComputeAreStillRequests) {
  // DG (the deformation gradient) and FV are Abaqus variables: the request is read, and the run
  // says what it does not compute.
  DeckDir dir;
  auto r = dir.read(cube_step("*EL PRINT, ELSET=CUBE\nDG, FV1\n*OUTPUT, FIELD\n*ELEMENT OUTPUT\nSE, SK\n"));
  ASSERT_TRUE(r.ok()) << r.report();
}
