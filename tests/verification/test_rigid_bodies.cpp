// *RIGID BODY (model/rigid_body.hpp, model/rigid_motion.hpp): nodes that follow a reference
// node, u = u_R + (R(θ) − I) r.
//
// References (decks/verification/gen_rigid_bodies.py):
//  - a column built in at its base, its top face tied to a reference node loaded by a force and
//    a moment: the base carries both (Σ RF and Σ r × RF exact), the top face moves rigidly;
//  - a block and a plane-strain plate made rigid as a whole and turned by 90° (NLGEOM) through
//    the reference node's rotation: every node at R X, no reaction;
//  - a rigid flat punch pressed into a block through its reference node: the reaction there is
//    the contact force Σ CPRESS·CNAREA, and CalculiX 2.20 on the same deck in its dialect gives
//    RF3 = −1.017847E+04; the same punch as R3D4 rigid elements gives the same answer.
#include "verification_fixture.hpp"

#include <cmath>
#include <map>
#include <set>

namespace inpact::verification {
namespace {

std::int32_t only_node(const model::Model& m, const std::string& set) {
  const auto rows = nset(m, set);
  EXPECT_EQ(rows.size(), 1u);
  return rows.front();
}

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Measured: Σ RF 2.2e-13 of the load, Σ r × RF 1.6e-13 of the moment (the column's round-off).
TEST(RigidBody, ColumnBaseCarriesTheForceAndMomentOfTheReferenceNode) {
  const auto r = run_deck(deck_path("rigid_moment_block_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const std::int32_t ref = only_node(m, "REF");
  const auto x_ref = coords(m, ref);
  std::array<double, 3> force{0, 0, 0}, moment{0, 0, 0};
  for (std::int32_t n : nset(m, "BASE")) {
    const std::array<double, 3> rf{nodal(f, "RF", n, 0), nodal(f, "RF", n, 1), nodal(f, "RF", n, 2)};
    const auto x = coords(m, n);
    const auto mo = cross({x[0] - x_ref[0], x[1] - x_ref[1], x[2] - x_ref[2]}, rf);
    for (int c = 0; c < 3; ++c) force[c] += rf[c], moment[c] += mo[c];
  }
  // Applied: F = (10, 0, 0), M = (0, 100, 0) at the reference node.
  const double force_error = std::hypot(force[0] + 10.0, force[1], force[2]) / 10.0;
  const double moment_error = std::hypot(moment[0], moment[1] + 100.0, moment[2]) / 100.0;
  report("rigid column: |sum RF + F| / |F|", force_error);
  report("rigid column: |sum r x RF + M| / |M|", moment_error);
  EXPECT_LE(force_error, 1e-10);
  EXPECT_LE(moment_error, 1e-10);
  // The top face follows u_R + UR × r.
  const std::array<double, 3> uR{nodal(f, "U", ref, 0), nodal(f, "U", ref, 1), nodal(f, "U", ref, 2)};
  const std::array<double, 3> th{nodal(f, "UR", ref, 0), nodal(f, "UR", ref, 1), nodal(f, "UR", ref, 2)};
  EXPECT_GT(std::abs(th[1]), 1e-3);  // the moment turns the face about y
  double worst = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    const auto x = coords(m, n);
    const auto rot = cross(th, {x[0] - x_ref[0], x[1] - x_ref[1], x[2] - x_ref[2]});
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(nodal(f, "U", n, c) - uR[c] - rot[c]));
  }
  EXPECT_LE(worst, 1e-12 * std::abs(uR[0]));
}

/// Every node but the reference and rotation nodes at R(π/2 about z) X: |U − (R − I) X|.
double worst_off_rotation(const Run& r) {
  const auto& m = r.model();
  const auto& f = r.capture.last();
  const std::int32_t ref = only_node(m, "REF");
  double worst = 0.0;
  for (const model::RigidBody& b : m.rigid_bodies)
    for (std::int32_t n : b.nodes) {
      const auto x = coords(m, n);
      worst = std::max({worst, std::abs(nodal(f, "U", n, 0) - (-x[1] - x[0])), std::abs(nodal(f, "U", n, 1) - (x[0] - x[1]))});
    }
  EXPECT_NEAR(nodal(f, "UR", ref, r.dim() == 3 ? 2 : 0), M_PI / 2, 1e-15);
  return worst;
}

TEST(RigidBody, WholeBlockTurnsByAFiniteRotationWithoutForce) {
  for (const char* deck : {"rigid_spin_block_c3d8.inp", "rigid_spin_plate_cpe4.inp"}) {
    const auto r = run_deck(deck_path(deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const double worst = worst_off_rotation(*r);
    report(std::string(deck) + ": worst |U - (R - I) X|", worst);
    EXPECT_LE(worst, 1e-14) << deck;
    const std::int32_t ref = only_node(r->model(), "REF");
    for (int c = 0; c < r->dim(); ++c) EXPECT_LE(std::abs(nodal(r->capture.last(), "RF", ref, c)), 1e-12) << deck;
  }
}

// Measured: balance 2e-16 of the force; 7.4e-5 off CalculiX (its contact discretisation).
TEST(RigidBody, PunchReactionIsTheContactForceAndCalculiXs) {
  const auto r = run_deck(deck_path("rigid_punch_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  const auto* cpress = field(f, "CPRESS");
  const auto* cnarea = field(f, "CNAREA");
  ASSERT_TRUE(cpress && cnarea);
  double contact_force = 0.0;
  for (std::size_t i = 0; i < cpress->values.size(); ++i) contact_force += cpress->values[i] * cnarea->values[i];
  const double rf3 = nodal(f, "RF", only_node(r->model(), "REF"), 2);
  report("rigid punch: |RF3 + sum CPRESS*CNAREA| / RF3", std::abs(rf3 + contact_force) / std::abs(rf3));
  report("rigid punch: RF3 / RF3(CalculiX) - 1", rf3 / -1.017847e4 - 1.0);
  EXPECT_LE(std::abs(rf3 + contact_force), 1e-9 * std::abs(rf3));
  EXPECT_NEAR(rf3 / -1.017847e4, 1.0, 0.02);
}

/// RF at the reference node along the punch's axis (3D: 3, 2D: 2) and Σ CPRESS·CNAREA of a
/// punch deck's last frame.
std::pair<double, double> punch_forces(const Run& r) {
  const auto& f = r.capture.last();
  const auto* cpress = field(f, "CPRESS");
  const auto* cnarea = field(f, "CNAREA");
  EXPECT_TRUE(cpress && cnarea);
  double contact_force = 0.0;
  if (cpress && cnarea)
    for (std::size_t i = 0; i < cpress->values.size(); ++i) contact_force += cpress->values[i] * cnarea->values[i];
  return {nodal(f, "RF", only_node(r.model(), "REF"), r.dim() - 1), contact_force};
}

// The C3D8 elements of *RIGID BODY, ELSET=PUNCH are not integrated (a rigid motion strains
// nothing, so they would add nothing but time): S asked for everywhere comes for the block's
// 256 elements alone, 8 points each, and the reaction stays the contact force.
TEST(RigidBody, ElementsOfARigidBodyAreNotIntegrated) {
  const auto path = edited_deck("rigid_punch_c3d8.inp", "rigid-elset-s", [](const std::string& line) {
    if (line == "*NODE OUTPUT") return std::vector<std::string>{"*ELEMENT OUTPUT", "S", line};
    return std::vector<std::string>{line};
  });
  const auto r = run_deck(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& block = m.mesh.elsets.at("BLOCK").rows;
  const auto* s = field(r->capture.last(), "S");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->elements.size(), 8 * block.size());
  std::set<std::int64_t> block_labels;
  for (std::int32_t e : block) block_labels.insert(m.mesh.elements.labels[static_cast<std::size_t>(e)]);
  for (std::int64_t label : s->elements) EXPECT_TRUE(block_labels.count(label)) << label;
  const auto [rf, contact] = punch_forces(*r);
  EXPECT_LE(std::abs(rf + contact), 1e-9 * std::abs(rf));
}

// The punch as a sheet of R3D4 rigid elements (SNEG facing the block) is the C3D8 punch's bottom
// face: the same answer. Measured: RF3 equal to 2.2e-16, balance 1.8e-16.
TEST(RigidBody, R3d4PunchIsTheSolidPunchsBottomFace) {
  const auto sheet = run_deck(deck_path("rigid_punch_r3d4.inp"));
  const auto solid = run_deck(deck_path("rigid_punch_c3d8.inp"));
  ASSERT_TRUE(sheet->outcome.completed) << sheet->outcome.message;
  ASSERT_TRUE(solid->outcome.completed) << solid->outcome.message;
  const auto [rf3, contact_force] = punch_forces(*sheet);
  const double rf3_solid = punch_forces(*solid).first;
  report("R3D4 punch: |RF3 / RF3(C3D8 punch) - 1|", std::abs(rf3 / rf3_solid - 1.0));
  report("R3D4 punch: |RF3 + sum CPRESS*CNAREA| / RF3", std::abs(rf3 + contact_force) / std::abs(rf3));
  EXPECT_LT(rf3, -1e3);
  EXPECT_NEAR(rf3 / rf3_solid, 1.0, 1e-10);
  EXPECT_LE(std::abs(rf3 + contact_force), 1e-9 * std::abs(rf3));
}

// Node to surface (Abaqus/Standard's default discretisation) under the same punches, hard contact
// with each method. The punch's free ends sit on slave nodes, which the block's bulge pushes
// past them: within the EXTENSION ZONE they stay on the punch's plane extended (before it, the
// sign of a sideways distance was round-off, and every method stopped; the analytical punches'
// DIRECT runs chattered at that node until their profiles' free ends got the zone too).
// Measured: each run in one increment; balance ≤ 1e-12; augmented Lagrange within 4e-4 of
// direct; direct 3D 4.9e-6 off CalculiX; SEGMENTS punches equal the element punches.
TEST(RigidBody, NodeToSurfacePunchesRunWithEveryMethod) {
  std::map<std::string, std::map<std::string, double>> direct_rf;  // deck → method → RF
  for (const std::string deck : {"rigid_punch_c3d8.inp", "rigid_punch_cpe4.inp", "rigid_punch_cax4.inp",
                                  "rigid_punch_segments_cpe4.inp", "rigid_punch_segments_cax4.inp",
                                  "rigid_punch_fillet_cpe4.inp"}) {
    std::map<std::string, double>& rf = direct_rf[deck];
    for (const std::string method : {"DIRECT", "AUGMENTED LAGRANGE", "PENALTY"}) {
      const auto path = edited_deck(deck, "nts-punch", [&](const std::string& line) {
        if (line.starts_with("*SURFACE BEHAVIOR")) return std::vector<std::string>{"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, " + method};
        if (line == "1e11") return std::vector<std::string>{};
        if (line.starts_with("*CONTACT PAIR")) return std::vector<std::string>{"*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE"};
        return std::vector<std::string>{line};
      });
      const auto r = run_deck(path.string());
      std::filesystem::remove(path);
      ASSERT_TRUE(r->outcome.completed) << deck << " " << method << ": " << r->outcome.message;
      const auto [force, contact_force] = punch_forces(*r);
      EXPECT_LT(force, -1e3) << deck << " " << method;
      EXPECT_LE(std::abs(force + contact_force), 1e-9 * std::abs(force)) << deck << " " << method;
      rf[method] = force;
      report(deck + " node to surface, " + method + ": RF / RF(direct) - 1", force / rf["DIRECT"] - 1.0);
    }
    EXPECT_NEAR(rf["AUGMENTED LAGRANGE"] / rf["DIRECT"], 1.0, 1e-3) << deck;
    if (deck == "rigid_punch_c3d8.inp") {
      report("rigid punch, node to surface, direct: RF3 / RF3(CalculiX) - 1", rf["DIRECT"] / -1.017847e4 - 1.0);
      EXPECT_NEAR(rf["DIRECT"] / -1.017847e4, 1.0, 0.02);
    }
  }
  // The analytical punches' ends keep the extension zone too: a SEGMENTS line is the element
  // punch's edge, with every method; a filleted edge carries less.
  for (const char* method : {"DIRECT", "AUGMENTED LAGRANGE", "PENALTY"}) {
    EXPECT_NEAR(direct_rf["rigid_punch_segments_cpe4.inp"][method] / direct_rf["rigid_punch_cpe4.inp"][method], 1.0, 1e-9);
    EXPECT_NEAR(direct_rf["rigid_punch_segments_cax4.inp"][method] / direct_rf["rigid_punch_cax4.inp"][method], 1.0, 1e-9);
    EXPECT_GT(direct_rf["rigid_punch_fillet_cpe4.inp"][method], direct_rf["rigid_punch_segments_cpe4.inp"][method]);
  }
}

// Surface to surface with DIRECT under the same punches. The block's top moves sideways at the
// punch's edge, so the next row of slave facets overlaps the punch by a sliver (5e-7 of a facet);
// its nodes touched within round-off and closed on weighted-gap rows all but dependent on their
// neighbours' (multipliers of 1e19), and the punch's interior nodes chattered (3D, axisymmetric:
// the analysis stopped). Such nodes now get no multiplier (contact_problem.cpp,
// kMinMultiplierOverlap). Measured: each run in one increment; 3D 6.5e-5 off CalculiX.
TEST(RigidBody, SurfaceToSurfaceDirectPunchesRun) {
  for (const std::string deck : {"rigid_punch_c3d8.inp", "rigid_punch_cpe4.inp", "rigid_punch_cax4.inp"}) {
    const auto path = edited_deck(deck, "s2s-direct-punch", [&](const std::string& line) {
      if (line.starts_with("*SURFACE BEHAVIOR")) return std::vector<std::string>{"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, DIRECT"};
      if (line == "1e11") return std::vector<std::string>{};
      return std::vector<std::string>{line};
    });
    const auto r = run_deck(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(r->outcome.completed) << deck << ": " << r->outcome.message;
    const auto [force, contact_force] = punch_forces(*r);
    EXPECT_LT(force, -1e3) << deck;
    EXPECT_LE(std::abs(force + contact_force), 1e-9 * std::abs(force)) << deck;
    if (deck == "rigid_punch_c3d8.inp") {
      report("rigid punch, surface to surface, direct: RF3 / RF3(CalculiX) - 1", force / -1.017847e4 - 1.0);
      EXPECT_NEAR(force / -1.017847e4, 1.0, 0.02);
    }
  }
}

/// The 2D punch of `deck` against the same punch of `reference`: RF2 equal to `tolerance`, and
/// RF2 = Σ CPRESS·CNAREA to 1e-9 (each deck: decks/verification/gen_rigid_bodies.py).
void expect_same_2d_punch(const std::string& deck, const std::string& reference, double tolerance) {
  const auto r = run_deck(deck_path(deck));
  const auto ref = run_deck(deck_path(reference));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  ASSERT_TRUE(ref->outcome.completed) << ref->outcome.message;
  const auto [rf2, contact_force] = punch_forces(*r);
  const double rf2_ref = punch_forces(*ref).first;
  report(deck + ": |RF2 / RF2(" + reference + ") - 1|", std::abs(rf2 / rf2_ref - 1.0));
  report(deck + ": |RF2 + sum CPRESS*CNAREA| / RF2", std::abs(rf2 + contact_force) / std::abs(rf2));
  EXPECT_LT(rf2, -1e3) << deck;
  EXPECT_NEAR(rf2 / rf2_ref, 1.0, tolerance) << deck;
  EXPECT_LE(std::abs(rf2 + contact_force), 1e-9 * std::abs(rf2)) << deck;
}

// The 2D counterparts: a punch of R2D2 (plane strain) or RAX2 (axisymmetric) line elements is
// the rigid quad punch's bottom edge. Measured: RF2 equal to 2.2e-16, balance 1.5e-16.
TEST(RigidBody, LineElementPunchesAreTheQuadPunchsBottomEdge) {
  expect_same_2d_punch("rigid_punch_r2d2.inp", "rigid_punch_cpe4.inp", 1e-10);
  expect_same_2d_punch("rigid_punch_rax2.inp", "rigid_punch_cax4.inp", 1e-10);
}

// The punch's bottom edge as an analytical surface (*SURFACE, TYPE=SEGMENTS, one LINE; no
// nodes, the rigid body only a reference node): the R2D2 / RAX2 punch's answer, in plane strain
// and axisymmetric, but for the slave face the punch's end crosses: the chords' surface to
// surface clips it there (mortar segments), the analytical pair counts its Gauss points on
// either side. Measured: RF2 4.3e-5 (plane strain) and 2.2e-5 (axisymmetric) off the line
// elements', the balance exact (0).
TEST(RigidBody, AnalyticalPunchIsTheLineElementPunch) {
  expect_same_2d_punch("rigid_punch_segments_cpe4.inp", "rigid_punch_r2d2.inp", 1e-4);
  expect_same_2d_punch("rigid_punch_segments_cax4.inp", "rigid_punch_rax2.inp", 1e-4);
}

// The same punch with its edge rounded, FILLET RADIUS = 0.25 between its side and its bottom:
// the block's base carries the punch's force (Σ RF₂ over the base = −RF₂ of the reference
// node), and the rounded edge carries less than the sharp one (the pressure peak at a sharp edge
// is where the block is loaded most). Measured: RF2 0.674 of the sharp punch's, the balance
// 6.2e-7: what Newton leaves (the fillet's contact is nonlinear in u; its residual criterion is
// 5e-3 of the average force, and it converged far below). Σ CFN₂ is 6.5e-4 off: CFN is
// CPRESS·CNAREA·n with the weighted normal made a unit vector, while the force is the
// gradient's, the normals' mean, shorter where they turn.
TEST(RigidBody, FilletedAnalyticalPunchBalancesAndCarriesLessThanTheSharpOne) {
  const auto rounded = run_deck(deck_path("rigid_punch_fillet_cpe4.inp"));
  const auto sharp = run_deck(deck_path("rigid_punch_segments_cpe4.inp"));
  ASSERT_TRUE(rounded->outcome.completed) << rounded->outcome.message;
  ASSERT_TRUE(sharp->outcome.completed) << sharp->outcome.message;
  const double rf2 = punch_forces(*rounded).first, rf2_sharp = punch_forces(*sharp).first;
  const auto& f = rounded->capture.last();
  double base = 0.0;
  for (std::int32_t row : nset(rounded->model(), "BASE")) base += nodal(f, "RF", row, 1);
  report("filleted punch: RF2 / RF2(sharp)", rf2 / rf2_sharp);
  report("filleted punch: |RF2 + sum RF2(base)| / RF2", std::abs(rf2 + base) / std::abs(rf2));
  EXPECT_LE(std::abs(rf2 + base), 1e-5 * std::abs(rf2));
  EXPECT_LT(rf2 / rf2_sharp, 1.0);
  EXPECT_GT(rf2 / rf2_sharp, 0.5);
}

// Friction against an analytical surface: the flat punch reaching past the block on both sides
// (x from −2 to 6), pressed, then slid by 0.05 with μ = 0.2: every node of the block's top slips,
// so RF1 = −μ RF2 exactly, and the analytical LINE gives the R2D2 sheet's answer (no free end
// over the block, so no face the end crosses). Measured: RF1/RF2 = −0.2 to the last bit, the
// analytical punch's RF1 and RF2 equal the R2D2 punch's to 2.9e-14.
TEST(RigidBody, AnalyticalPunchSlidesWithCoulombFrictionAsTheLineElementPunch) {
  const auto analytical = run_deck(deck_path("rigid_punch_slide_segments_cpe4.inp"));
  const auto elements = run_deck(deck_path("rigid_punch_slide_r2d2.inp"));
  ASSERT_TRUE(analytical->outcome.completed) << analytical->outcome.message;
  ASSERT_TRUE(elements->outcome.completed) << elements->outcome.message;
  const double mu = 0.2;
  std::array<double, 2> rf{}, rf_elements{};
  for (int c = 0; c < 2; ++c) {
    rf[c] = nodal(analytical->capture.last(), "RF", only_node(analytical->model(), "REF"), c);
    rf_elements[c] = nodal(elements->capture.last(), "RF", only_node(elements->model(), "REF"), c);
  }
  report("sliding analytical punch: RF1 / RF2 + mu", rf[0] / rf[1] + mu);
  report("sliding analytical punch: |RF1 / RF1(R2D2) - 1|", std::abs(rf[0] / rf_elements[0] - 1.0));
  report("sliding analytical punch: |RF2 / RF2(R2D2) - 1|", std::abs(rf[1] / rf_elements[1] - 1.0));
  EXPECT_LT(rf[1], -1e3);
  EXPECT_NEAR(rf[0] / rf[1], -mu, 1e-9);
  EXPECT_NEAR(rf_elements[0] / rf_elements[1], -mu, 1e-9);
  EXPECT_NEAR(rf[0] / rf_elements[0], 1.0, 1e-9);
  EXPECT_NEAR(rf[1] / rf_elements[1], 1.0, 1e-9);
}

// The narrow R2D2 punch (x 0..2 over the block's 0..4) pressed and slid by 0.02 with μ = 0.2: a
// slave node beyond the punch's free end whose faces overlap it by a sliver projects onto the
// end itself, seen sideways; its "slip" from there was the whole distance to the end, 0.48 per
// increment (CSLIP 3.4 after the step, friction μ p against the slide). Friction now acts only
// where the node faces the master (contact/surface_to_surface.cpp, project_node). Measured: the
// largest |CSLIP1| 0.0204, RF1/RF2 −0.125 (μ N over the nodes that face the punch; the sliver
// node's normal force, 0.25 of the total, carries none).
TEST(RigidBody, NoSlaveNodeSlipsFartherThanTheRigidPunchSlides) {
  const auto r = run_deck(deck_path("rigid_punch_slide_narrow_r2d2.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  const auto* slip = field(f, "CSLIP1");
  ASSERT_TRUE(slip);
  double worst = 0.0;
  for (double v : slip->values) worst = std::max(worst, std::abs(v));
  const double rf1 = nodal(f, "RF", only_node(r->model(), "REF"), 0), rf2 = nodal(f, "RF", only_node(r->model(), "REF"), 1);
  report("narrow sliding punch: largest |CSLIP1|", worst);
  report("narrow sliding punch: RF1 / RF2", rf1 / rf2);
  EXPECT_LE(worst, 0.02 * 1.05);
  EXPECT_LE(std::abs(rf1), 0.2 * std::abs(rf2) * (1.0 + 1e-9));
}

// General contact's ALL EXTERIOR does not take the two faces of rigid elements yet: the R3D4
// punch would pass through the block without a word (RF3 = 0, "completed"), so the deck is an
// error at the inclusion's line, naming the way out.
TEST(RigidBody, AllExteriorWithoutAPairOnRigidElementsIsRefused) {
  const auto path = edited_deck("rigid_punch_r3d4.inp", "r3d4-all-exterior", [](const std::string& line) {
    if (line.starts_with("*CONTACT PAIR"))
      return std::vector<std::string>{"*CONTACT", "*CONTACT INCLUSIONS, ALL EXTERIOR", "*CONTACT PROPERTY ASSIGNMENT",
                                      ", , FRICTIONLESS"};
    if (line == "BLOCK_TOP, PUNCH_BOTTOM") return std::vector<std::string>{};
    return std::vector<std::string>{line};
  });
  const std::string message = stop_message(path);
  EXPECT_NE(message.find(": error: *CONTACT INCLUSIONS: ALL EXTERIOR would leave out the 16 rigid elements (R3D3, "
                         "R3D4, R2D2, RAX2) that no *CONTACT PAIR or named inclusion reaches"),
            std::string::npos)
      << message;
}

// Named, the rigid punch's face is in general contact: the exterior against PUNCH_BOTTOM (an
// inclusion with one empty field) presses the block as the pair does (prescribed punch travel, so
// the penalty law of general contact and the pair's agree). Measured: RF3 within 2.4e-6.
TEST(RigidBody, TheExteriorAgainstANamedRigidSurfaceRuns) {
  const auto path = edited_deck("rigid_punch_r3d4.inp", "r3d4-named-inclusion", [](const std::string& line) {
    if (line.starts_with("*CONTACT PAIR"))
      return std::vector<std::string>{"*CONTACT", "*CONTACT INCLUSIONS", ", PUNCH_BOTTOM", "*CONTACT PROPERTY ASSIGNMENT",
                                      ", , FRICTIONLESS"};
    if (line == "BLOCK_TOP, PUNCH_BOTTOM") return std::vector<std::string>{};
    return std::vector<std::string>{line};
  });
  const auto general = run_deck(path.string());
  std::filesystem::remove(path);
  const auto pair = run_deck(deck_path("rigid_punch_r3d4.inp"));
  ASSERT_TRUE(general->outcome.completed) << general->outcome.message;
  ASSERT_TRUE(pair->outcome.completed) << pair->outcome.message;
  const double rf3 = punch_forces(*general).first, rf3_pair = punch_forces(*pair).first;
  report("R3D4 punch, exterior against its named face: |RF3 / RF3(pair) - 1|", std::abs(rf3 / rf3_pair - 1.0));
  EXPECT_NEAR(rf3 / rf3_pair, 1.0, 1e-4);
}

// Each body of rigid (or shell) elements needs its own pair or named inclusion: a second rigid
// sheet beside the paired punch, under ALL EXTERIOR, is refused and counted alone.
TEST(RigidBody, APairOnOneRigidBodyDoesNotCoverAnother) {
  const auto path = edited_deck("rigid_punch_r3d4.inp", "r3d4-second-sheet", [](const std::string& line) {
    if (line.starts_with("*SOLID SECTION"))
      return std::vector<std::string>{"*NODE", "9001, 10., 10., 5.", "9002, 11., 10., 5.", "9003, 11., 11., 5.",
                                      "9004, 10., 11., 5.", "9005, 10.5, 10.5, 5.", "*ELEMENT, TYPE=R3D4, ELSET=SHEET",
                                      "9001, 9001, 9002, 9003, 9004", "*RIGID BODY, REF NODE=9005, ELSET=SHEET", line};
    if (line == "BLOCK_TOP, PUNCH_BOTTOM")
      return std::vector<std::string>{line, "*CONTACT", "*CONTACT INCLUSIONS, ALL EXTERIOR"};
    return std::vector<std::string>{line};
  });
  const std::string message = stop_message(path);
  EXPECT_NE(message.find(": error: *CONTACT INCLUSIONS: ALL EXTERIOR would leave out the 1 rigid elements"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace inpact::verification
