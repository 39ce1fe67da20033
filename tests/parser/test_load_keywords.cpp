// *BOUNDARY *CLOAD *DLOAD *DSLOAD *TEMPERATURE *INITIAL CONDITIONS *AMPLITUDE *EQUATION.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {
/// The cube with a bottom node set, a top surface and an open step; `step` goes inside it.
std::string cube_step(const std::string& model_data, const std::string& step) {
  return one_cube_deck("*NSET, NSET=BOT\n1, 2, 3, 4\n*SURFACE, NAME=TOP\nCUBE, S2\n" + model_data + "*STEP\n*STATIC\n" +
                       step + "*END STEP\n");
}
}  // namespace

TEST(Boundary, ModelDataWithTypeNamesExpandedToDofRanges) {
  DeckDir dir;
  auto r = dir.read(cube_step("*BOUNDARY\nBOT, ENCASTRE\n5, XSYMM\n6, 2\n7, 1, 3, 0.5\n8, ZASYMM\n", ""));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.boundaries.size(), 1u);
  const auto& e = r.model.boundaries[0].entries;
  ASSERT_EQ(e.size(), 7u);
  // ENCASTRE: DOFs 1-6 on the four bottom nodes.
  EXPECT_EQ(e[0].target, "BOT");
  EXPECT_EQ(e[0].nodes, (std::vector<std::int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(e[0].first_dof, 1);
  EXPECT_EQ(e[0].last_dof, 6);
  EXPECT_EQ(e[0].value, 0.0);
  // XSYMM: u1 = ur2 = ur3 = 0 → DOF 1 and DOFs 5-6.
  EXPECT_EQ(e[1].nodes, (std::vector<std::int32_t>{4}));
  EXPECT_EQ(std::pair(e[1].first_dof, e[1].last_dof), std::pair(1, 1));
  EXPECT_EQ(std::pair(e[2].first_dof, e[2].last_dof), std::pair(5, 6));
  // Direct format: last DOF defaults to the first, the value to 0.
  EXPECT_EQ(std::pair(e[3].first_dof, e[3].last_dof), std::pair(2, 2));
  EXPECT_EQ(e[3].value, 0.0);
  EXPECT_EQ(std::pair(e[4].first_dof, e[4].last_dof), std::pair(1, 3));
  EXPECT_EQ(e[4].value, 0.5);
  // ZASYMM: u1 = u2 = ur3 = 0.
  EXPECT_EQ(std::pair(e[5].first_dof, e[5].last_dof), std::pair(1, 2));
  EXPECT_EQ(std::pair(e[6].first_dof, e[6].last_dof), std::pair(6, 6));
  EXPECT_EQ(e[6].loc.line, 25u);
}

TEST(Boundary, HistoryDataRecordsOpAmplitudeAndFixed) {
  DeckDir dir;
  auto r = dir.read(cube_step("*AMPLITUDE, NAME=Ramp1\n0., 0., 1., 1.\n",
                              "*BOUNDARY, OP=NEW, AMPLITUDE=ramp1\nBOT, 3, 3, -0.1\n*BOUNDARY, OP=NEW, FIXED\n5, 1, 3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_TRUE(r.model.boundaries.empty());
  const auto& b = r.model.steps[0].boundaries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].op, model::Op::New);
  EXPECT_EQ(b[0].amplitude, "RAMP1");
  EXPECT_EQ(b[0].entries[0].value, -0.1);
  EXPECT_FALSE(b[0].fixed);
  EXPECT_TRUE(b[1].fixed);
}

TEST(Boundary, ErrorsCiteTheField) {
  DeckDir dir;
  auto r = dir.read(cube_step("*BOUNDARY\nBOT, ENCASTER\n5, 3, 1\n6, 7\n",
                              "*BOUNDARY\n5, 1\n*BOUNDARY, OP=NEW\n6, 1\n*BOUNDARY, TYPE=VELOCITY\n7, 1, 1, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:6: error: *BOUNDARY: 'ENCASTER' is not a boundary type (did you mean ENCASTRE?)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:7: error: *BOUNDARY: the last DOF 1 is smaller than the first DOF 3"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:4: error: *BOUNDARY: degree of freedom 7 is out of range 1..6")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:28:15: error: *BOUNDARY: OP must be the same on every *BOUNDARY of a step (line "
                                "26 has OP=MOD)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:30:17: error: *BOUNDARY: TYPE=VELOCITY is not supported")) << r.report();
}

TEST(Boundary, ModelDataAfterAStepIsAnError) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n*END STEP\n*BOUNDARY\n1, 1\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:19:1: error: *BOUNDARY: model data must come before the first *STEP"))
      << r.report();
}

TEST(Loads, CloadDloadAndTemperatureInAStep) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*NSET, NSET=BOT\n1, 2, 3, 4\n*STEP\n*STATIC\n"
                                  "*CLOAD\n7, 3, -100.\nBOT, 1, 2.\n"
                                  "*DLOAD, OP=NEW\nCUBE, P2, 5.\n1, GRAV, 9.81, 0, 0, -2\n1, BZ, 3.\n"
                                  "*TEMPERATURE, AMPLITUDE=A\nALL, 100.\n*AMPLITUDE, NAME=A\n0,0,1,1\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.steps[0];
  ASSERT_EQ(s.cloads.size(), 1u);
  const auto& c = s.cloads[0].entries;
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].nodes, (std::vector<std::int32_t>{6}));
  EXPECT_EQ(c[0].dof, 3);
  EXPECT_EQ(c[0].magnitude, -100.0);
  EXPECT_EQ(c[1].nodes.size(), 4u);
  EXPECT_EQ(s.cloads[0].op, model::Op::Mod);

  ASSERT_EQ(s.dloads.size(), 1u);
  EXPECT_EQ(s.dloads[0].op, model::Op::New);
  EXPECT_FALSE(s.dloads[0].surface_load);
  const auto& d = s.dloads[0].entries;
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].kind, model::DloadEntry::Kind::Pressure);
  EXPECT_EQ(d[0].faces, (std::vector<std::uint8_t>{1}));  // P2 = face S2
  EXPECT_EQ(d[0].magnitude, 5.0);
  EXPECT_EQ(d[1].kind, model::DloadEntry::Kind::Gravity);
  EXPECT_EQ(d[1].magnitude, 9.81);
  EXPECT_EQ(d[1].direction, (std::array<double, 3>{0, 0, -1}));  // normalised
  EXPECT_EQ(d[2].kind, model::DloadEntry::Kind::BodyForce);
  EXPECT_EQ(d[2].direction, (std::array<double, 3>{0, 0, 1}));

  ASSERT_EQ(s.temperatures.size(), 1u);
  EXPECT_EQ(s.temperatures[0].amplitude, "A");
  EXPECT_EQ(s.temperatures[0].entries[0].nodes.size(), 8u);
  EXPECT_EQ(s.temperatures[0].entries[0].value, 100.0);
}

TEST(Loads, GravityNeedsADensity) {
  DeckDir dir;
  auto r = dir.read(cube_step("", "*DLOAD\nCUBE, GRAV, 9.81, 0, 0, -1\n"));
  EXPECT_TRUE(has_diagnostic(
      r, "deck.inp:23:1: error: *DLOAD: GRAV needs the density of material 'STEEL' (add *DENSITY to it)"))
      << r.report();
  auto ok = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*STEP\n*STATIC\n*DLOAD\nCUBE, GRAV, 9.81, 0, 0, -1\n*END STEP\n"));
  EXPECT_TRUE(ok.ok()) << ok.report();
}

TEST(Loads, CentrifugalLoadReadsItsAxis) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*STEP\n*STATIC\n*DLOAD\nCUBE, CENTRIF, 1e4, 1, 2, 0, 0, 0, 2\n"
                                  "*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& e = r.model.steps[0].dloads[0].entries[0];
  EXPECT_EQ(e.kind, model::DloadEntry::Kind::Centrifugal);
  EXPECT_EQ(e.magnitude, 1e4);
  EXPECT_EQ(e.point, (std::array<double, 3>{1, 2, 0}));
  EXPECT_EQ(e.direction, (std::array<double, 3>{0, 0, 1}));  // normalised
}

TEST(Loads, CentrifugalLoadNeedsADensityAnAxisAndAllNineFields) {
  DeckDir dir;
  auto no_density = dir.read(cube_step("", "*DLOAD\nCUBE, CENTRIF, 1e4, 0, 0, 0, 0, 0, 1\n"));
  EXPECT_TRUE(has_diagnostic(no_density, "CENTRIF needs the density of material 'STEEL' (add *DENSITY to it)"))
      << no_density.report();
  auto zero_axis = dir.read(cube_step("", "*DLOAD\nCUBE, CENTRIF, 1e4, 0, 0, 0, 0, 0, 0\n"));
  EXPECT_TRUE(has_diagnostic(zero_axis, "the rotation axis direction is the zero vector")) << zero_axis.report();
  auto short_line = dir.read(cube_step("", "*DLOAD\nCUBE, CENTRIF, 1e4, 0, 0, 0\n"));
  EXPECT_TRUE(has_diagnostic(short_line, "CENTRIF, omega squared, axis point x, y, z, axis direction x, y, z"))
      << short_line.report();
}

TEST(Loads, RotaryAccelerationReadsItsAxisAndNeedsADensity) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*STEP\n*STATIC\n*DLOAD\nCUBE, ROTA, 50., 1, 2, 0, 0, 0, 2\n"
                                  "*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& e = r.model.steps[0].dloads[0].entries[0];
  EXPECT_EQ(e.kind, model::DloadEntry::Kind::RotaryAcceleration);
  EXPECT_EQ(e.magnitude, 50.0);
  EXPECT_EQ(e.point, (std::array<double, 3>{1, 2, 0}));
  EXPECT_EQ(e.direction, (std::array<double, 3>{0, 0, 1}));
  auto no_density = dir.read(cube_step("", "*DLOAD\nCUBE, ROTA, 50., 0, 0, 0, 0, 0, 1\n"));
  EXPECT_TRUE(has_diagnostic(no_density, "ROTA needs the density of material 'STEEL' (add *DENSITY to it)"))
      << no_density.report();
  auto short_line = dir.read(cube_step("", "*DLOAD\nCUBE, ROTA, 50., 0, 0, 0\n"));
  EXPECT_TRUE(has_diagnostic(short_line, "ROTA, rotary acceleration, axis point x, y, z, axis direction x, y, z"))
      << short_line.report();
}

TEST(Loads, DsloadPutsThePressureOnTheSurfaceFaces) {
  DeckDir dir;
  auto r = dir.read(cube_step("", "*DSLOAD, AMPLITUDE=A\nTOP, P, 2.5\n*AMPLITUDE, NAME=A\n0,0,1,1\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& b = r.model.steps[0].dloads;
  ASSERT_EQ(b.size(), 1u);
  EXPECT_TRUE(b[0].surface_load);
  EXPECT_EQ(b[0].amplitude, "A");
  const auto& e = b[0].entries[0];
  EXPECT_EQ(e.kind, model::DloadEntry::Kind::Pressure);
  EXPECT_EQ(e.elements, (std::vector<std::int32_t>{0}));
  EXPECT_EQ(e.faces, (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(e.magnitude, 2.5);
}

TEST(Loads, PressureLabelsAreCheckedAgainstTheElementFaces) {
  DeckDir dir;
  auto r = dir.read(
      cube_step("", "*DLOAD\nCUBE, P, 1.\nCUBE, P7, 1.\nCUBE, GRV, 1.\n*DSLOAD\nTOPP, P, 1.\n*DLOAD\nCUBE, EDNOR1, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:7: error: *DLOAD: P (without a face number) is for shells: element 1 is "
                                "not one; on solid and plane elements give the face, P1, P2, ..."))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:7: error: *DLOAD: element 1 (C3D8) has no face 7: its pressure labels are P1..P6"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:25:7: error: *DLOAD: load type 'GRV' is not supported (inpact supports Pn, "
                                "GRAV, CENTRIF, ROTA, BX, BY, BZ, and on shell edges EDNORn, EDSHRn, EDTn); did you mean GRAV?"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:29:7: error: *DLOAD: EDNOR1 is a load on a shell's edge; element 1 (C3D8) is "
                                "not a shell"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:27:1: error: *DSLOAD: surface 'TOPP' is not defined (did you mean 'TOP'?)"))
      << r.report();
}

TEST(Loads, StepLoadInTheModelDataIsAnError) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*CLOAD\n7, 3, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:16:1: error: *CLOAD: not allowed in the model data; it belongs in *STEP"))
      << r.report();
  auto r2 = dir.read(cube_step("", "*CLOAD\n*CLOAD, OP=NEW\n"));
  EXPECT_TRUE(has_diagnostic(r2, "deck.inp:22:1: error: *CLOAD: data lines are missing")) << r2.report();
  EXPECT_EQ(r2.model.steps[0].cloads.size(), 1u);  // OP=NEW alone: removes the earlier loads
}

TEST(InitialConditions, TemperatureOnANodeSet) {
  DeckDir dir;
  auto r = dir.read(cube_step("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20.\n7, 25.\n", ""));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& t = r.model.initial_temperatures;
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].nodes.size(), 8u);
  EXPECT_EQ(t[0].value, 20.0);
  EXPECT_EQ(t[1].value, 25.0);
  auto bad = dir.read(cube_step("*INITIAL CONDITIONS, TYPE=STRESS\nCUBE, 1.\n", ""));
  EXPECT_TRUE(has_diagnostic(bad, "deck.inp:20:27: error: *INITIAL CONDITIONS: TYPE=STRESS is not supported yet"))
      << bad.report();
}

// The third field is the gradient through a shell's thickness; a fourth is an error.
TEST(InitialConditions, TemperatureWithAShellGradient) {
  DeckDir dir;
  auto r = dir.read(cube_step("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20., 5.\n", "*TEMPERATURE\nALL, 373., 1000.\n7, 30.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.initial_temperatures.at(0).gradient, 5.0);
  const auto& entries = r.model.steps.at(0).temperatures.at(0).entries;
  EXPECT_EQ(entries.at(0).gradient, 1000.0);
  EXPECT_FALSE(entries.at(1).gradient.has_value());
  auto bad = dir.read(cube_step("", "*TEMPERATURE\nALL, 373., 1000., 2.\n"));
  EXPECT_TRUE(has_diagnostic(bad, "*TEMPERATURE: data line has 4 fields, expected 2 to 3")) << bad.report();
}

TEST(Amplitude, PairsAcrossLinesWithScaleAndShift) {
  DeckDir dir;
  auto r = dir.read(cube_step("*AMPLITUDE, NAME=A1\n0., 0., 0.5, 0.8, 1., 1., 2., 1.5\n3., 0.\n"
                              "*AMPLITUDE, NAME=SS, DEFINITION=SMOOTH STEP, TIME=TOTAL TIME, SCALEY=2., SHIFTX=1.\n0, 0\n1, 1\n"
                              "*AMPLITUDE, NAME=EQ, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5, BEGIN=1.\n0, 1, 0.5\n",
                              ""));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& a = r.model.amplitudes.at("A1");
  EXPECT_EQ(a.name, "A1");
  EXPECT_EQ(a.definition, model::Amplitude::Definition::Tabular);
  EXPECT_EQ(a.time, model::Amplitude::Time::Step);
  ASSERT_EQ(a.points.size(), 5u);
  EXPECT_EQ(a.points[1], (std::array<double, 2>{0.5, 0.8}));
  EXPECT_EQ(a.points[4], (std::array<double, 2>{3.0, 0.0}));
  const auto& ss = r.model.amplitudes.at("SS");
  EXPECT_EQ(ss.definition, model::Amplitude::Definition::SmoothStep);
  EXPECT_EQ(ss.time, model::Amplitude::Time::Total);
  EXPECT_EQ(ss.points[1], (std::array<double, 2>{2.0, 2.0}));
  const auto& eq = r.model.amplitudes.at("EQ");
  ASSERT_EQ(eq.points.size(), 3u);
  EXPECT_EQ(eq.points[2], (std::array<double, 2>{2.0, 0.5}));
}

TEST(Amplitude, DecreasingTimesOddFieldsAndUnsupportedDefinitions) {
  DeckDir dir;
  auto r = dir.read(cube_step("*AMPLITUDE, NAME=A\n0, 0, 1, 1\n0.5, 2\n*AMPLITUDE, NAME=B\n0, 0, 1\n"
                              "*AMPLITUDE, NAME=C, DEFINITION=PERIODIC\n1, 1\n*AMPLITUDE, NAME=b\n0, 0\n",
                              "*CLOAD, AMPLITUDE=NOPE\n7, 1, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *AMPLITUDE: time 0.5 comes after time 1: times must not decrease"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:7: error: *AMPLITUDE: a time without its value")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:25:32: error: *AMPLITUDE: DEFINITION=PERIODIC is not supported yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:27:18: error: *AMPLITUDE: amplitude 'b' is defined twice (first at line 23)")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*CLOAD: amplitude 'NOPE' is not defined")) << r.report();
}

TEST(Equation, TermsContinueOnTheNextLine) {
  DeckDir dir;
  auto r = dir.read(cube_step("*EQUATION\n5\n1, 1, 1., 2, 1, -1., 3, 1, 0.5, 4, 1, 0.5,\n5, 1, -1.\n2\n6, 2, 1., 7, 2, -1.\n",
                              ""));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& eqs = r.model.equations;
  ASSERT_EQ(eqs.size(), 2u);
  ASSERT_EQ(eqs[0].terms.size(), 5u);
  EXPECT_EQ(eqs[0].terms[0].node, 0);
  EXPECT_EQ(eqs[0].terms[1].coefficient, -1.0);
  EXPECT_EQ(eqs[0].terms[4].node, 4);  // node 5, from the continuation line
  EXPECT_EQ(eqs[0].terms[4].dof, 1);
  EXPECT_EQ(eqs[0].loc.line, 21u);
  ASSERT_EQ(eqs[1].terms.size(), 2u);
  EXPECT_EQ(eqs[1].terms[1].node, 6);
  EXPECT_EQ(eqs[1].terms[1].dof, 2);
}

TEST(Equation, SetTermsExpandNodeByNode) {
  DeckDir dir;
  auto r = dir.read(cube_step("*NSET, NSET=TOPN\n6, 5\n*NSET, NSET=BOTN\n1, 2\n*EQUATION\n3\nTOPN, 3, 1., BOTN, 3, -1., 8, 3, 0.5\n",
                              ""));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& eqs = r.model.equations;
  ASSERT_EQ(eqs.size(), 2u);  // one per node of the sets, matched in label order
  EXPECT_EQ(eqs[0].terms[0].node, 4);
  EXPECT_EQ(eqs[0].terms[1].node, 0);
  EXPECT_EQ(eqs[0].terms[2].node, 7);
  EXPECT_EQ(eqs[1].terms[0].node, 5);
  EXPECT_EQ(eqs[1].terms[1].node, 1);
  EXPECT_EQ(eqs[1].terms[2].node, 7);
}

TEST(Equation, CountMismatchAndZeroLeadingCoefficient) {
  DeckDir dir;
  auto r = dir.read(cube_step("*EQUATION\n2\n1, 1, 0., 2, 1, 1.\n3\n1, 2, 1., 2, 2, 1.\n", ""));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:7: error: *EQUATION: the first coefficient cannot be zero")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:1: error: *EQUATION: the equation has 2 terms, expected 3 (the number on its first line)")) << r.report();
  auto sizes = dir.read(cube_step("*EQUATION\n2\nBOT, 1, 1., ALL, 1, -1.\n", ""));
  EXPECT_TRUE(has_diagnostic(sizes, "deck.inp:21:1: error: *EQUATION: the node sets of an equation must have the same "
                                    "number of nodes (4 and 8)"))
      << sizes.report();
}

TEST(Loads, GravityWithoutAnElementSetLoadsTheWholeModel) {
  // Abaqus/CAE writes a model-wide gravity load with the element field empty.
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*STEP\n*STATIC\n*DLOAD\n, GRAV, 9.81, 0, 0, -1\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& e = r.model.steps[0].dloads[0].entries[0];
  EXPECT_EQ(e.kind, model::DloadEntry::Kind::Gravity);
  EXPECT_EQ(e.elements, std::vector<std::int32_t>{0});
  // Other loads still name their elements.
  auto bad = dir.read(one_cube_deck("*STEP\n*STATIC\n*DLOAD\n, BZ, 3.\n*END STEP\n"));
  EXPECT_FALSE(bad.ok());
}

TEST(Loads, GravityInAPlaneModelMayGiveItsDirectionInThePlane) {
  // Abaqus/CAE writes a 2D model's gravity as `, GRAV, g, n1, n2`.
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*DENSITY\n7.8e-9\n*STEP\n*STATIC\n*DLOAD\nCUBE, GRAV, 9.81, 0., -2.\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.steps[0].dloads[0].entries[0].direction, (std::array<double, 3>{0, -1, 0}));
}
