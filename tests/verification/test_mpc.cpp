// *MPC (parser/kw_equation.cpp). References:
//  - TIE, mpc_tie_c3d8.inp: two unit cubes stacked with coincident nodes tied, pulled by 100
//    (E = 1000, ν = 0): the top rises by 0.2 exactly and each tied pair moves as one;
//  - TIE, mpc_tie_b33.inp: a B33 cantilever in two halves tied at x = 5 bends and twists as one
//    beam (the tie joins the rotations of beam nodes): Euler–Bernoulli's closed forms, which B33
//    meets at the nodes;
//  - BEAM, mpc_beam_b33_offset.inp: a rigid segment inside a B33 cantilever, and a load on an arm
//    tied to the tip: bending and twist of the flexible lengths only (closed forms in the deck);
//  - BEAM as a spider: the column of test_rigid_bodies.cpp with its top face tied to the
//    reference node by one MPC BEAM line instead of *RIGID BODY, TIE NSET: the same answer.
#include "verification_fixture.hpp"

#include <cmath>

#include "solver/elements/beam_section.hpp"

namespace inpact::verification {
namespace {

// Measured: U3 of the top 0.2 to 1.1e-16, the tied pairs equal to 0.
TEST(Mpc, TiedCubesCarryTheLoadAsOneColumn) {
  const auto r = run_deck(deck_path("mpc_tie_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  EXPECT_EQ(m.equations.size(), 12u);  // 4 pairs × 3 DOFs
  double worst_top = 0.0, worst_pair = 0.0;
  for (std::int32_t n : nset(m, "TOP")) worst_top = std::max(worst_top, std::abs(nodal(f, "U", n, 2) - 0.2));
  const auto upper = nset(m, "UPPER_BOTTOM"), lower = nset(m, "LOWER_TOP");
  ASSERT_EQ(upper.size(), lower.size());
  for (std::size_t i = 0; i < upper.size(); ++i)
    for (int c = 0; c < 3; ++c) worst_pair = std::max(worst_pair, std::abs(nodal(f, "U", upper[i], c) - nodal(f, "U", lower[i], c)));
  report("mpc tie: |U3(top) - 0.2|", worst_top);
  report("mpc tie: |U(upper) - U(lower)| over the tied pairs", worst_pair);
  EXPECT_LE(worst_top, 1e-12);
  EXPECT_LE(worst_pair, 1e-15);
}

// The B33 decks: RECT 0.3 × 0.2 with n1 = y, bending in x–y about I22 = 0.2·0.3³/12.
constexpr double kE = 2.0e5, kI22 = 4.5e-4;

double torsional_stiffness() {
  model::BeamSection section;
  section.dims = {0.3, 0.2};
  return kE / 2.6 * solver::elements::beam_properties(section, kE, 0.3).torsion;
}

std::size_t row_of(const Run& r, std::int64_t label) {
  return static_cast<std::size_t>(*r.model().mesh.nodes.index.find(0, label));
}

void expect_close(double value, double exact, const std::string& what) {
  EXPECT_NEAR(value, exact, 1e-9 * std::abs(exact)) << what;
  report(what + ": relative error", std::abs(value - exact) / std::abs(exact));
}

// Measured: every quantity to 1e-14 or better.
TEST(Mpc, TieJoinsTheRotationsOfBeamNodes) {
  const auto r = run_deck(deck_path("mpc_tie_b33.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const std::size_t tip = row_of(*r, 4);
  const solver::Frame& bend = *r->capture.of_step(1).back();
  const solver::Frame& twist = *r->capture.of_step(2).back();
  expect_close(nodal(bend, "U", tip, 1), 1000.0 / (3 * kE * kI22), "tied halves: tip deflection / PL^3/(3EI)");
  expect_close(nodal(bend, "UR", tip, 2), 100.0 / (2 * kE * kI22), "tied halves: tip rotation / PL^2/(2EI)");
  expect_close(nodal(twist, "UR", tip, 0), 5.0 * 10.0 / torsional_stiffness(), "tied halves: twist / TL/(GJ)");
}

// Measured: every quantity to 1e-14 or better.
TEST(Mpc, RigidBeamStiffensItsSegmentAndCarriesAnOffsetLoad) {
  const auto r = run_deck(deck_path("mpc_beam_b33_offset.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const std::size_t tip = row_of(*r, 6), arm = row_of(*r, 7), link_end = row_of(*r, 4), link_start = row_of(*r, 3);
  const double GJ = torsional_stiffness();
  const solver::Frame& bend = *r->capture.of_step(1).back();
  expect_close(nodal(bend, "U", tip, 1), 848.0 / (3 * kE * kI22), "rigid segment: tip deflection");
  expect_close(nodal(bend, "UR", tip, 2), 40.0 / (kE * kI22), "rigid segment: tip rotation");
  // The link's far end moves with its start: v4 = v3 + 2·θ3, the same rotation.
  expect_close(nodal(bend, "U", link_end, 1), nodal(bend, "U", link_start, 1) + 2 * nodal(bend, "UR", link_start, 2),
               "rigid segment: far end follows");
  expect_close(nodal(bend, "UR", link_end, 2), nodal(bend, "UR", link_start, 2), "rigid segment: far end turns with it");
  const solver::Frame& twist = *r->capture.of_step(2).back();
  expect_close(nodal(twist, "UR", tip, 0), 5.0 * 8.0 / GJ, "rigid segment: twist of the flexible 8");
  // The arm's unit force along y at one above the tip: the tip bends as in step 1 and twists
  // by the torque −1; the arm's end moves by v − θ1.
  const solver::Frame& offset = *r->capture.of_step(3).back();
  expect_close(nodal(offset, "U", tip, 1), 848.0 / (3 * kE * kI22), "offset load: tip deflection");
  expect_close(nodal(offset, "UR", tip, 0), -8.0 / GJ, "offset load: tip twist");
  expect_close(nodal(offset, "U", arm, 1), nodal(offset, "U", tip, 1) + 8.0 / GJ, "offset load: the arm's end");
  EXPECT_NEAR(nodal(offset, "RM", row_of(*r, 1), 0), 1.0, 1e-9);  // the root carries the torque
}

// Measured: the spider's displacements equal the rigid body's to 0 (the same rules).
TEST(Mpc, BeamSpiderGivesTheRigidBodyAnswer) {
  const auto rigid = run_deck(deck_path("rigid_moment_block_c3d8.inp"));
  const auto path = edited_deck("rigid_moment_block_c3d8.inp", "mpc-spider", [](const std::string& line) {
    if (line == "*RIGID BODY, REF NODE=REF, TIE NSET=TOP") return std::vector<std::string>{"*MPC", "BEAM, TOP, REF"};
    return std::vector<std::string>{line};
  });
  const auto spider = run_deck(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(rigid->outcome.completed) << rigid->outcome.message;
  ASSERT_TRUE(spider->outcome.completed) << spider->outcome.message;
  ASSERT_EQ(spider->model().rigid_bodies.size(), 1u);
  EXPECT_TRUE(spider->model().rigid_bodies[0].mpc_beam);
  const auto& a = rigid->capture.last();
  const auto& b = spider->capture.last();
  double worst = 0.0, largest = 0.0;
  for (std::size_t n = 0; n < rigid->model().mesh.nodes.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(nodal(a, "U", n, c) - nodal(b, "U", n, c)));
      largest = std::max(largest, std::abs(nodal(a, "U", n, c)));
    }
  report("MPC BEAM spider against *RIGID BODY: max |dU| / max |U|", worst / largest);
  EXPECT_LE(worst, 1e-12 * largest);
}

}  // namespace
}  // namespace inpact::verification
