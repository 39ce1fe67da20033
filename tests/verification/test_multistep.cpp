// Case 6: multi-step history on a bar (4 × 1 × 1, E = 1000, A = 1, ν = 0: uniaxial, EA = 1000),
// x = 0 held. Load groups act on the faces x = 2 (MID), 3 (Q) and 4 (RIGHT).
//  Step 1 (DIRECT 0.5): MID held, 100 (4 × 25) at RIGHT, ramped.
//    t = 1: segment 2–4 carries 100 → u(3) = 0.1, u(4) = 0.2; RF1(MID) = −100, RF1(LEFT) = 0.
//  Step 2 (DIRECT 0.25): *BOUNDARY, OP=NEW keeps LEFT and the symmetry planes only: MID is
//    released and its reaction −100 is left as a load that ramps to zero; *CLOAD, OP=NEW
//    removes the RIGHT load (ramps from 100 to 0) and puts 60·a(t) at Q, a = (0,0) (0.5,1) (1,0.5).
//    With F_R = 100(1−t), F_M = −100(1−t), F_Q = 60 a(t):
//    u(2) = 2 F_Q/EA, u(3) = u(2) + (F_R + F_Q)/EA, u(4) = u(3) + F_R/EA, RF1(LEFT) = −F_Q.
//  Step 3 (DIRECT 0.25): RIGHT driven to u1 = 0.4 from where it is (0.09 → 0.4, ramped), 30 at Q
//    (the step-2 end value, constant): N34 = (1000 u4 − 90)/4, RF1(RIGHT) = N34,
//    RF1(LEFT) = −(N34 + 30).
#include <fstream>
#include <iterator>
#include <string>

#include "fixtures/deck_fixture.hpp"
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

double face_u1(const Run& r, const solver::Frame& f, const char* set) {
  double s = 0;
  const auto rows = nset(r.model(), set);
  for (std::int32_t n : rows) s += nodal(f, "U", static_cast<std::size_t>(n), 0);
  return s / static_cast<double>(rows.size());
}

double face_rf1(const Run& r, const solver::Frame& f, const char* set) {
  double s = 0;
  for (std::int32_t n : nset(r.model(), set)) s += nodal(f, "RF", static_cast<std::size_t>(n), 0);
  return s;
}

double amplitude_a2(double t) { return t <= 0.5 ? 2 * t : 1.0 - (t - 0.5); }

TEST(MultiStep, OpNewLoadsAndReleasedSupportsRampToZeroAndAmplitudesDriveLoads) {
  const auto r = run_deck(deck_path("multistep_bar.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double EA = 1000.0, tol = 1e-10;  // linear problem: exact to round-off
  double worst = 0;
  auto expect = [&](double got, double want, const std::string& what) {
    worst = std::max(worst, std::abs(got - want));
    EXPECT_NEAR(got, want, tol * std::max(1.0, std::abs(want))) << what;
  };

  // Step 1.
  const auto s1 = r->capture.of_step(1);
  ASSERT_EQ(s1.size(), 2u);
  for (const auto* f : s1) {
    const double t = f->step_time, F = 100 * t;
    expect(face_u1(*r, *f, "MID"), 0.0, "step 1 u(2)");
    expect(face_u1(*r, *f, "Q"), F / EA, "step 1 u(3)");
    expect(face_u1(*r, *f, "RIGHT"), 2 * F / EA, "step 1 u(4)");
    expect(face_rf1(*r, *f, "MID"), -F, "step 1 RF(MID)");
    expect(face_rf1(*r, *f, "LEFT"), 0.0, "step 1 RF(LEFT)");
    expect_balance(*r, *f, {F, 0, 0}, 1e-12, "multistep step 1 t=" + std::to_string(t));
  }

  // Step 2.
  const auto s2 = r->capture.of_step(2);
  ASSERT_EQ(s2.size(), 4u);
  for (const auto* f : s2) {
    const double t = f->step_time;
    const double FR = 100 * (1 - t), FM = -100 * (1 - t), FQ = 60 * amplitude_a2(t);
    const double u2 = 2 * FQ / EA, u3 = u2 + (FR + FQ) / EA, u4 = u3 + FR / EA;
    const std::string at = " at step 2 t = " + std::to_string(t);
    expect(face_u1(*r, *f, "MID"), u2, "u(2)" + at);
    expect(face_u1(*r, *f, "Q"), u3, "u(3)" + at);
    expect(face_u1(*r, *f, "RIGHT"), u4, "u(4)" + at);
    expect(face_rf1(*r, *f, "LEFT"), -FQ, "RF(LEFT)" + at);
    expect(face_rf1(*r, *f, "MID"), 0.0, "RF(MID) (released)" + at);
    expect_balance(*r, *f, {FR + FM + FQ, 0, 0}, 1e-12, "multistep step 2 t=" + std::to_string(t));
  }

  // Step 3.
  const auto s3 = r->capture.of_step(3);
  ASSERT_EQ(s3.size(), 4u);
  for (const auto* f : s3) {
    const double t = f->step_time;
    const double u4 = 0.09 + (0.4 - 0.09) * t, N34 = (EA * u4 - 90) / 4;
    const std::string at = " at step 3 t = " + std::to_string(t);
    expect(face_u1(*r, *f, "RIGHT"), u4, "u(4)" + at);
    expect(face_u1(*r, *f, "Q"), 3 * (N34 + 30) / EA, "u(3)" + at);
    expect(face_rf1(*r, *f, "RIGHT"), N34, "RF(RIGHT)" + at);
    expect(face_rf1(*r, *f, "LEFT"), -(N34 + 30), "RF(LEFT)" + at);
    expect_balance(*r, *f, {30, 0, 0}, 1e-12, "multistep step 3 t=" + std::to_string(t));
  }
  report("multistep: worst |value - hand value|", worst);
  report("multistep: Newton iterations (10 increments)", r->capture.iterations);
}

/// The multistep bar's text with `from` replaced by `to` (once, where it must be).
std::string bar_with(const std::string& from, const std::string& to) {
  std::ifstream in(deck_path("multistep_bar.inp"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Abaqus/CAE writes each boundary condition and load of a step as its own block, every one with
// OP=NEW when any changes: OP=NEW removes what earlier steps defined, not the step's other
// blocks. And two loads at one DOF in one step add up (Abaqus, CalculiX). Step 2 of the bar
// written so (its three support lines as three OP=NEW blocks, its 15 at Q as 10 + 5 in two
// OP=NEW blocks) gives the same U at every increment, to 1e-14 (RF to 1e-11).
TEST(MultiStep, OpNewOnEachBlockOfAStepKeepsTheStepsOwnAndLoadsAtOneDofAdd) {
  const std::string step2 =
      "*BOUNDARY, OP=NEW\nLEFT, 1, 1\nY0, 2, 2\nZ0, 3, 3\n*CLOAD, OP=NEW, AMPLITUDE=A2\nQ, 1, 15.\n";
  const std::string as_cae_writes = "*BOUNDARY, OP=NEW\nLEFT, 1, 1\n*BOUNDARY, OP=NEW\nY0, 2, 2\n*BOUNDARY, OP=NEW\n"
                                    "Z0, 3, 3\n*CLOAD, OP=NEW, AMPLITUDE=A2\nQ, 1, 10.\n"
                                    "*CLOAD, OP=NEW, AMPLITUDE=A2\nQ, 1, 5.\n";
  const std::string cae = bar_with(step2, as_cae_writes);
  const test::DeckDir dir;
  const auto written = run_deck(dir.write("cae.inp", cae));
  const auto reference = run_deck(deck_path("multistep_bar.inp"));
  ASSERT_TRUE(written->outcome.completed && reference->outcome.completed) << written->outcome.message;
  ASSERT_EQ(written->capture.frames.size(), reference->capture.frames.size());
  for (std::size_t k = 0; k < reference->capture.frames.size(); ++k) {
    const solver::Frame &got = written->capture.frames[k].frame, &want = reference->capture.frames[k].frame;
    for (std::size_t n = 0; n < reference->model().mesh.nodes.size(); ++n)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(nodal(got, "U", n, c), nodal(want, "U", n, c), 1e-14) << "frame " << k << " node " << n;
        EXPECT_NEAR(nodal(got, "RF", n, c), nodal(want, "RF", n, c), 1e-11) << "frame " << k << " node " << n;
      }
  }
}

// Loads that add up need one amplitude: a second load at Q in step 2 under the step's own ramp
// is a deck error at its line.
TEST(MultiStep, LoadsAtOneDofInOneStepWithTwoAmplitudesAreRefused) {
  const std::string deck = bar_with("*CLOAD, OP=NEW, AMPLITUDE=A2\nQ, 1, 15.\n",
                                    "*CLOAD, OP=NEW, AMPLITUDE=A2\nQ, 1, 10.\n*CLOAD\nQ, 1, 5.\n");
  const test::DeckDir dir;
  const std::string message = stop_message(dir.write("two.inp", deck));
  EXPECT_NE(message.find("two.inp:79:1: error: *CLOAD: node"), std::string::npos) << message;
  EXPECT_NE(message.find("is loaded earlier in this step with AMPLITUDE=A2; loads at one DOF in one step add up and "
                         "need one amplitude"),
            std::string::npos)
      << message;
}

/// A unit cube of one C3D8 (node set ALL, element set CUBE), E = 1000, ν = 0.3, density 2.
const std::string kUnitCube =
    "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 0., 0., 1.\n6, 1., 0., 1.\n"
    "7, 1., 1., 1.\n8, 0., 1., 1.\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
    "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n2.\n";

// Two gravities and two pressures on one cube in one step (1 × 1 × 1 C3D8, density 2, its base
// held): GRAV 10 along −z and 5 along +x, P 3 and 4 on its top. And a *DSLOAD of 5 on a surface
// that names the top face twice: a surface is a set of faces, loaded once. The base carries
// −(ρ V g) and the pressures' 7 + 5: ΣRF = (−10, 0, 20 + 12), to 1e-10.
TEST(MultiStep, GravitiesAndPressuresInOneStepAdd) {
  const std::string deck =
      kUnitCube + "*NSET, NSET=BASE\n1, 2, 3, 4\n*SURFACE, NAME=TOP\nCUBE, S2\nCUBE, S2\n"
      "*BOUNDARY\nBASE, ENCASTRE\n*STEP\n*STATIC\n*DLOAD\nCUBE, GRAV, 10., 0., 0., -1.\nCUBE, P2, 3.\n"
      "*DLOAD\nCUBE, GRAV, 5., 1., 0., 0.\nCUBE, P2, 4.\n*DSLOAD\nTOP, P, 5.\n*OUTPUT, FIELD\n*NODE OUTPUT\nRF\n"
      "*END STEP\n";
  const test::DeckDir dir;
  const auto r = run_deck(dir.write("cube.inp", deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto rf = sum_rf(*r, r->capture.last());
  EXPECT_NEAR(rf[0], -10.0, 1e-10);
  EXPECT_NEAR(rf[1], 0.0, 1e-10);
  EXPECT_NEAR(rf[2], 32.0, 1e-10);
}

// A whole-model GRAV in a model with a spring (which has no mass) loads the cube alone.
TEST(MultiStep, GravityOverAModelWithASpringLoadsTheMassOnly) {
  const std::string deck =
      kUnitCube + "*ELEMENT, TYPE=SPRING1, ELSET=SP\n2, 7\n*SPRING, ELSET=SP\n1\n100.\n*BOUNDARY\nALL, 1, 3\n"
                  "*STEP\n*STATIC\n*DLOAD\n, GRAV, 10., 0., 0., -1.\n*END STEP\n";
  const test::DeckDir dir;
  const auto r = run_deck(dir.write("cube.inp", deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  EXPECT_NEAR(sum_rf(*r, r->capture.last())[2], 20.0, 1e-10);
}

// A held unit cube (density 2) under GRAV 10 along −z, turned to −y in step 2 (two increments):
// the gravity vector ramps from (0, 0, −10) to (0, −10, 0), so Σ RF = −ρ V g(t) is (0, 10, 10) at
// half the step and (0, 20, 0) at its end. Ramping the new direction from the old size would
// give (0, 20, 0) at half the step.
TEST(MultiStep, GravityTurnedInALaterStepTurnsAsItRamps) {
  const std::string deck =
      kUnitCube + "*BOUNDARY\nALL, 1, 3\n*STEP\n*STATIC\n*DLOAD\nCUBE, GRAV, 10., 0., 0., -1.\n*END STEP\n"
      "*STEP\n*STATIC\n0.5, 1.\n*DLOAD\nCUBE, GRAV, 10., 0., -1., 0.\n*END STEP\n";
  const test::DeckDir dir;
  const auto r = run_deck(dir.write("cube.inp", deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto frames = r->capture.of_step(2);
  ASSERT_EQ(frames.size(), 2u);
  for (const auto& [frame, expected] : {std::pair{r->capture.of_step(1).back(), std::array<double, 3>{0, 0, 20}},
                                        std::pair{frames[0], std::array<double, 3>{0, 10, 10}},
                                        std::pair{frames[1], std::array<double, 3>{0, 20, 0}}}) {
    const auto rf = sum_rf(*r, *frame);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rf[c], expected[c], 1e-10) << "component " << c;
  }
}

}  // namespace
}  // namespace inpact::verification
