// Beam stresses at section points (solver/elements/beam_section_points.hpp) on the cantilevers of
// test_beams.cpp (L = 10, n1 = y, n2 = z; tip loads 1 along y, 2 along z, a torque 5): S11 from
// the statics of the cantilever, M(x) = P (L − x) over the section modulus, and S12 from
// St. Venant's torsion — T r/J on a circle, Bredt's T/(2 A_m t) in a box's wall, T t/J on an open
// wall's face — to round-off (1e-9).
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "solver/elements/beam_section.hpp"
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double kL = 10.0, kE = 2.0e5, kG = kE / 2.6;

/// The B33 cantilever of two elements with the *BEAM SECTION lines `section` in place of the
/// RECT's, writing S and E beside SF and SM.
std::unique_ptr<Run> run_section(const std::string& tag, const std::vector<std::string>& section) {
  const auto path = edited_deck("beam_cantilever_b33_2.inp", tag, [&](const std::string& line) {
    if (line == "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT") return section;
    if (line == "0.3, 0.2" || line == "0., 1., 0.") return std::vector<std::string>{};
    if (line == "SF, SM") return std::vector<std::string>{"SF, SM, S, E"};
    return std::vector<std::string>{line};
  });
  auto r = run_deck(path.string());
  std::filesystem::remove(path);
  return r;
}

/// Component c of `key` at element `el`, integration point `ip`, section point `sp`.
double at(const solver::Frame& f, const std::string& key, std::int64_t el, int ip, int sp, int c) {
  const auto* fd = field(f, key);
  if (!fd) throw std::runtime_error("frame has no field " + key);
  const std::size_t n = fd->component_labels.size();
  for (std::size_t i = 0; i < fd->elements.size(); ++i)
    if (fd->elements[i] == el && fd->ip[i] == ip && (sp == 0 || fd->section_point.at(i) == sp))
      return fd->values[i * n + static_cast<std::size_t>(c)];
  throw std::runtime_error(fmt::format("{} has no element {} ip {} sp {}", key, el, ip, sp));
}

/// The distance from the root of element `el`'s integration point `ip` (two Gauss points on
/// elements of length 5).
double x_of(std::int64_t el, int ip) {
  const double g = (ip == 1 ? -1.0 : 1.0) / std::sqrt(3.0);
  return 5.0 * static_cast<double>(el - 1) + 2.5 * (1.0 + g);
}

/// S11 at every section point (x1, x2) of every point against the statics: step 1 (P = 1 along
/// y = n1) bends about n2, σ = −M2 x1/I22 with M2 = L − x; step 2 (2 along z = n2) about n1,
/// σ = M1 x2/I11 with M1 = −2 (L − x).
void expect_bending(const Run& r, const std::vector<std::array<double, 3>>& points, double i11, double i22) {
  for (int step : {1, 2})
    for (std::int64_t el : {1, 2})
      for (int ip : {1, 2})
        for (const auto& [sp, x1, x2] : points) {
          const double m = (step == 1 ? 1.0 : 2.0) * (kL - x_of(el, ip));
          const double s11 = step == 1 ? -m * x1 / i22 : -m * x2 / i11;
          const double got = at(*r.capture.of_step(step).back(), "S", el, ip, static_cast<int>(sp), 0);
          EXPECT_NEAR(got, s11, 1e-9 * std::abs(m) * 1e4) << "step " << step << " element " << el << " ip " << ip
                                                            << " sp " << sp;
          EXPECT_NEAR(at(*r.capture.of_step(step).back(), "E", el, ip, static_cast<int>(sp), 0), s11 / kE,
                      1e-9 * std::abs(m) * 1e4 / kE);
        }
}

/// S12 and E12 under the torque 5 (step 3) at each section point, against `tau` of that point.
void expect_torsion(const Run& r, const std::vector<std::pair<int, double>>& tau) {
  const solver::Frame& f = *r.capture.of_step(3).back();
  for (std::int64_t el : {1, 2})
    for (int ip : {1, 2})
      for (const auto& [sp, t] : tau) {
        EXPECT_NEAR(at(f, "S", el, ip, sp, 3), t, 1e-9 * t) << "sp " << sp;
        EXPECT_NEAR(at(f, "E", el, ip, sp, 3), t / kG, 1e-9 * t / kG) << "sp " << sp;
        EXPECT_NEAR(at(f, "S", el, ip, sp, 0), 0.0, 1e-9 * t) << "sp " << sp;
      }
}

// RECT 0.3 × 0.2: the four corners 1, 5, 21, 25 (Abaqus's default output points) carry
// ±M c/I; St. Venant's torsional shear vanishes at a rectangle's corners.
TEST(BeamStresses, ARectangleCarriesTheBendingStressAtItsCorners) {
  const auto r = run_section("beam-s-rect", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT", "0.3, 0.2",
                                             "0., 1., 0."});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  expect_bending(*r, {{1, -0.15, -0.1}, {5, 0.15, -0.1}, {21, -0.15, 0.1}, {25, 0.15, 0.1}}, 2e-4, 4.5e-4);
  const solver::Frame& f = *r->capture.of_step(3).back();
  for (int sp : {1, 5, 21, 25}) EXPECT_NEAR(at(f, "S", 1, 1, sp, 3), 0.0, 1e-9);
  // SF and SM stay at the integration points, without section points.
  EXPECT_TRUE(field(f, "SF")->section_point.empty());
}

// CIRC r = 0.1: 3, 7, 11, 15 on the surface at ±n1, ±n2; the torque gives T r/J (J = π r⁴/2)
// there, and MISES = √3 S12.
TEST(BeamStresses, ACircleCarriesTheTorsionalShearOnItsSurface) {
  const auto r = run_section("beam-s-circ", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=CIRC", "0.1",
                                             "0., 1., 0."});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double i = std::numbers::pi * 1e-4 / 4, tau = 5 * 0.1 / (2 * i);
  expect_bending(*r, {{3, 0.1, 0.0}, {7, 0.0, 0.1}, {11, -0.1, 0.0}, {15, 0.0, -0.1}}, i, i);
  expect_torsion(*r, {{3, tau}, {7, tau}, {11, tau}, {15, tau}});
}

// CalculiX's two-number CIRC: an ellipse of full axes 0.3 (n1) and 0.2 (n2), semi-axes a = 0.15,
// b = 0.1: I11 = π a b³/4, I22 = π a³ b/4, J = π a³ b³/(a² + b²); the torque gives 2T/(π a² b)
// at (±a, 0) and 2T/(π a b²) at (0, ±b), and the tip turns by T L/(G J) (B33: exact).
TEST(BeamStresses, CalculixsEllipseCarriesItsBendingAndTorsion) {
  const auto r = run_section("beam-s-ellipse", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=CIRC", "0.3, 0.2",
                                                "0., 1., 0."});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double a = 0.15, b = 0.1, pi = std::numbers::pi;
  const double i11 = pi * a * b * b * b / 4, i22 = pi * a * a * a * b / 4;
  const double j = pi * a * a * a * b * b * b / (a * a + b * b);
  expect_bending(*r, {{3, a, 0.0}, {7, 0.0, b}, {11, -a, 0.0}, {15, 0.0, -b}}, i11, i22);
  const double on_n1 = 2 * 5 / (pi * a * a * b), on_n2 = 2 * 5 / (pi * a * b * b);
  expect_torsion(*r, {{3, on_n1}, {7, on_n2}, {11, on_n1}, {15, on_n2}});
  const auto tip = static_cast<std::size_t>(nset(r->model(), "TIP").at(0));
  const double twist = 5 * kL / (kG * j);
  EXPECT_NEAR(nodal(*r->capture.of_step(3).back(), "UR", tip, 0), twist, 1e-9 * twist);
}

// BOX 0.3 × 0.2 with walls 0.02 (±n1) and 0.03 (±n2): the midline's corners, each with Bredt's
// T/(2 A_m t) of the wall that starts there (1: t1, 5: t2, 9: t3, 13: t4).
TEST(BeamStresses, ABoxCarriesBredtsShearInItsWalls) {
  const auto r = run_section("beam-s-box", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=BOX",
                                            "0.3, 0.2, 0.02, 0.03, 0.02, 0.03", "0., 1., 0."});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double i11 = (0.3 * 0.008 - 0.26 * std::pow(0.14, 3)) / 12, i22 = (0.2 * 0.027 - 0.14 * std::pow(0.26, 3)) / 12;
  expect_bending(*r, {{1, 0.14, -0.085}, {5, 0.14, 0.085}, {9, -0.14, 0.085}, {13, -0.14, -0.085}}, i11, i22);
  const double am = 0.28 * 0.17;
  expect_torsion(*r, {{1, 5 / (2 * am * 0.02)}, {5, 5 / (2 * am * 0.03)}, {9, 5 / (2 * am * 0.02)},
                      {13, 5 / (2 * am * 0.03)}});
}

// A doubly symmetric I (0.15, 0.3, 0.2, 0.2, 0.02, 0.02, 0.01): the flange tips on the flanges'
// midlines (x2 = ±0.14), and the open wall's T t/J on the flanges' faces (J = Σ b t³/3).
TEST(BeamStresses, AnICarriesTheStressAtItsFlangeTips) {
  const auto r = run_section("beam-s-i", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=I",
                                          "0.15, 0.3, 0.2, 0.2, 0.02, 0.02, 0.01", "0., 1., 0."});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double web = 0.26, i11 = 2 * (0.2 * std::pow(0.02, 3) / 12 + 0.004 * 0.14 * 0.14) + 0.01 * std::pow(web, 3) / 12;
  const double i22 = 2 * 0.02 * std::pow(0.2, 3) / 12 + web * std::pow(0.01, 3) / 12;
  const double J = (2 * 0.2 * std::pow(0.02, 3) + web * std::pow(0.01, 3)) / 3;
  expect_bending(*r, {{1, -0.1, -0.14}, {5, 0.1, -0.14}, {11, -0.1, 0.14}, {15, 0.1, 0.14}}, i11, i22);
  expect_torsion(*r, {{1, 5 * 0.02 / J}, {5, 5 * 0.02 / J}, {11, 5 * 0.02 / J}, {15, 5 * 0.02 / J}});

  // Unequal flanges (0, 0.3, 0.2, 0.1, 0.02, 0.01, 0.01), the origin on the bottom edge: the
  // points lie e below and 0.295 − e above the centroid.
  const auto tee = run_section("beam-s-tee", {"*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=I",
                                              "0., 0.3, 0.2, 0.1, 0.02, 0.01, 0.01", "0., 1., 0."});
  ASSERT_TRUE(tee->outcome.completed) << tee->outcome.message;
  const double a1 = 0.004, a2 = 0.001, aw = 0.27 * 0.01, area = a1 + a2 + aw;
  const double e = (a1 * 0.01 + a2 * 0.295 + aw * 0.155) / area;
  const double t11 = 0.2 * std::pow(0.02, 3) / 12 + a1 * std::pow(0.01 - e, 2) + 0.1 * std::pow(0.01, 3) / 12 +
                     a2 * std::pow(0.295 - e, 2) + 0.01 * std::pow(0.27, 3) / 12 + aw * std::pow(0.155 - e, 2);
  const double t22 = (0.02 * 0.008 + 0.01 * 0.001 + 0.27 * 1e-6) / 12;
  expect_bending(*tee, {{1, -0.1, 0.01 - e}, {5, 0.1, 0.01 - e}, {11, -0.05, 0.295 - e}, {15, 0.05, 0.295 - e}}, t11,
                 t22);
}

// A general section with the RECT's A, I and J and *SECTION POINTS at two of its corners: the
// same S11 there, numbered 1 and 2 in the order given; S12 is not output (axial only, as Abaqus).
TEST(BeamStresses, AGeneralSectionReportsAtItsSectionPoints) {
  model::BeamSection s;
  s.dims = {0.3, 0.2};
  const double J = solver::elements::beam_properties(s, kE, 0.3).torsion;
  const auto r = run_section("beam-s-general",
                             {"*BEAM GENERAL SECTION, ELSET=BEAM, SECTION=GENERAL",
                              fmt::format("0.06, 2e-4, 0., 4.5e-4, {:.17g}", J), "0., 1., 0.", fmt::format("{}, {}", kE, kG),
                              "*SECTION POINTS", "-0.15, -0.1, 0.15, 0.1"});
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  expect_bending(*r, {{1, -0.15, -0.1}, {2, 0.15, 0.1}}, 2e-4, 4.5e-4);
  EXPECT_EQ(at(*r->capture.of_step(3).back(), "S", 1, 1, 1, 3), 0.0);

  // Without *SECTION POINTS it has nowhere to report S.
  const auto none = run_section("beam-s-general-none", {"*BEAM GENERAL SECTION, ELSET=BEAM, SECTION=GENERAL",
                                                        fmt::format("0.06, 2e-4, 0., 4.5e-4, {:.17g}", J), "0., 1., 0.",
                                                        fmt::format("{}, {}", kE, kG)});
  ASSERT_TRUE(none->outcome.completed) << none->outcome.message;
  const auto* stress = field(*none->capture.of_step(1).back(), "S");
  EXPECT_TRUE(stress == nullptr || stress->elements.empty());
}

}  // namespace
}  // namespace inpact::verification
