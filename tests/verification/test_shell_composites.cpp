// Composite shells (*SHELL SECTION, COMPOSITE) against classical lamination theory: the
// laminated cantilever strip of gen_shells.py (laminate), L = 10, b = 1, t = 0.1, of a lamina
// E1 = 1.4e5, E2 = 1e4, ν12 = 0, G12 = 5e3, G13 = 5e3, G23 = 3e3 under a tip line load P = 1.
// With ν12 = 0 and cross plies nothing varies across the width (A12 = B12 = D12 = 0, no 16
// terms), so the strip is a Timoshenko beam of bending stiffness b D*, D* = D11 − B11²/A11
// (the axial force vanishes), and shear stiffness b K, K = 5/6 Σ G_k t_k with each ply's G in
// the strip's 13 plane (G13 at 0°, G23 at 90°):
//   δ = P L³ / (3 b D*) + P L / (b K),
// minus P L h² / (12 b D*) for S4, whose elements are one-point Timoshenko beams (test_shells.cpp).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "fixtures/deck_fixture.hpp"
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double kE1 = 1.4e5, kE2 = 1e4, kG13 = 5e3, kG23 = 3e3, kL = 10.0, kP = 1.0;

std::string laminate_deck(const std::string& etype, int n, const std::string& layup) {
  const std::string cmd = "python3 " + deck_path("gen_shells.py") + " --out " + generated_dir().string() +
                          " laminate " + etype + " " + std::to_string(n) + " " + layup;
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return (generated_dir() / ("laminate_" + etype + "_" + std::to_string(n) + "_" + layup + ".inp")).string();
}

/// A ply of the strip: its bottom and top z from the midsurface and whether its fibres run along x.
struct Ply {
  double bottom, top;
  bool along_x;
};

/// D* and K of the plies (per unit width).
std::array<double, 2> laminate_stiffness(const std::vector<Ply>& plies) {
  double a = 0.0, b = 0.0, d = 0.0, k = 0.0;
  for (const Ply& p : plies) {
    const double q = p.along_x ? kE1 : kE2;
    a += q * (p.top - p.bottom);
    b += q * (p.top * p.top - p.bottom * p.bottom) / 2;
    d += q * (p.top * p.top * p.top - p.bottom * p.bottom * p.bottom) / 3;
    k += 5.0 / 6 * (p.along_x ? kG13 : kG23) * (p.top - p.bottom);
  }
  return {d - b * b / a, k};
}

double tip_deflection(const std::string& deck) {
  const auto r = run_deck(deck);
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
  if (!r->outcome.completed) return 0.0;
  double sum = 0.0;
  const auto tip = nset(r->model(), "TIP");
  for (std::int32_t n : tip) sum += nodal(r->capture.last(), "U", static_cast<std::size_t>(n), 2);
  return sum / static_cast<double>(tip.size());
}

double expected(const std::string& etype, const std::array<double, 2>& stiffness) {
  const auto [d, k] = stiffness;
  const double h = etype == "S8R" ? 0.0 : kL / 10;
  return kP * kL * kL * kL / (3 * d) + kP * kL / k - kP * kL * h * h / (12 * d);
}

TEST(ShellComposites, CrossPlyStripsMatchLaminationTheory) {
  const std::vector<Ply> symmetric = {{-0.05, -0.025, true}, {-0.025, 0.0, false}, {0.0, 0.025, false},
                                      {0.025, 0.05, true}};
  const std::vector<Ply> unsymmetric = {{-0.05, 0.0, true}, {0.0, 0.05, false}};
  struct Case {
    const char* etype;
    int n;
  };
  for (const Case& c : {Case{"S8R", 5}, Case{"S4", 10}}) {
    const double cross = tip_deflection(laminate_deck(c.etype, c.n, "cross"));
    EXPECT_NEAR(cross, expected(c.etype, laminate_stiffness(symmetric)), 1e-8 * cross) << c.etype;
    // The same plies turned by *ORIENTATION names instead of angles; and by orientations whose
    // axis 1 is the normal, as their second line says, so that Abaqus projects their axis 2.
    EXPECT_NEAR(tip_deflection(laminate_deck(c.etype, c.n, "orient")), cross, 1e-12 * cross) << c.etype;
    EXPECT_NEAR(tip_deflection(laminate_deck(c.etype, c.n, "normal1")), cross, 1e-12 * cross) << c.etype;
    // [0/90]: bending and stretching couple (B11 ≠ 0).
    const double unsym = tip_deflection(laminate_deck(c.etype, c.n, "unsym"));
    EXPECT_NEAR(unsym, expected(c.etype, laminate_stiffness(unsymmetric)), 1e-8 * unsym) << c.etype;
    report(std::string("laminated strip ") + c.etype + " [0/90/90/0], [0/90]: tip / lamination theory",
           cross / expected(c.etype, laminate_stiffness(symmetric)));
  }
}

// A ply's angle adds to its section's ORIENTATION: a ply at 30° and one at 10° in a section
// oriented at 20° are the same strip (it bends and twists: D16 ≠ 0).
TEST(ShellComposites, APlyAngleAddsToTheSectionOrientation) {
  const auto turned = run_deck(laminate_deck("S4", 10, "turned"));
  const auto composed = run_deck(laminate_deck("S4", 10, "composed"));
  ASSERT_TRUE(turned->outcome.completed && composed->outcome.completed);
  const solver::Frame &a = turned->capture.last(), &b = composed->capture.last();
  for (std::int32_t n : nset(turned->model(), "TIP"))
    for (int c = 0; c < 3; ++c) {
      const double u = nodal(a, "U", static_cast<std::size_t>(n), c);
      EXPECT_NEAR(nodal(b, "U", static_cast<std::size_t>(n), c), u, 1e-10 * 200) << n << " " << c;
    }
  // The 30° ply is softer than the 0° one, and the strip twists: its tip's edges lift unequally.
  const auto tip = nset(turned->model(), "TIP");
  const double edge = nodal(a, "U", static_cast<std::size_t>(tip.front()), 2);
  const double other = nodal(a, "U", static_cast<std::size_t>(tip.back()), 2);
  EXPECT_GT(edge, 100.0);
  EXPECT_GT(std::abs(edge - other), 1e-3 * edge);
}

// S is reported in each ply's material axes: at SPOS of the [0/90] strip the ply's axis 1 runs
// across the strip (S11 = 0, no Poisson) and axis 2 along −x (S22 = σxx), at SNEG along x. With
// ε0 = −(B11/A11) κ at the midsurface, σxx = Q (ε0 + κ z): S22(SPOS)/S11(SNEG) = E2 (ε0/κ + t/2)
// / (E1 (ε0/κ − t/2)) at every point.
TEST(ShellComposites, StressesAreReportedInThePlyAxes) {
  const auto r = run_deck(laminate_deck("S8R", 5, "unsym"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto* s = field(r->capture.last(), "S");
  ASSERT_TRUE(s);
  const double a11 = (kE1 + kE2) * 0.05, b11 = (kE2 - kE1) * 0.05 * 0.05 / 2;
  const double ratio = -b11 / a11;  // ε0 / κ
  const double expected_ratio = kE2 * (ratio + 0.05) / (kE1 * (ratio - 0.05));
  const std::size_t n = s->component_labels.size();
  ASSERT_EQ(s->elements.size() % 2, 0u);
  for (std::size_t i = 0; i < s->elements.size(); i += 2) {  // SNEG, then SPOS of each point
    ASSERT_EQ(s->section_point[i], 1);
    ASSERT_EQ(s->section_point[i + 1], 6);  // two plies of three points
    const double bottom = s->values[n * i], top11 = s->values[n * (i + 1)], top22 = s->values[n * (i + 1) + 1];
    EXPECT_NEAR(top11, 0.0, 1e-9 * std::abs(bottom)) << i;
    EXPECT_NEAR(top22 / bottom, expected_ratio, 1e-8) << i;
    EXPECT_NEAR(s->values[n * i + 3], 0.0, 1e-8 * std::abs(bottom)) << i;
  }
}

// The inner plies, asked for at their middles (points 2, 5, 8, 11 of [0/90/90/0], three points
// a ply), as Abaqus's manual shows it: the strip bends without membrane strain (symmetric, ν12 =
// 0), so each ply carries Q κ z in its own axes. The 0° plies' S11 = E1 κ z (S22 = 0), the 90°
// plies' S22 = E2 κ z (S11 = 0): at one in-plane point S22(5)/S11(2) = E2 z5 / (E1 z2) = E2/(3 E1),
// S11(11) = −S11(2) and S22(8) = −S22(5).
TEST(ShellComposites, InnerPliesAreReportedAtTheSectionPointsAskedFor) {
  std::ifstream in(laminate_deck("S8R", 5, "cross"));
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  deck.insert(deck.rfind("*END STEP"), "*OUTPUT, FIELD\n*ELEMENT OUTPUT\n2, 5, 8, 11\nS\n");
  const test::DeckDir dir;
  const auto r = run_deck(dir.write("deck.inp", deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto* s = field(r->capture.last(), "S");
  ASSERT_TRUE(s);
  const std::size_t n = s->component_labels.size();
  ASSERT_EQ(s->elements.size(), 5u * 4 * 4);  // 5 elements, 2 × 2 points, 4 section points
  for (std::size_t i = 0; i < s->elements.size(); i += 4) {
    ASSERT_EQ(s->section_point[i], 2);
    ASSERT_EQ(s->section_point[i + 3], 11);
    const double* sp2 = &s->values[n * i];
    const double* sp5 = &s->values[n * (i + 1)];
    const double* sp8 = &s->values[n * (i + 2)];
    const double* sp11 = &s->values[n * (i + 3)];
    const double scale = std::abs(sp2[0]);
    EXPECT_GT(scale, 0.0);
    EXPECT_NEAR(sp2[1], 0.0, 1e-9 * scale);
    EXPECT_NEAR(sp5[0], 0.0, 1e-9 * scale);
    EXPECT_NEAR(sp5[1] / sp2[0], kE2 / (3 * kE1), 1e-8) << i;
    EXPECT_NEAR(sp11[0], -sp2[0], 1e-9 * scale) << i;
    EXPECT_NEAR(sp8[1], -sp5[1], 1e-9 * scale) << i;
  }
}

/// A plate of four S4 (4 × 1, t = 0.1, E = 2e5, ν = 0.3), its section ORIENTATION (when
/// `oriented`) turned by 30° about z; `step` is the deck after *BOUNDARY (supports, the step).
std::unique_ptr<Run> run_turned_plate(bool oriented, const std::string& step) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  std::string deck = "*NODE, NSET=ALL\n";
  for (int i = 0; i <= 4; ++i) deck += fmt::format("{}, {}, 0., 0.\n{}, {}, 1., 0.\n", i + 1, i, i + 11, i);
  deck += "*ELEMENT, TYPE=S4, ELSET=PLATE\n";
  for (int i = 0; i < 4; ++i) deck += fmt::format("{}, {}, {}, {}, {}\n", i + 1, i + 1, i + 2, i + 12, i + 11);
  deck += fmt::format("*ORIENTATION, NAME=TURNED\n{}, {}, 0., {}, {}, 0.\n", c, s, -s, c);
  deck += std::string("*SHELL SECTION, ELSET=PLATE, MATERIAL=M") + (oriented ? ", ORIENTATION=TURNED" : "") +
          "\n0.1\n*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*BOUNDARY\n" + step;
  const test::DeckDir dir;
  return run_deck(dir.write("deck.inp", deck));
}

// SF and SM are reported in the axes of the section's ORIENTATION, as S is (Abaqus gives a shell's
// element variables in its local directions). The plate (run_turned_plate) held in its plane and
// pulled along x by N = 1 a length: in axes turned by 30° about the normal, SF1 =
// N cos²30°, SF2 = N sin²30°, SF3 = −N sin 30° cos 30° and t·S at every point, to 1e-12; without
// the orientation SF = (N, 0, 0).
TEST(ShellComposites, SectionForcesAreReportedInTheSectionOrientation) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  for (const bool oriented : {false, true}) {
    const auto r = run_turned_plate(oriented, "1, 1, 2\n11, 1, 1\nALL, 3, 6\n*STEP\n*STATIC\n*CLOAD\n5, 1, 0.5\n"
                                              "15, 1, 0.5\n*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS, SF\n*END STEP\n");
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::FieldData& sf = *field(r->capture.last(), "SF");
    const solver::FieldData& stress = *field(r->capture.last(), "S");
    ASSERT_EQ(sf.component_labels.size(), 3u);
    const std::array<double, 3> expected = oriented ? std::array{c * c, s * s, -s * c} : std::array{1.0, 0.0, 0.0};
    const std::size_t n = stress.component_labels.size();
    for (std::size_t i = 0; i < sf.elements.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(sf.values[3 * i + k], expected[k], 1e-12) << "oriented " << oriented << " SF" << k + 1;
        const std::size_t slot = k == 2 ? 3 : k;  // S11, S22, S12
        EXPECT_NEAR(0.1 * stress.values[n * (2 * i) + slot], expected[k], 1e-12) << "S at SNEG, " << k;
      }
  }
}

// SM turns with the section's ORIENTATION as SF does: the plate clamped at x = 0 and bent by end
// moments about y (its isotropic stiffness does not see the orientation), SM in axes turned by
// 30° is the default axes' SM turned, m11' = c² m11 + s² m22 + 2cs m12, m22' = s² m11 + c² m22 −
// 2cs m12, m12' = cs (m22 − m11) + (c² − s²) m12, at every in-plane point to 1e-10.
TEST(ShellComposites, SectionMomentsTurnWithTheSectionOrientation) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  std::vector<double> sm[2];
  for (const bool oriented : {false, true}) {
    const auto r = run_turned_plate(oriented, "1, ENCASTRE\n11, ENCASTRE\n*STEP\n*STATIC\n*CLOAD\n5, 5, 0.5\n"
                                              "15, 5, 0.5\n*OUTPUT, FIELD\n*ELEMENT OUTPUT\nSM\n*END STEP\n");
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    sm[oriented] = field(r->capture.last(), "SM")->values;
  }
  ASSERT_EQ(sm[0].size(), sm[1].size());
  double largest = 0.0;
  for (double v : sm[0]) largest = std::max(largest, std::abs(v));
  EXPECT_GT(largest, 0.5);
  for (std::size_t i = 0; i + 2 < sm[0].size(); i += 3) {
    const double m11 = sm[0][i], m22 = sm[0][i + 1], m12 = sm[0][i + 2];
    EXPECT_NEAR(sm[1][i], c * c * m11 + s * s * m22 + 2 * c * s * m12, 1e-10 * largest) << i;
    EXPECT_NEAR(sm[1][i + 1], s * s * m11 + c * c * m22 - 2 * c * s * m12, 1e-10 * largest) << i;
    EXPECT_NEAR(sm[1][i + 2], c * s * (m22 - m11) + (c * c - s * s) * m12, 1e-10 * largest) << i;
  }
}

constexpr double kStretch = 3e-3;

/// One S4 (1 × 1) of `section_and_materials`, held against w and turning at every node and moved
/// to u = ε x, v = ε y (ε = kStretch) over two increments, after `model_lines` and with
/// `step_lines` first in the step; `variables` output at its six section points.
std::unique_ptr<Run> run_stretched_plate(const std::string& section_and_materials, const std::string& model_lines,
                                         const std::string& step_lines, const std::string& variables) {
  std::string deck = "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n"
                     "*ELEMENT, TYPE=S4, ELSET=PLATE\n1, 1, 2, 3, 4\n" +
                     section_and_materials + model_lines + "*BOUNDARY\nALL, 3, 6\n1, 1, 2\n*STEP\n*STATIC\n0.5, 1.\n" +
                     step_lines + "*BOUNDARY\n";
  for (const auto& [node, x, y] : {std::tuple{2, 1, 0}, std::tuple{3, 1, 1}, std::tuple{4, 0, 1}})
    deck += fmt::format("{}, 1, 1, {}\n{}, 2, 2, {}\n", node, kStretch * x, node, kStretch * y);
  deck += "*OUTPUT, FIELD\n*ELEMENT OUTPUT\n1, 2, 3, 4, 5, 6\n" + variables + "\n*END STEP\n";
  const test::DeckDir dir;
  return run_deck(dir.write("deck.inp", deck));
}

// A COMPOSITE of an elastic layer (SNEG side) and a plastic one (E = 2e5, ν = 0.3; σ_y = 200,
// H = 2000), one S4 stretched equibiaxially, ε11 = ε22 = ε = 3e-3, through displacements held at
// every node (u = ε x, v = ε y, no w, no turn): each section point's strain is (ε, ε, 0), so each
// layer answers by its own law alone. Elastic: σ11 = σ22 = E ε/(1 − ν). Plastic, equibiaxial
// σ with Mises σ̄ = σ and flow ε̇ᵖ11 = ε̇ᵖ22 = ε̄̇ᵖ/2: ε = σ(1 − ν)/E + ε̄ᵖ/2, σ = σ_y + H ε̄ᵖ, so
// ε̄ᵖ = (ε − σ_y(1 − ν)/E) / ((1 − ν) H/E + 1/2). Exact for this proportional path (1e-9).
TEST(ShellComposites, AnElasticAndAPlasticLayerEachFollowTheirOwnLaw) {
  constexpr double kStrain = kStretch, kE = 2e5, kNu = 0.3, kYield = 200.0, kH = 2000.0;
  const auto r = run_stretched_plate("*SHELL SECTION, ELSET=PLATE, COMPOSITE\n0.05, 3, ELASTIC\n0.05, 3, METAL\n"
                                     "*MATERIAL, NAME=ELASTIC\n*ELASTIC\n2e5, 0.3\n"
                                     "*MATERIAL, NAME=METAL\n*ELASTIC\n2e5, 0.3\n*PLASTIC\n200., 0.\n400., 0.1\n",
                                     "", "", "S, PEEQ");
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto* s = field(r->capture.last(), "S");
  const auto* peeq = field(r->capture.last(), "PEEQ");
  ASSERT_TRUE(s && peeq);
  const double elastic = kE * kStrain / (1 - kNu);
  const double plastic_strain = (kStrain - kYield * (1 - kNu) / kE) / ((1 - kNu) * kH / kE + 0.5);
  const double plastic = kYield + kH * plastic_strain;
  const std::size_t n = s->component_labels.size();
  ASSERT_EQ(s->elements.size(), 4u * 6);
  for (std::size_t i = 0; i < s->elements.size(); ++i) {
    const bool in_metal = s->section_point[i] > 3;
    const double sigma = in_metal ? plastic : elastic;
    EXPECT_NEAR(s->values[n * i], sigma, 1e-9 * sigma) << "section point " << s->section_point[i];
    EXPECT_NEAR(s->values[n * i + 1], sigma, 1e-9 * sigma) << "section point " << s->section_point[i];
    EXPECT_NEAR(peeq->values[i], in_metal ? plastic_strain : 0.0, 1e-9 * plastic_strain)
        << "section point " << s->section_point[i];
  }
}

// A plastic layer beside a layer of temperature tables (E = 2e5 − 1e3 T, ν = 0.3 from rows at 0
// and 100), the plate at T = 50 from 0 and stretched equibiaxially by ε = 3e-3 as above (α = 0):
// the table layer reads its own T, σ = E(50) ε/(1 − ν) = 1.5e5 ε/0.7; the plastic one is as
// before. (The element's law, the plastic one, reads no temperature: the table layer must get
// its T all the same.)
TEST(ShellComposites, ATableLayerBesideAPlasticLayerReadsItsTemperature) {
  constexpr double kStrain = kStretch;
  const auto r = run_stretched_plate("*SHELL SECTION, ELSET=PLATE, COMPOSITE\n0.05, 3, TABLE\n0.05, 3, METAL\n"
                                     "*MATERIAL, NAME=TABLE\n*ELASTIC\n2e5, 0.3, 0.\n1e5, 0.3, 100.\n"
                                     "*MATERIAL, NAME=METAL\n*ELASTIC\n2e5, 0.3\n*PLASTIC\n200., 0.\n400., 0.1\n",
                                     "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 0.\n", "*TEMPERATURE\nALL, 50.\n", "S");
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto* s = field(r->capture.last(), "S");
  ASSERT_TRUE(s);
  ASSERT_EQ(s->elements.size(), 4u * 6);
  const double table = 1.5e5 * kStrain / 0.7;
  const double plastic_strain = (kStrain - 200.0 * 0.7 / 2e5) / (0.7 * 2000.0 / 2e5 + 0.5);
  const double plastic = 200.0 + 2000.0 * plastic_strain;
  const std::size_t n = s->component_labels.size();
  for (std::size_t i = 0; i < s->elements.size(); ++i) {
    const double sigma = s->section_point[i] > 3 ? plastic : table;
    EXPECT_NEAR(s->values[n * i], sigma, 1e-9 * sigma) << "section point " << s->section_point[i];
  }
}

// The plastic layers of one COMPOSITE take one form of hardening (one law starts every point's
// state); a plastic layer turned by an angle is refused (its plastic strain would be reported in
// other axes than its stress).
TEST(ShellComposites, PlasticLayersOfTwoHardeningFormsOrTurnedAreRefused) {
  const std::string model = "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n"
                            "*ELEMENT, TYPE=S4, ELSET=PLATE\n1, 1, 2, 3, 4\n"
                            "*MATERIAL, NAME=ISO\n*ELASTIC\n2e5, 0.3\n*PLASTIC\n200., 0.\n"
                            "*MATERIAL, NAME=KIN\n*ELASTIC\n2e5, 0.3\n*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS\n"
                            "200., 1e4, 50.\n"
                            "*BOUNDARY\nALL, 1, 6\n*STEP\n*STATIC\n*END STEP\n";
  const test::DeckDir dir;
  const std::string mixed = stop_message(dir.write("mixed.inp", "*SHELL SECTION, ELSET=PLATE, COMPOSITE\n"
                                                                "0.05, 3, ISO\n0.05, 3, KIN\n" + model));
  EXPECT_NE(mixed.find("the plastic layers of a COMPOSITE section keep one layout of state so far; material 'KIN' "
                       "keeps 14 values a point where material 'ISO' of an earlier layer keeps 8 (expected the same "
                       "form of hardening)"),
            std::string::npos)
      << mixed;
  const std::string turned = stop_message(dir.write("turned.inp", "*SHELL SECTION, ELSET=PLATE, COMPOSITE\n"
                                                                  "0.05, 3, ISO, 30.\n0.05, 3, ISO\n" + model));
  EXPECT_NE(turned.find("material 'ISO' has *PLASTIC; a plastic shell or layer takes isotropic elasticity and no "
                        "ORIENTATION or angle so far"),
            std::string::npos)
      << turned;
}

}  // namespace
}  // namespace inpact::verification
