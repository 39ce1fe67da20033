// Shell edges: edge-based surfaces (Abaqus's E1.., CalculiX's S3..), the edge tractions EDNOR,
// EDSHR, EDT, and a pre-tension section across a shell (decks/verification/gen_shell_edges.py).
//  - A strip pulled by EDNOR = −q on its free edge: S22 = q/t at every section point, U2 = qL/(Et),
//    U1 = −ν q b/(E t) at x = b (exact in the element space); CalculiX's EDNOR gives the same.
//  - A built-in plate under EDT on its free edge: the reactions sum to q b along +z (EDT acts
//    against the shell normal +z) and the edge deflects between the wide plate's and the narrow
//    beam's closed forms; under EDSHR (along E3 in its node order, −x) they sum to q b along +x.
//  - A plate whose edge is the slave of a *TIE to a far stiffer block's face, pulled by EDNOR: the
//    plate carries q/t as on a rigid support (to the block's compliance, 1e-4) and the block's
//    reactions balance the load exactly.
//  - A strip cut across by a pre-tension section on shell edges: the uniform membrane stress and
//    tightening of a bar (the solid pretension test's closed forms, with A = b t).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kT = 0.1, kWidth = 1.0, kLength = 2.0;

std::int32_t node_row(const model::Model& m, std::int64_t label) { return *m.mesh.nodes.index.find(0, label); }

/// Σ RF over the held nodes (sum_rf would add the rotation nodes' moments).
std::array<double, 3> bottom_reactions(const Run& r, const solver::Frame& f) {
  std::array<double, 3> s{0, 0, 0};
  for (std::int32_t n : nset(r.model(), "BOTTOM"))
    for (int c = 0; c < 3; ++c) s[c] += nodal(f, "RF", static_cast<std::size_t>(n), c);
  return s;
}

/// Largest |S − expected| over every section point of the shells of a frame (S11, S22, S12).
double worst_membrane_stress(const Run& r, const solver::Frame& f, const std::array<double, 3>& expected) {
  const auto& elements = r.model().mesh.elements;
  double worst = 0;
  for (const auto& p : point_values(r, f)) {
    const auto row = elements.index.find(0, p.element);
    if (!row || !model::is_shell(model::element_type(elements.type[static_cast<std::size_t>(*row)]))) continue;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p.s[c] - expected[c]));
  }
  return worst;
}

class EdnorStrip : public ::testing::TestWithParam<const char*> {};

TEST_P(EdnorStrip, PullsTheStripWithUniformMembraneStress) {
  const auto r = run_deck(deck_path(GetParam()));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const solver::Frame& f = r->capture.last();
  const double q = 50.0;
  const double worst = worst_membrane_stress(*r, f, {0, q / kT, 0});
  report(std::string(GetParam()) + ": worst |S - (0, q/t, 0)|", worst);
  EXPECT_LE(worst, 1e-10 * q / kT);
  for (std::int32_t n : nset(m, "TOP")) {
    const double x = m.mesh.nodes.coords[static_cast<std::size_t>(n)][0];
    EXPECT_NEAR(nodal(f, "U", static_cast<std::size_t>(n), 1), q * kLength / (kE * kT), 1e-12);
    EXPECT_NEAR(nodal(f, "U", static_cast<std::size_t>(n), 0), -kNu * q * x / (kE * kT), 1e-12);
  }
  const auto rf = bottom_reactions(*r, f);
  EXPECT_NEAR(rf[1], -q * kWidth, 1e-10 * q);
}

INSTANTIATE_TEST_SUITE_P(ShellEdges, EdnorStrip,
                         ::testing::Values("edge_load_ednor_s4.inp", "edge_load_ednor_s8r.inp"));

TEST(ShellEdges, CalculixAgreesOnEdnor) {
  if (std::system("command -v ccx > /dev/null 2>&1") != 0) GTEST_SKIP() << "ccx is not installed";
  const auto dir = generated_dir() / "ccx_edge_load_ednor";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(deck_path("edge_load_ednor_s4.inp"), dir / "strip.inp",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string cmd = "cd '" + dir.string() + "' && ccx strip > ccx.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const auto ccx = ccx_displacements((dir / "strip.dat").string(), "TOP");
  ASSERT_EQ(ccx.size(), 3u);
  const auto r = run_deck(deck_path("edge_load_ednor_s4.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  double worst = 0;
  for (const auto& [label, u] : ccx)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(nodal(r->capture.last(), "U", static_cast<std::size_t>(node_row(r->model(), label)), c) - u[c]));
  report("EDNOR strip vs CalculiX: max |du|", worst);
  EXPECT_LE(worst, 1e-6 * 50.0 * kLength / (kE * kT));  // ccx prints 7 digits
}

TEST(ShellEdges, TransverseAndShearEdgeTractionsLoadTheirDirections) {
  const auto r = run_deck(deck_path("edge_load_edt_edshr_s4.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double q = 0.05, P = q * kWidth;
  const auto& m = r->model();
  const solver::Frame& bent = *r->capture.of_step(1).back();
  const auto rf1 = bottom_reactions(*r, bent);
  EXPECT_NEAR(rf1[0], 0, 1e-10 * P);
  EXPECT_NEAR(rf1[1], 0, 1e-10 * P);
  EXPECT_NEAR(rf1[2], P, 1e-10 * P);
  // Anticlastic bending sits between the narrow beam (E, plus shear) and the wide plate (E/(1 − ν²)).
  const double inertia = kWidth * kT * kT * kT / 12, shear = kE / (2 * (1 + kNu)) * 5.0 / 6.0 * kWidth * kT;
  const double narrow = P * std::pow(kLength, 3) / (3 * kE * inertia) + P * kLength / shear;
  const double wide = (1 - kNu * kNu) * P * std::pow(kLength, 3) / (3 * kE * inertia);
  for (std::int32_t n : nset(m, "TOP")) {
    const double w = -nodal(bent, "U", static_cast<std::size_t>(n), 2);
    EXPECT_GT(w, wide);
    EXPECT_LT(w, narrow);
  }
  const solver::Frame& sheared = *r->capture.of_step(2).back();
  const auto rf2 = bottom_reactions(*r, sheared);
  EXPECT_NEAR(rf2[0], P, 1e-10 * P);
  EXPECT_NEAR(rf2[1], 0, 1e-10 * P);
  EXPECT_NEAR(rf2[2], 0, 1e-10 * P);
  for (std::int32_t n : nset(m, "TOP")) EXPECT_LT(nodal(sheared, "U", static_cast<std::size_t>(n), 0), 0);
}

TEST(ShellEdges, TiedShellEdgePassesTheMembraneForceToTheBlock) {
  const auto r = run_deck(deck_path("tie_shell_edge_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  const double q = 50.0;
  const double worst = worst_membrane_stress(*r, f, {q / kT, 0, 0});
  report("shell edge tied to a block: worst |S - (q/t, 0, 0)| / (q/t)", worst / (q / kT));
  EXPECT_LE(worst, 1e-4 * q / kT);  // the block's compliance (1000 times stiffer): measured 4.1e-5
  std::array<double, 3> held{0, 0, 0};
  for (std::int32_t n : nset(r->model(), "HELD"))
    for (int c = 0; c < 3; ++c) held[c] += nodal(f, "RF", static_cast<std::size_t>(n), c);
  EXPECT_NEAR(held[0], -q * kWidth, 1e-10 * q);
  EXPECT_NEAR(held[1], 0, 1e-10 * q);
  EXPECT_NEAR(held[2], 0, 1e-10 * q);
}

class ShellPretension : public ::testing::TestWithParam<const char*> {};

TEST_P(ShellPretension, CarriesTheBoltLoadAsUniformMembraneStress) {
  const auto r = run_deck(deck_path(GetParam()));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  ASSERT_EQ(m.pretension_sections.size(), 1u);
  const auto& s = m.pretension_sections[0];
  EXPECT_NEAR(s.area, kWidth * kT, 1e-12);
  EXPECT_NEAR(s.normal[1], -1.0, 1e-12);  // out of the elements above the cut
  // The cut opens along its normal only: each copy turns with its original (one rotation node).
  std::map<std::int32_t, std::int32_t> rotation_of;
  for (const auto& r_node : m.node_rotations) rotation_of[r_node.node] = r_node.rot_node;
  for (const auto& [original, copy] : s.node_pairs) {
    ASSERT_TRUE(rotation_of.count(original) && rotation_of.count(copy));
    EXPECT_EQ(rotation_of.at(copy), rotation_of.at(original));
  }
  const std::size_t pt = static_cast<std::size_t>(node_row(m, 100));
  const double area = kWidth * kT;
  struct Expect {
    int step;
    double force, tightening;
  };
  for (const Expect& e : {Expect{1, 100.0, 100.0 * kLength / (kE * area)}, Expect{2, kE * 0.01 / kLength * area, 0.01}}) {
    const solver::Frame& f = *r->capture.of_step(e.step).back();
    const std::string what = std::string(GetParam()) + " step " + std::to_string(e.step);
    const double worst = worst_membrane_stress(*r, f, {0, e.force / area, 0});
    report(what + ": worst |S - (0, F/(b t), 0)|", worst);
    EXPECT_LE(worst, 1e-10 * e.force / area) << what;
    EXPECT_NEAR(nodal(f, "RF", pt, 0), e.force, 1e-10 * e.force) << what;
    EXPECT_NEAR(nodal(f, "U", pt, 0), e.tightening, 1e-10 * e.tightening) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(ShellEdges, ShellPretension,
                         ::testing::Values("pretension_shell_s8.inp", "pretension_shell_s4.inp"));

}  // namespace
}  // namespace inpact::verification
