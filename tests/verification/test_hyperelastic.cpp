// Hyperelastic blocks and the near-incompressible cantilever (decks/verification/hyper_*.inp,
// written by gen_hyper.py; the refined reference cantilever is generated at test time).
//  - Neo-Hooke (C10 = 1, D1 = 0.1) in uniaxial tension to stretch 2: the nominal stress
//    Σ RF / A0 and the lateral stretch against the closed form (lateral stretch from σ22 = 0,
//    by bisection), within 1e-6 relative: one C3D8 (a deck without NLGEOM: switched on), a
//    2 × 1 × 1 C3D20H mesh, a 2 × 2 CAX8H mesh (A0 = π r², the reaction is the whole ring's).
//  - A follower pressure of −1 (NLGEOM) on a cube's face: σ11 = 1 and the stretch of
//    τ1/J = 1, within 1e-8.
//  - Simple shear to γ = 1 (J = 1): P12 = Σ RF1(top) / A0 = 2 C10 γ and σ12 = 2 C10 γ at every
//    point, within 1e-6: one C3D8, a 2 × 2 × 2 C3D20 mesh, a 3 × 2 CPE4H mesh.
//  - The plane-strain cantilever (K0/μ0 = 1e4): tip deflection of CPE4H 80 × 8, CPE8H and CPE8RH
//    40 × 4 within 1 % of the refined CPE8H 80 × 8 (and within 2 % of Timoshenko's beam, whose
//    clamp is not the deck's); the standard CPE4 locks (below half of it); the pressure at the
//    element centroids within 3 % of p = −σ11/2 = −P (L − x)(y − h/2)/(2I) of the largest,
//    between x = 2 and 8 (no checkerboard).
#include "verification_fixture.hpp"

#include <numbers>

namespace inpact::verification {
namespace {

constexpr double C10 = 1.0, D1 = 0.1;

/// Neo-Hooke principal Kirchhoff stress τ_a = 2 C10 (λ̄_a² − Ī1/3) + J · 2(J − 1)/D1.
double tau(double la, double lb, double lc, int a) {
  const double J = la * lb * lc, s = std::pow(J, -2.0 / 3);
  const double l2[3] = {la * la * s, lb * lb * s, lc * lc * s};
  return 2 * C10 * (l2[a] - (l2[0] + l2[1] + l2[2]) / 3) + J * 2 * (J - 1) / D1;
}

double lateral_stretch(double l) {
  double lo = 0.2, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (tau(l, mid, mid, 1) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double sum_over(const Run& r, const solver::Frame& f, const std::string& set, const std::string& key, int c) {
  double s = 0;
  for (std::int32_t n : nset(r.model(), set)) s += nodal(f, key, static_cast<std::size_t>(n), c);
  return s;
}

struct Uniaxial {
  const char* deck;
  int axis;     ///< the stretched direction (0-based)
  double area;  ///< A0 of the end face (CAX: π r²)
  double length;
};

TEST(Hyperelastic, NeoHookeUniaxialTensionToStretchTwo) {
  const double l = 2.0, lt = lateral_stretch(l), P = tau(l, lt, lt, 0) / l;
  for (const Uniaxial& c : {Uniaxial{"hyper_uniaxial_c3d8.inp", 0, 1.0, 1.0},
                            Uniaxial{"hyper_uniaxial_c3d20h.inp", 0, 1.0, 2.0},
                            Uniaxial{"hyper_uniaxial_cax8h.inp", 1, std::numbers::pi, 1.0}}) {
    SCOPED_TRACE(c.deck);
    const auto r = run_deck(deck_path(c.deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    EXPECT_NEAR(f.step_time, 1.0, 1e-12);
    const double nominal = sum_over(*r, f, "END", "RF", c.axis) / c.area;
    EXPECT_NEAR(nominal, P, 1e-6 * P);
    // The lateral stretch: the node farthest from the symmetry planes.
    const auto& mesh = r->model().mesh;
    std::size_t far = 0;
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
      if (mesh.nodes.coords[n][0] + mesh.nodes.coords[n][1] + mesh.nodes.coords[n][2] >
          mesh.nodes.coords[far][0] + mesh.nodes.coords[far][1] + mesh.nodes.coords[far][2])
        far = n;
    const int lateral = c.axis == 0 ? 1 : 0;
    const double x = mesh.nodes.coords[far][lateral];
    EXPECT_NEAR((x + nodal(f, "U", far, lateral)) / x, lt, 1e-6 * lt);
    report(std::string(c.deck) + ": |P - closed form| / P", std::abs(nominal - P) / P);
    if (std::string(c.deck) == "hyper_uniaxial_c3d8.inp") {
      EXPECT_TRUE(r->model().steps[0].nlgeom_switched_on);
    }
  }
}

// NLGEOM pressure follows the face: a cube pulled by −1 on its face x = 1 carries σ11 = 1
// (Cauchy) exactly; its stretch is the λ of τ1/J = 1 with the lateral faces free (τ2 = 0).
TEST(Hyperelastic, FollowerPressureGivesTheCauchyStressOfThePressure) {
  const auto r = run_deck(deck_path("hyper_follower_pressure_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  for (const auto& p : point_values(*r, f, "S")) {
    EXPECT_NEAR(p.s[0], 1.0, 1e-8);
    EXPECT_NEAR(p.s[1], 0.0, 1e-8);
  }
  double lo = 1.0, hi = 3.0;  // σ11(λ) = τ1/J rises with λ
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi), lt = lateral_stretch(mid);
    (tau(mid, lt, lt, 0) / (mid * lt * lt) > 1.0 ? hi : lo) = mid;
  }
  const double stretch = 0.5 * (lo + hi);
  const auto& mesh = r->model().mesh;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (mesh.nodes.coords[n][0] > 0.5) {
      EXPECT_NEAR(1.0 + nodal(f, "U", n, 0), stretch, 1e-8);
    }
  report("hyper_follower_pressure_c3d8.inp: stretch", stretch);
}

TEST(Hyperelastic, NeoHookeSimpleShear) {
  const double gamma = 1.0, P12 = 2 * C10 * gamma;
  for (const auto& [deck, area] : {std::pair{"hyper_shear_c3d8.inp", 1.0}, std::pair{"hyper_shear_c3d20.inp", 1.0},
                                   std::pair{"hyper_shear_cpe4h.inp", 1.5}}) {
    SCOPED_TRACE(deck);
    const auto r = run_deck(deck_path(deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    const double nominal = sum_over(*r, f, "TOP", "RF", 0) / area;
    EXPECT_NEAR(nominal, P12, 1e-6 * P12);
    for (const auto& p : point_values(*r, f, "S")) EXPECT_NEAR(p.s[3], P12, 1e-6 * P12);
    report(std::string(deck) + ": |P12 - 2 C10 gamma| / P12", std::abs(nominal - P12) / P12);
  }
}

// --- the near-incompressible cantilever ---

/// decks/verification/gen_hyper.py --bending-reference into the generated decks' folder.
void generate_hyper_reference() {
  const std::string cmd = "python3 " + deck_path("gen_hyper.py") + " --bending-reference --out " + generated_dir().string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

constexpr double L = 10.0, h = 1.0, P = 1e-5, mu = 1.0;

double tip_deflection(const Run& r) {
  const solver::Frame& f = r.capture.last();
  const auto tip = nset(r.model(), "TIP");
  return -sum_over(r, f, "TIP", "U", 1) / static_cast<double>(tip.size());
}

/// The largest deviation of the element-centroid pressure from the beam's, between x = 2 and 8,
/// over the largest beam pressure there.
double pressure_deviation(const Run& r) {
  const double I = h * h * h / 12;
  std::map<std::int64_t, std::array<double, 3>> sum;  // element → Σx, Σy, Σp (and count below)
  std::map<std::int64_t, int> count;
  for (const auto& p : point_values(r, r.capture.last(), "S")) {
    auto& s = sum[p.element];
    s[0] += p.x[0];
    s[1] += p.x[1];
    s[2] += -(p.s[0] + p.s[1] + p.s[2]) / 3;
    ++count[p.element];
  }
  double worst = 0, largest = 0;
  for (const auto& [e, s] : sum) {
    const double n = count[e], x = s[0] / n, y = s[1] / n;
    if (x < 2 || x > 8) continue;
    const double beam = -P * (L - x) * (y - h / 2) / (2 * I);
    worst = std::max(worst, std::abs(s[2] / n - beam));
    largest = std::max(largest, std::abs(beam));
  }
  return worst / largest;
}

TEST(Hyperelastic, NearIncompressibleCantileverDoesNotLockInHybridElements) {
  generate_hyper_reference();
  const auto ref = run_deck((generated_dir() / "hyper_bending_reference_cpe8h.inp").string());
  ASSERT_TRUE(ref->outcome.completed) << ref->outcome.message;
  const double v_ref = tip_deflection(*ref);
  const double I = h * h * h / 12, timoshenko = P * L * L * L / (3 * 4 * mu * I) + P * L / (5.0 / 6 * mu * h);
  report("cantilever CPE8H 80 x 8: tip deflection", v_ref);
  report("cantilever CPE8H 80 x 8: / Timoshenko", v_ref / timoshenko);
  EXPECT_NEAR(v_ref, timoshenko, 0.02 * timoshenko);
  for (const char* deck : {"hyper_bending_cpe4h.inp", "hyper_bending_cpe8h.inp", "hyper_bending_cpe8rh.inp"}) {
    SCOPED_TRACE(deck);
    const auto r = run_deck(deck_path(deck));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const double v = tip_deflection(*r), dp = pressure_deviation(*r);
    EXPECT_NEAR(v, v_ref, 0.01 * v_ref);
    EXPECT_LE(dp, 0.03);
    report(std::string(deck) + ": tip deflection / refined", v / v_ref);
    report(std::string(deck) + ": centroid pressure deviation / largest", dp);
  }
  const auto locked = run_deck(deck_path("hyper_bending_cpe4.inp"));
  ASSERT_TRUE(locked->outcome.completed) << locked->outcome.message;
  const double ratio = tip_deflection(*locked) / v_ref;
  EXPECT_LT(ratio, 0.5);
  report("hyper_bending_cpe4.inp (standard CPE4, locks): tip deflection / refined", ratio);
}

}  // namespace
}  // namespace inpact::verification
