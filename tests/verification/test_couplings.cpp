// *COUPLING with *KINEMATIC and *DISTRIBUTING (model/coupling.hpp,
// solver/distributing_coupling.hpp).
//
// References (decks/verification/gen_couplings.py):
//  - kinematic: the column of test_rigid_bodies.cpp with its top face coupled instead of made a
//    rigid body gives the same displacements (the rigid-face answer); coupling DOF 3 only pushes
//    the face down evenly and leaves it free to spread;
//  - distributing: over a held face the reactions are the distribution by hand (area weights,
//    centroid, J); on a free column the base carries the whole load and the reference node moves
//    with the face's weighted mean; a prescribed reference node sets that mean; a plane-strain
//    plate carries a force and a moment (DOF 6) to its built-in edge;
//  - both columns against CalculiX 2.20 on the same decks in its dialect (gen_couplings.py
//    --ccx): its *NODE PRINT of the top face, held below.
#include "verification_fixture.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <span>

namespace inpact::verification {
namespace {

using V3 = std::array<double, 3>;

V3 cross(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V3 minus(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 vec(const solver::Frame& f, const std::string& key, std::int32_t n, int dim = 3) {
  V3 v{0, 0, 0};
  for (int c = 0; c < dim; ++c) v[c] = nodal(f, key, n, c);
  return v;
}

std::int32_t ref_node(const model::Model& m) { return nset(m, "REF").front(); }

/// The area weight of a node of the columns' 1 × 1 top face, meshed 2 × 2: ¼ at an edge of the
/// square and ½ inside it, in each direction.
double face_weight(const V3& x) {
  auto w = [](double s) { return std::abs(s - 0.5) < 1e-9 ? 0.5 : 0.25; };
  return w(x[0]) * w(x[1]);
}

/// Σ RF and Σ (x − x_ref) × RF over a node set.
std::pair<V3, V3> resultant(const model::Model& m, const solver::Frame& f, const std::string& set, const V3& x_ref,
                            int dim = 3) {
  V3 force{0, 0, 0}, moment{0, 0, 0};
  for (std::int32_t n : nset(m, set)) {
    const V3 rf = vec(f, "RF", n, dim);
    const V3 mo = cross(minus(coords(m, n), x_ref), rf);
    for (int c = 0; c < 3; ++c) force[c] += rf[c], moment[c] += mo[c];
  }
  return {force, moment};
}

double norm(const V3& a) { return std::hypot(a[0], a[1], a[2]); }

// Measured: the same displacements and rotations as the rigid body, bit for bit.
TEST(Coupling, KinematicFaceMovesAsTheRigidBodyTieDoes) {
  const auto coupled = run_deck(deck_path("coupling_kinematic_column_c3d8.inp"));
  const auto rigid = run_deck(deck_path("rigid_moment_block_c3d8.inp"));
  ASSERT_TRUE(coupled->outcome.completed) << coupled->outcome.message;
  ASSERT_TRUE(rigid->outcome.completed) << rigid->outcome.message;
  const auto& m = coupled->model();
  const auto& a = coupled->capture.last();
  const auto& b = rigid->capture.last();
  double worst = 0.0, largest = 0.0;
  for (std::int32_t n : nset(m, "ALL"))
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(nodal(a, "U", n, c) - nodal(b, "U", n, c)));
      largest = std::max(largest, std::abs(nodal(b, "U", n, c)));
    }
  const std::int32_t ref = ref_node(m);
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(nodal(a, "UR", ref, c) - nodal(b, "UR", ref, c)) * 4.5);
  report("kinematic coupling vs rigid body: max |dU| / max |U|", worst / largest);
  EXPECT_LE(worst, 1e-10 * largest);
}

TEST(Coupling, KinematicDof3PushesTheFaceEvenlyAndLeavesItFreeToSpread) {
  const auto r = run_deck(deck_path("coupling_kinematic_push_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double spread = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    EXPECT_NEAR(nodal(f, "U", n, 2), -0.001, 1e-15);
    spread = std::max(spread, std::abs(nodal(f, "U", n, 0)));
  }
  EXPECT_GT(spread, 1e-5);  // the Poisson spread, about ν · 0.001 / 4 · ½ at the corners
  const std::int32_t ref = ref_node(m);
  const auto [force, moment] = resultant(m, f, "BASE", coords(m, ref));
  report("kinematic push: |sum RF3_base + RF3_ref| / |RF3_ref|", std::abs(force[2] + nodal(f, "RF", ref, 2)) / std::abs(force[2]));
  EXPECT_NEAR(force[2] + nodal(f, "RF", ref, 2), 0.0, 1e-10 * std::abs(force[2]));
  EXPECT_GT(std::abs(force[2]), 1.0);
}

// Only the tangential DOF of a cylindrical orientation about the column's axis is coupled:
// twisted by UR3 = 0.01, the face turns rigidly, u = UR × r (CalculiX 2.20 on the same deck in
// its dialect gives the same, to its seven digits). Measured: 3.5e-18 at worst.
TEST(Coupling, KinematicTangentialDofOfACylindricalOrientationTwistsTheFace) {
  const auto r = run_deck(deck_path("coupling_kinematic_twist_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double worst = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    const V3 x = coords(m, n);
    const V3 expected = cross({0, 0, 0.01}, {x[0] - 0.5, x[1] - 0.5, 0.0});
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(nodal(f, "U", n, c) - expected[c]));
  }
  report("kinematic twist: max |U - UR x r| over the top face", worst);
  EXPECT_LE(worst, 1e-12 * 0.01);
}

// CalculiX's hinge.inp in our mesh: a free bar swung by 1.57 rad in one NLGEOM step. The exact
// answer is the rigid rotation u = (R − I)(X − X_R) at every node. The whole step at once folds
// the coupled face's elements (det F < 0, where St. Venant–Kirchhoff feels no strain): the
// attempt is cut back, and the quarter steps start from the tangent's prediction of the swing.
// Before both, the run converged silently to a fold, 5 % off (U2 = −9.499 at the tip).
// Measured: 2.5e-3 at worst, tip (8.991983, −9.999843) against CalculiX's (8.992435, −9.999599).
TEST(Coupling, KinematicHingeSwingsAFreeBarRigidlyThroughAQuarterTurn) {
  const auto r = run_deck(deck_path("coupling_kinematic_hinge_c3d20r.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const double c = std::cos(1.57), s = std::sin(1.57);
  std::vector<bool> used(m.mesh.nodes.size(), false);
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    for (std::int32_t n : m.mesh.elements.nodes_of(e)) used[static_cast<std::size_t>(n)] = true;
  double worst = 0.0;
  for (std::size_t n = 0; n < used.size(); ++n) {
    if (!used[n]) continue;
    const V3 r0 = minus(coords(m, static_cast<std::int32_t>(n)), {10, 0, 0});
    const V3 expected = {c * r0[0] - s * r0[1] - r0[0], s * r0[0] + c * r0[1] - r0[1], 0};
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(nodal(f, "U", n, k) - expected[k]));
  }
  report("kinematic hinge: max |U - (R - I) r| over the bar", worst);
  EXPECT_LE(worst, 1e-3 * 13.5);  // 13.5: the largest displacement
  const V3 tip = vec(f, "U", nset(m, "TIP").front());
  EXPECT_NEAR(tip[0], 8.992435, 1e-3 * 10);
  EXPECT_NEAR(tip[1], -9.999599, 1e-3 * 10);
  const bool cut_back = std::any_of(r->capture.messages.begin(), r->capture.messages.end(), [](const std::string& t) {
    return t.find("turned inside out at an integration point") != std::string::npos;
  });
  EXPECT_TRUE(cut_back);
}

// A *CLOAD on a reference DOF the coupling does not couple (DOF 1 of the push deck, which
// couples DOF 3 only) would act on nothing: the run stops naming the load's line.
TEST(Coupling, ALoadOnAnUncoupledReferenceDofIsADeckError) {
  int line_no = 0, cload_line = 0;
  const auto path = edited_deck("coupling_kinematic_push_c3d8.inp", "coupling-cload", [&](const std::string& line) {
    ++line_no;
    if (line != "REF, 3, 3, -0.001") return std::vector<std::string>{line};
    cload_line = line_no + 2;
    return std::vector<std::string>{line, "*CLOAD", "REF, 1, 5."};
  });
  const std::string message = stop_message(path);
  EXPECT_NE(message.find(":" + std::to_string(cload_line) +
                         ":1: error: *CLOAD: node 82 DOF 1 carries a load but nothing connects that degree of freedom"),
            std::string::npos)
      << message;
}

// The reactions of a held face are the coupling's distribution of F1 = 10, M3 = 5 (the deck's
// header works it out). Measured: 4.4e-16 at worst (reactions of order 2).
TEST(Coupling, DistributingSpreadsTheLoadByAreaWeightsAboutTheCentroid) {
  const auto r = run_deck(deck_path("coupling_distributing_held_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double worst = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    const V3 x = coords(m, n);
    const double w = face_weight(x), rx = x[0] - 0.5, ry = x[1] - 0.5;
    const V3 expected{w * (10 - 20 * ry), w * 20 * rx, -w * 40 * rx};
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(nodal(f, "RF", n, c) + expected[c]));
  }
  report("distributing coupling: max |RF + f_by_hand| over the held face", worst);
  EXPECT_LE(worst, 1e-12);
}

// CalculiX's node-based *DISTRIBUTING COUPLING (the reference node on a DCOUP3D element, weights
// written per node): the held face's nodes carry w_i/16 of F = (10, 5, 0) and no moment, though
// the reference node is 0.5 off the face (CalculiX's meaning; a *COUPLING's would add one).
// CalculiX's own distcoup and distcoupspring agree to 1.3e-7 (RF) and 3.6e-8 (U).
// Measured: 0 at worst.
TEST(Coupling, NodeBasedDistributingCouplingSpreadsTheForceByTheWeightsGiven) {
  const auto r = run_deck(deck_path("distributing_coupling_held_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double worst = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    const double w = face_weight(coords(m, n));  // the deck's weights over their sum 16
    const V3 expected{10 * w, 5 * w, 0};
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(nodal(f, "RF", n, c) + expected[c]));
  }
  report("*DISTRIBUTING COUPLING: max |RF + w F| over the held face", worst);
  EXPECT_LE(worst, 1e-12);
}

// WEIGHTING METHOD=LINEAR: w = area (1 − r/r0), r0 the farthest coupling node's distance from the
// reference node, so the face's four corners carry nothing; the resultant is still F and the
// moment M (about the reference node), whatever the weights. Measured: corners 0, sums 6.6e-15.
TEST(Coupling, LinearWeightingLeavesTheFarthestNodesUnloadedAndTheResultantExact) {
  const auto path = edited_deck("coupling_distributing_held_c3d8.inp", "coupling-linear", [](const std::string& line) {
    return std::vector<std::string>{line == "*DISTRIBUTING" ? "*DISTRIBUTING, WEIGHTING METHOD=LINEAR" : line};
  });
  const auto r = run_deck(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double corner = 0.0;
  for (std::int32_t n : nset(m, "TOP")) {
    const V3 x = coords(m, n);
    if (std::abs(x[0] - 0.5) > 0.25 && std::abs(x[1] - 0.5) > 0.25)
      for (int c = 0; c < 3; ++c) corner = std::max(corner, std::abs(nodal(f, "RF", n, c)));
  }
  const auto [force, moment] = resultant(m, f, "TOP", coords(m, ref_node(m)));
  const double sum_error = std::max(norm({force[0] + 10, force[1], force[2]}), norm({moment[0], moment[1], moment[2] + 5}));
  report("linear weighting: max |RF| at the corners", corner);
  report("linear weighting: |sum RF + F|, |sum r x RF + M|", sum_error);
  EXPECT_LE(corner, 1e-13);
  EXPECT_LE(sum_error, 1e-12);
  EXPECT_GT(std::abs(nodal(f, "RF", nset(m, "TOP")[1], 0)), 0.1);  // an edge node carries load
}

/// θ = J⁻¹ Σ ŵ r × u and ū = Σ ŵ u over the columns' top face (J is diagonal for the square).
std::pair<V3, V3> face_mean_motion(const model::Model& m, const solver::Frame& f) {
  V3 mean{0, 0, 0}, h{0, 0, 0}, J{0, 0, 0};
  for (std::int32_t n : nset(m, "TOP")) {
    const V3 x = coords(m, n);
    const double w = face_weight(x);
    const V3 r{x[0] - 0.5, x[1] - 0.5, 0.0}, u = vec(f, "U", n);
    const V3 ru = cross(r, u);
    for (int c = 0; c < 3; ++c) mean[c] += w * u[c], h[c] += w * ru[c];
    J[0] += w * r[1] * r[1], J[1] += w * r[0] * r[0], J[2] += w * (r[0] * r[0] + r[1] * r[1]);
  }
  return {mean, {h[0] / J[0], h[1] / J[1], h[2] / J[2]}};
}

// Measured: Σ RF 2.8e-13 of |F|, Σ r × RF 4.2e-14 of |M| (the column's round-off); UR at the
// face's least-squares rotation to 2.7e-16.
TEST(Coupling, DistributingColumnCarriesTheLoadAndTheReferenceNodeFollowsTheFaceMean) {
  const auto r = run_deck(deck_path("coupling_distributing_column_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const std::int32_t ref = ref_node(m);
  const auto [force, moment] = resultant(m, f, "BASE", coords(m, ref));
  const double force_error = norm({force[0] + 10, force[1], force[2]}) / 10;
  const double moment_error = norm({moment[0], moment[1] + 100, moment[2] + 20}) / std::hypot(100.0, 20.0);
  report("distributing column: |sum RF + F| / |F|", force_error);
  report("distributing column: |sum r x RF + M| / |M|", moment_error);
  EXPECT_LE(force_error, 1e-10);
  EXPECT_LE(moment_error, 1e-10);
  const auto [mean, theta] = face_mean_motion(m, f);
  const V3 ur = vec(f, "UR", ref), u_ref = vec(f, "U", ref);
  const V3 turn = cross(ur, {0, 0, 0.5});  // θ × d, d = x_R − centroid
  report("distributing column: |UR - J^-1 sum w r x u| / |UR|", norm(minus(ur, theta)) / norm(theta));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(ur[c], theta[c], 1e-12 * norm(theta));
    EXPECT_NEAR(u_ref[c], mean[c] + turn[c], 1e-12 * norm(u_ref));
  }
  EXPECT_GT(std::abs(ur[2]), 1e-6);  // M3 twists the face
}

// An *EQUATION may eliminate a distributing coupling's reference DOF (CalculiX's pret3 ties a
// beam's end to its reference node so): u_82 = u_999, the load on node 999. The coupling is then
// solved for coupling-node DOFs, and the column answers as with the load on the reference node
// itself: every U to 1e-12 of the largest, node 999 moving as the reference node did.
TEST(Coupling, AnEquationOnTheReferenceNodeLeavesTheCouplingOnItsFace) {
  const auto path = edited_deck("coupling_distributing_column_c3d8.inp", "coupling-equation", [](const std::string& line) {
    if (line == "*STEP")
      return std::vector<std::string>{"*NODE", "999, 0.5, 0.5, 4.5", "*EQUATION", "2", "82, 1, 1., 999, 1, -1.", "2",
                                      "82, 2, 1., 999, 2, -1.", "2", "82, 3, 1., 999, 3, -1.", line};
    return std::vector<std::string>{line == "REF, 1, 10." ? "999, 1, 10." : line};
  });
  const auto tied = run_deck(path.string());
  std::filesystem::remove(path);
  const auto direct = run_deck(deck_path("coupling_distributing_column_c3d8.inp"));
  ASSERT_TRUE(tied->outcome.completed) << tied->outcome.message;
  ASSERT_TRUE(direct->outcome.completed) << direct->outcome.message;
  const solver::Frame &a = tied->capture.last(), &b = direct->capture.last();
  const auto& tied_labels = tied->model().mesh.nodes.labels;
  const auto row_of = [&](std::int64_t label) {  // the tied deck's row of a node label
    return static_cast<std::size_t>(std::find(tied_labels.begin(), tied_labels.end(), label) - tied_labels.begin());
  };
  const std::vector<std::int32_t> column = nset(direct->model(), "ALL");
  double largest = 0.0;
  for (std::int32_t n : column)
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(nodal(b, "U", static_cast<std::size_t>(n), c)));
  for (std::int32_t n : column) {
    const std::size_t row = row_of(direct->model().mesh.nodes.labels[static_cast<std::size_t>(n)]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(nodal(a, "U", row, c), nodal(b, "U", static_cast<std::size_t>(n), c), 1e-12 * largest) << n;
  }
  const std::size_t ref = static_cast<std::size_t>(ref_node(direct->model()));
  ASSERT_LT(row_of(999), tied_labels.size());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(nodal(a, "U", row_of(999), c), nodal(b, "U", ref, c), 1e-12 * largest);
}

// The equation may name a node of the coupled face, or another DOF of the reference node itself:
// u1 of the reference node = u1 of top node 77, or = its own u3. Both rules hold at the end: the
// reference node moves with the face's weighted mean (u_R = mean + UR × d) and its u1 is what the
// equation says, to 1e-12 of the motion. Tied to node 77 the equation's force stays inside the
// column, so the base carries the load F1 = 10 (1e-10); tied to its own u3 it pushes the node
// along x and z against each other, a support of its own.
TEST(Coupling, AnEquationToAFaceNodeOrTheReferenceNodeAndTheCouplingBothHold) {
  struct Case {
    const char* equation;
    std::int64_t other_node;
    int other_component;
  };
  for (const Case& k : {Case{"82, 1, 1., 77, 1, -1.", 77, 0}, Case{"82, 1, 1., 82, 3, -1.", 82, 2}}) {
    SCOPED_TRACE(k.equation);
    const auto path = edited_deck("coupling_distributing_column_c3d8.inp", "coupling-face-equation",
                                  [&](const std::string& line) {
                                    if (line != "*STEP") return std::vector<std::string>{line};
                                    return std::vector<std::string>{"*EQUATION", "2", k.equation, line};
                                  });
    const auto r = run_deck(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const auto& m = r->model();
    const auto& f = r->capture.last();
    const std::int32_t ref = ref_node(m);
    const auto [mean, theta] = face_mean_motion(m, f);
    const V3 u_ref = vec(f, "U", ref), ur = vec(f, "UR", ref);
    const V3 turn = cross(ur, {0, 0, 0.5});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(u_ref[c], mean[c] + turn[c], 1e-12 * norm(u_ref)) << c;
    const auto& labels = m.mesh.nodes.labels;
    const auto other = static_cast<std::int32_t>(std::find(labels.begin(), labels.end(), k.other_node) - labels.begin());
    EXPECT_NEAR(u_ref[0], vec(f, "U", other)[static_cast<std::size_t>(k.other_component)], 1e-12 * norm(u_ref));
    EXPECT_GT(std::abs(u_ref[0]), 1e-6);
    if (k.other_node == 82) continue;
    const auto [force, moment] = resultant(m, f, "BASE", coords(m, ref));
    EXPECT_NEAR(force[0], -10.0, 1e-10 * 10);
    EXPECT_NEAR(force[1], 0.0, 1e-10 * 10);
    EXPECT_NEAR(force[2], 0.0, 1e-10 * 10);
  }
}

// Measured: the face's mean u3 exact and its rotation about x to 2.2e-16; the reference node's
// RF balances the base's to 4.4e-15.
TEST(Coupling, DistributingPrescribedReferenceNodeSetsTheFaceMeanMotion) {
  const auto r = run_deck(deck_path("coupling_distributing_pull_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const auto [mean, theta] = face_mean_motion(m, f);
  report("distributing pull: |mean u3 - 0.001| / 0.001", std::abs(mean[2] - 0.001) / 0.001);
  report("distributing pull: |theta1 - 0.0005| / 0.0005", std::abs(theta[0] - 0.0005) / 0.0005);
  EXPECT_NEAR(mean[2], 0.001, 1e-15);
  EXPECT_NEAR(theta[0], 0.0005, 1e-15);
  const std::int32_t ref = ref_node(m);
  const V3 x_ref = coords(m, ref);
  const auto [force, moment] = resultant(m, f, "BASE", x_ref);
  const V3 rf = vec(f, "RF", ref), rm = vec(f, "RM", ref);
  EXPECT_GT(std::abs(rf[2]), 1.0);
  EXPECT_GT(std::abs(rm[0]), 1.0);
  report("distributing pull: |sum RF_base + RF_ref| / |RF_ref|", norm({force[0] + rf[0], force[1] + rf[1], force[2] + rf[2]}) / norm(rf));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(force[c] + rf[c], 0.0, 1e-10 * norm(rf));
    EXPECT_NEAR(moment[c] + rm[c], 0.0, 1e-10 * (norm(rm) + 4.5 * norm(rf)));
  }
}

// Under NLGEOM the DOF map is laid out again every iteration (a rigid body turns finitely): a
// distributing coupling's prescribed reference node must eliminate the same coupling-node DOFs
// each time. The pull deck with translations only, NLGEOM, and a held one-node rigid body far
// away (which makes the map re-linearise): the face's mean u3 is still the prescribed 0.001.
TEST(Coupling, PrescribedReferenceNodeKeepsItsPivotsWhenTheMapIsLaidOutAgain) {
  const auto path = edited_deck("coupling_distributing_pull_c3d8.inp", "coupling-nlgeom", [](const std::string& line) {
    std::vector<std::string> out;
    if (line == "REF, 4, 4, 0.0005") return out;
    out.push_back(line == "*STEP" ? "*STEP, NLGEOM" : line);
    if (line == "*NODE, NSET=ALL") out.insert(out.end(), {"900, 5., 5., 5.", "901, 6., 5., 5."});
    if (line.rfind("*DISTRIBUTING", 0) == 0) out.push_back("1, 3");
    if (line.rfind("*SOLID SECTION", 0) == 0)
      out.insert(out.end(), {"*NSET, NSET=LONE", "901", "*RIGID BODY, REF NODE=900, TIE NSET=LONE", "*BOUNDARY", "900, 1, 6"});
    return out;
  });
  const auto r = run_deck(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto [mean, theta] = face_mean_motion(r->model(), r->capture.last());
  EXPECT_NEAR(mean[2], 0.001, 1e-15);
}

// Measured: Σ RF 5.8e-13 of |F|, Σ r × RF 3.3e-13 of |M|.
TEST(Coupling, DistributingPlaneStrainPlateCarriesAForceAndAMomentToItsRoot) {
  const auto r = run_deck(deck_path("coupling_distributing_plate_cpe4.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const std::int32_t ref = ref_node(m);
  const auto [force, moment] = resultant(m, f, "ROOT", coords(m, ref), 2);
  report("distributing plate: |sum RF + F| / |F|", std::hypot(force[0], force[1] + 3.0) / 3.0);
  report("distributing plate: |sum r x RF + M| / |M|", std::abs(moment[2] + 7.0) / 7.0);
  EXPECT_NEAR(force[0], 0.0, 1e-10 * 3.0);
  EXPECT_NEAR(force[1], -3.0, 1e-10 * 3.0);
  EXPECT_NEAR(moment[2], -7.0, 1e-10 * 7.0);
  EXPECT_GT(std::abs(nodal(f, "UR", ref, 0)), 1e-8);
}

/// CalculiX 2.20's displacements of the columns' top face (nodes 73–81), *NODE PRINT.
struct CcxRow {
  std::int64_t node;
  V3 u;
};
const CcxRow kCcxDistributing[] = {
    {73, {5.524624E-02, -2.551535E-03, 1.242853E-02}}, {74, {5.504804E-02, 5.828196E-16, 9.019330E-17}},
    {75, {5.524624E-02, 2.551535E-03, -1.242853E-02}}, {76, {5.248658E-02, -2.971429E-03, 1.243227E-02}},
    {77, {5.228855E-02, 5.771388E-16, 5.461629E-18}},  {78, {5.248658E-02, 2.971429E-03, -1.243227E-02}},
    {79, {4.930339E-02, -3.391323E-03, 1.242853E-02}}, {80, {4.910518E-02, 5.793976E-16, -7.448469E-17}},
    {81, {4.930339E-02, 3.391323E-03, -1.242853E-02}}};
const CcxRow kCcxKinematic[] = {
    {73, {5.223335E-02, 1.024369E-15, 1.231290E-02}}, {75, {5.223335E-02, 7.010603E-16, -1.231290E-02}},
    {77, {5.223335E-02, 8.627148E-16, 1.236908E-17}}, {81, {5.223335E-02, 7.010603E-16, -1.231290E-02}}};

/// max |U − U_ccx| / max |U_ccx| over the rows.
double off_calculix(const Run& r, std::span<const CcxRow> rows) {
  const auto& m = r.model();
  const auto& f = r.capture.last();
  double worst = 0.0, largest = 0.0;
  for (const CcxRow& row : rows) {
    const auto node = m.mesh.nodes.index.find(0, row.node);
    if (!node) {
      ADD_FAILURE() << "no node " << row.node;
      return 1.0;
    }
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(nodal(f, "U", static_cast<std::size_t>(*node), c) - row.u[c]));
      largest = std::max(largest, std::abs(row.u[c]));
    }
  }
  return worst / largest;
}

// Measured: 8.4e-8 (distributing) and 6.3e-8 (kinematic) of the largest, CalculiX's seven
// printed digits.
TEST(Coupling, BothColumnsMatchCalculiX) {
  const auto distributing = run_deck(deck_path("coupling_distributing_column_c3d8.inp"));
  const auto kinematic = run_deck(deck_path("coupling_kinematic_column_c3d8.inp"));
  ASSERT_TRUE(distributing->outcome.completed && kinematic->outcome.completed);
  const double d = off_calculix(*distributing, kCcxDistributing), k = off_calculix(*kinematic, kCcxKinematic);
  report("distributing column vs CalculiX: max |dU| / max |U|", d);
  report("kinematic column vs CalculiX: max |dU| / max |U|", k);
  EXPECT_LE(d, 1e-6);
  EXPECT_LE(k, 1e-6);
}

}  // namespace
}  // namespace inpact::verification
