// Shells against closed forms and the standard shell benchmarks of MacNeal and Harder (1985),
// decks written by decks/verification/gen_shells.py at test time (their headers give the
// problem data). Each benchmark runs on two or three meshes; the figures are reported and the
// finest must lie within the stated tolerance of the published reference.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

/// Writes gen_shells.py's deck `name` (ETYPE N [thin]) into the generated folder, returns its path.
std::string shell_deck(const std::string& name, const std::string& etype, int n, bool thin = false) {
  const std::string cmd = "python3 " + deck_path("gen_shells.py") + " --out " + generated_dir().string() + " " + name +
                          " " + etype + " " + std::to_string(n) + (thin ? " thin" : "");
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return (generated_dir() / (name + "_" + etype + "_" + std::to_string(n) + (thin ? "_thin" : "") + ".inp")).string();
}

/// The row of the single node of node set `set`.
std::size_t single(const Run& r, const std::string& set) {
  const auto rows = nset(r.model(), set);
  EXPECT_EQ(rows.size(), 1u) << set;
  return static_cast<std::size_t>(rows.at(0));
}

/// Runs a deck and returns component c of U at the node of set `set` in the last frame of `step`.
double displacement(const std::string& deck, const std::string& set, int c, int step = 1) {
  const auto r = run_deck(deck);
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
  if (!r->outcome.completed) return 0.0;
  return nodal(*r->capture.of_step(step).back(), "U", single(*r, set), c);
}

// Cantilever strip, ν = 0 (a Timoshenko beam: nothing varies across the width), L = 10, b = 1,
// t = 0.1, E = 2e5, G = 1e5, tip line load P = 1: δ = PL³/(3EI) + PL/(κGA) with κ = 5/6 for the
// quadratic S8R (nodally exact, as B32), minus PLh²/(12EI) for S4 and S4R, whose edge-tied
// shear and constant curvature make each element a one-point linear Timoshenko beam (as B31).
// Round-off: 1e-8. S3 converges: within 1 % at 20 × 2 elements; S6 (3 points, untied shear)
// within 1e-3 with 10 × 1 squares cut in two (measured 3.8e-4; 5 × 1: 4.6e-3).
TEST(Shells, CantileverStripMatchesTheTimoshenkoBeam) {
  const double P = 1.0, L = 10.0, E = 2e5, G = 1e5, I = 0.1 * 0.1 * 0.1 / 12, A = 0.1;
  const double exact = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6 * G * A);
  struct Case {
    const char* etype;
    int n;
    double expected, tolerance;
  };
  const double h = L / 10;
  for (const Case& c : {Case{"S4", 10, exact - P * L * h * h / (12 * E * I), 1e-8},
                        Case{"S4R", 10, exact - P * L * h * h / (12 * E * I), 1e-8}, Case{"S8R", 5, exact, 1e-8},
                        Case{"S3", 20, exact, 1e-2}, Case{"S6", 10, exact, 1e-3}}) {
    const auto r = run_deck(shell_deck("strip", c.etype, c.n));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    for (std::int32_t tip : nset(r->model(), "TIP"))
      EXPECT_NEAR(nodal(f, "U", static_cast<std::size_t>(tip), 2), c.expected, c.tolerance * exact) << c.etype;
    report(std::string("strip ") + c.etype + ": tip deflection / Timoshenko",
           nodal(f, "U", static_cast<std::size_t>(nset(r->model(), "TIP")[0]), 2) / exact);
    // The root carries the load: Σ RF3 = −P (1e-8: the thin strip's system, its drilling
    // stiffness 1e-4 of the bending one, loses about eight digits).
    double root = 0.0;
    for (std::int32_t n : nset(r->model(), "ROOT")) root += nodal(f, "RF", static_cast<std::size_t>(n), 2);
    EXPECT_NEAR(root, -P, 1e-8) << c.etype;
  }
}

// The strip twisted by T = 1: away from the ends the twist rate is T/(GJ) with the Mindlin
// plate's torsion constant J = (bt³/3)(1 − 2 tanh(λb/2)/(λb)), λ = √(12κ)/t (uniform twist
// with the free edges' transverse shear boundary layer; it gives 0.3123 bt³ here, Saint-Venant's
// 0.3123 bt³ for b/t = 10). Measured on the axis between x = 3 and 7; within 1 % at 40 × 20.
TEST(Shells, StripTorsionMatchesTheMindlinPlateTorsionConstant) {
  const double b = 1.0, t = 0.1, G = 1e5, lambda = std::sqrt(10.0) / t;
  const double J = b * t * t * t / 3 * (1 - 2 * std::tanh(lambda * b / 2) / (lambda * b));
  for (const char* etype : {"S4", "S8R"}) {
    const auto r = run_deck(shell_deck("torsion", etype, etype == std::string("S8R") ? 20 : 40));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    double at3 = 0, at7 = 0;
    for (std::int32_t n : nset(r->model(), "AXIS")) {
      const double x = coords(r->model(), n)[0];
      if (std::abs(x - 3) < 1e-9) at3 = nodal(f, "UR", static_cast<std::size_t>(n), 0);
      if (std::abs(x - 7) < 1e-9) at7 = nodal(f, "UR", static_cast<std::size_t>(n), 0);
    }
    const double rate = (at7 - at3) / 4, expected = 1.0 / (G * J);
    report(std::string("strip torsion ") + etype + ": twist rate / (T/GJ)", rate / expected);
    EXPECT_NEAR(rate, expected, 1e-2 * expected) << etype;
  }
}

// NLGEOM: Sze, Liu and Lo's strip (2004) rolled up by an end moment M = 2π EI/L (48 elements, one
// across; U2, UR1, UR3 held, a planar problem). Each corotated element carries pure bending, so
// the nodes lie on the regular polygon of chords L/48 that closes after a full turn: the tip
// is back at the root turned by 2π, every node on one circle of radius r = h/(2 sin(α/2)),
// α = 2π/48, which exceeds the exact circle's L/(2π) by α²/24 = 7.1e-4. The root holds M.
// Measured (Newton's tolerance sets the last digits): the tip off the root by 4e-11 L (S4) and
// 2e-13 L (S3), the nodes off their circle by 9e-11 r and 5e-13 r.
TEST(Shells, AnEndMomentRollsTheStripIntoACircle) {
  const double L = 12.0, moment = 50 * M_PI / 3, alpha = 2 * M_PI / 48;
  const double polygon = (L / 48) / (2 * std::sin(alpha / 2));
  for (const char* etype : {"S4", "S3"}) {
    const auto r = run_deck(shell_deck("rollup", etype, 48));
    ASSERT_TRUE(r->outcome.completed) << etype << ": " << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    double off_polygon = 0.0, tip_gap = 0.0;
    for (std::int32_t n : nset(r->model(), "ALL")) {
      const auto row = static_cast<std::size_t>(n);
      const double x = coords(r->model(), n)[0] + nodal(f, "U", row, 0), z = nodal(f, "U", row, 2);
      off_polygon = std::max(off_polygon, std::abs(std::hypot(x, z - polygon) - polygon));
    }
    for (std::int32_t n : nset(r->model(), "TIP")) {
      const auto row = static_cast<std::size_t>(n);
      tip_gap = std::max({tip_gap, std::abs(nodal(f, "U", row, 0) + L), std::abs(nodal(f, "U", row, 2))});
      EXPECT_NEAR(nodal(f, "UR", row, 1), -2 * M_PI, 1e-4) << etype;
    }
    EXPECT_LT(tip_gap, 1e-4 * L) << etype;
    EXPECT_LT(off_polygon, 1e-4 * polygon) << etype;
    EXPECT_LT(polygon / (L / (2 * M_PI)) - 1, 1e-3);
    double root = 0.0;
    for (std::int32_t n : nset(r->model(), "ROOT")) root += nodal(f, "RM", static_cast<std::size_t>(n), 1);
    EXPECT_NEAR(root, moment, 1e-4 * moment) << etype;
    report(std::string("shell roll-up ") + etype + ": tip off the root / L", tip_gap / L);
    report(std::string("shell roll-up ") + etype + ": nodes off their circle / r", off_polygon / polygon);
  }
}

// *NODAL THICKNESS is interpolated from the nodes to the points, as Abaqus does: the strip with
// t = 0.1 (1 + x/L) under a tip line load 1 (gen_shells.py tapered) bends by ∫ P(L − x)²/EI(x) +
// ∫ P/(κGA(x)) = 12PL³/(Ebt0³)(3/2 + ln 2 − 2) + PL ln 2/(κGbt0) = 11.58966. S8R (5 elements) to
// 1e-4 (measured 6e-6; ccx 2.20's expansion of the same deck with 10 S8R: 11.5895); S4 converges
// at h² (20 and 40 elements: −4e-4, −9e-5). The element's mean thickness instead would make the
// root elements far stiffer (t³).
TEST(Shells, NodalThicknessIsInterpolatedToThePoints) {
  const double exact = 12 * 1000 / (2e5 * 1e-3) * (1.5 + std::log(2.0) - 2) + 10 / (5.0 / 6 * 1e5 * 0.1) * std::log(2.0);
  const auto tip = [](const std::string& deck) {
    const auto r = run_deck(deck);
    EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
    return r->outcome.completed ? nodal(r->capture.last(), "U", static_cast<std::size_t>(nset(r->model(), "TIP")[0]), 2)
                                : 0.0;
  };
  EXPECT_NEAR(tip(shell_deck("tapered", "S8R", 5)), exact, 1e-4 * exact);
  const double coarse = tip(shell_deck("tapered", "S4", 20)) - exact, fine = tip(shell_deck("tapered", "S4", 40)) - exact;
  EXPECT_LT(std::abs(fine), 2e-4 * exact);
  EXPECT_NEAR(coarse / fine, 4.0, 1.0);
  report("tapered strip S4 40: tip / closed form - 1", fine / exact);
}

// The sign of a shell pressure. Abaqus: for an element-based P on conventional shells "the force
// vector points along the element SPOS normal", while a pressure on a surface (*DSLOAD on SPOS)
// pushes against that surface's normal; CalculiX does the same. The S8R strip (normal +z) under
// a uniform pressure q = 1 per unit area (q b = 1 per length): δ = qbL⁴/(8EI) + qbL²/(2κGA),
// up with P and down with the SPOS surface's pressure, to 1e-6.
TEST(Shells, APressureActsAlongTheNormalAndASurfacePressureAgainstIt) {
  const double L = 10.0, E = 2e5, G = 1e5, I = 0.1 * 0.1 * 0.1 / 12, A = 0.1;
  const double exact = L * L * L * L / (8 * E * I) + L * L / (2 * 5.0 / 6 * G * A);
  const auto r = run_deck(shell_deck("pressure", "S8R", 5));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  for (int step : {1, 2}) {
    const solver::Frame& f = *r->capture.of_step(step).back();
    for (std::int32_t tip : nset(r->model(), "TIP"))
      EXPECT_NEAR(nodal(f, "U", static_cast<std::size_t>(tip), 2), step == 1 ? exact : -exact, 1e-6 * exact) << step;
  }
}

// The same roll-up with S8R (quadratic, the tip moment as its consistent 1/6, 2/3, 1/6 edge
// loads): the midside nodes turn against the corner-node frame like any other node. The tip
// comes back to the root turned by 2π. The nodes approach the exact circle r = L/2π at the rate
// h²: the small-strain kernel sees each element's arc from its chord, and that arc's shear
// strain tan φ − φ is third order in the element's half-angle φ (a flat S4 has none). Measured:
// 5.2e-2 r with 8 elements (45° each), 1.3e-2 with 16, 5.7e-3 with 24.
TEST(Shells, AnEndMomentRollsAnS8RStripTowardTheExactCircle) {
  const double L = 12.0, moment = 50 * M_PI / 3, r = L / (2 * M_PI);
  std::vector<double> off;
  for (int n : {8, 16}) {
    const auto run = run_deck(shell_deck("rollup", "S8R", n));
    ASSERT_TRUE(run->outcome.completed) << run->outcome.message;
    const solver::Frame& f = run->capture.last();
    double off_circle = 0.0, tip_gap = 0.0;
    for (std::int32_t node : nset(run->model(), "ALL")) {
      const auto row = static_cast<std::size_t>(node);
      const double x = coords(run->model(), node)[0] + nodal(f, "U", row, 0), z = nodal(f, "U", row, 2);
      off_circle = std::max(off_circle, std::abs(std::hypot(x, z - r) - r));
    }
    for (std::int32_t node : nset(run->model(), "TIP")) {
      const auto row = static_cast<std::size_t>(node);
      tip_gap = std::max({tip_gap, std::abs(nodal(f, "U", row, 0) + L), std::abs(nodal(f, "U", row, 2))});
      EXPECT_NEAR(nodal(f, "UR", row, 1), -2 * M_PI, 1e-4) << n;
    }
    EXPECT_LT(tip_gap, 1e-4 * L) << n;
    double root = 0.0;
    for (std::int32_t node : nset(run->model(), "ROOT")) root += nodal(f, "RM", static_cast<std::size_t>(node), 1);
    EXPECT_NEAR(root, moment, 1e-4 * moment) << n;
    off.push_back(off_circle / r);
    report("shell roll-up S8R " + std::to_string(n) + ": nodes off the exact circle / r", off_circle / r);
  }
  EXPECT_LT(off[1], 1.5e-2);
  EXPECT_NEAR(off[0] / off[1], 4.0, 0.5);  // h²
}

/// Σ RM2 over node set `set` in frame f.
double moment_about_y(const Run& r, const solver::Frame& f, const std::string& set) {
  double sum = 0.0;
  for (std::int32_t n : nset(r.model(), set)) sum += nodal(f, "RM", static_cast<std::size_t>(n), 1);
  return sum;
}

// A strip of elastic-perfectly plastic metal (E = 2e5, ν = 0, yield 200; L = 10, b = 1,
// t = 0.1, five Simpson points) bent by its tip's rotation about y, small strain
// (gen_shells.py plastic). Elastic at first: the surfaces' S11 = E κ t/2 and the root moment
// EI κ with κ = θ/L, to 1e-9. Then turned to 1 rad (κ five times the first yield's): every
// point but the midsurface's at yield (Mises 200 at the surfaces, to 1e-6), and Simpson's rule
// makes the moment exactly the fully plastic one, σ_y b t²/4 = 0.5 (measured 0.4998: the last
// increment's midsurface and quarter points; held to 1e-3). Between the two the lamina's width
// strain meets the plastic flow's ε22 = −ε11/2 through the thickness, so S22 is not zero there:
// shell kinematics, not a beam's.
TEST(Shells, APlasticStripBentByItsTipReachesTheFullyPlasticMoment) {
  const auto r = run_deck(shell_deck("plastic", "S4", 10));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& first = *r->capture.of_step(1).front();
  const double kappa = 0.03 / 10.0;  // the first increment: 0.1 of the step's 0.3 rad
  const auto* s = field(first, "S");
  ASSERT_TRUE(s);
  const std::size_t n = s->component_labels.size();
  for (std::size_t i = 0; i < s->elements.size(); ++i)
    EXPECT_NEAR(std::abs(s->values[n * i]), 2e5 * kappa * 0.05, 1e-9 * 30.0) << "point " << i;
  EXPECT_NEAR(moment_about_y(*r, first, "ROOT"), 2e5 * (0.1 * 0.1 * 0.1 / 12) * kappa, 1e-9);
  const solver::Frame& last = r->capture.last();
  EXPECT_NEAR(moment_about_y(*r, last, "ROOT"), 200.0 * 0.1 * 0.1 / 4, 1e-3 * 0.5);
  const auto* plastic = field(last, "S");
  const auto* peeq = field(last, "PEEQ");
  ASSERT_TRUE(plastic && peeq);
  for (std::size_t i = 0; i < plastic->elements.size(); ++i) {
    const double s11 = plastic->values[n * i], s22 = plastic->values[n * i + 1], s12 = plastic->values[n * i + 3];
    EXPECT_NEAR(std::sqrt(s11 * s11 - s11 * s22 + s22 * s22 + 3 * s12 * s12), 200.0, 1e-6 * 200.0) << "point " << i;
    EXPECT_GT(peeq->values[i], 3e-3) << "point " << i;  // the surface strain 5e-3 less about the yield's 1e-3
  }
  report("plastic strip S4: root moment / fully plastic moment", moment_about_y(*r, last, "ROOT") / 0.5);
}

// The same strip under NLGEOM (gen_shells.py plastic_nlgeom): its tip turned to 1 rad, 2.9° per
// element, the plastic law sees the corotated strains. The root still carries the fully plastic
// moment σ_y b t²/4 = 0.5, to 1e-3 (measured 4e-4). With 10 elements the run stops at 0.72 of
// the second step: sections yielded through all but their elastic core leave the strip's width
// nearly free (the residual diverges across it).
TEST(Shells, APlasticStripBentUnderNlgeomCarriesTheFullyPlasticMoment) {
  const auto r = run_deck(shell_deck("plastic_nlgeom", "S4", 20));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& last = r->capture.last();
  EXPECT_NEAR(moment_about_y(*r, last, "ROOT"), 0.5, 1e-3 * 0.5);
  const auto* peeq = field(last, "PEEQ");
  ASSERT_TRUE(peeq);
  EXPECT_GT(*std::max_element(peeq->values.begin(), peeq->values.end()), 3e-3);
  report("plastic strip S4 NLGEOM: root moment / fully plastic moment", moment_about_y(*r, last, "ROOT") / 0.5);
}

// A clamped plate of a hardening metal under a pressure of 5, NLGEOM (gen_shells.py
// plastic_plate): it deflects some 13 thicknesses, stretched and yielded through its thickness.
// The pressure follows the deformed surface, yet its resultant is p times the area its fixed
// edge encloses: the edge's reactions sum to −5 along z and 0 across, to 1e-6. S8R (6 × 6) and
// S4 (12 × 12) agree on the centre's deflection to 2 % (0.1325, 0.1315). CalculiX 2.20 on the S8R
// deck: 0.1420 with 6 × 6, 0.1227 with 12 × 12 (inpact 0.1298): its expanded bricks integrate the
// plastic bending with two points through the thickness, inpact's Simpson rule with five.
TEST(Shells, AClampedPlasticPlateUnderPressureBalancesItsLoad) {
  std::vector<double> centre;
  for (const auto& [etype, n] : {std::pair{"S8R", 6}, std::pair{"S4", 12}}) {
    const auto r = run_deck(shell_deck("plastic_plate", etype, n));
    ASSERT_TRUE(r->outcome.completed) << etype << ": " << r->outcome.message;
    const solver::Frame& f = r->capture.last();
    std::array<double, 3> reaction{};
    for (std::int32_t node : nset(r->model(), "EDGE"))
      for (int c = 0; c < 3; ++c) reaction[c] += nodal(f, "RF", static_cast<std::size_t>(node), c);
    EXPECT_NEAR(reaction[2], -5.0, 1e-6 * 5) << etype;
    EXPECT_NEAR(reaction[0], 0.0, 1e-6 * 5) << etype;
    EXPECT_NEAR(reaction[1], 0.0, 1e-6 * 5) << etype;
    const auto* peeq = field(f, "PEEQ");
    ASSERT_TRUE(peeq);
    EXPECT_GT(*std::max_element(peeq->values.begin(), peeq->values.end()), 0.05) << etype;
    centre.push_back(nodal(f, "U", single(*r, "CENTER"), 2));
    report(std::string("plastic plate ") + etype + ": centre deflection / thickness", centre.back() / 0.01);
  }
  EXPECT_GT(centre[0], 0.1);
  EXPECT_NEAR(centre[1], centre[0], 0.02 * centre[0]);
}

struct Benchmark {
  const char* name;
  const char* point;  ///< the node set of the measured node
  int component;      ///< 0-based
  double reference;
  const char* etype;
  std::vector<int> meshes;  ///< coarse to fine
  double tolerance;         ///< on the finest mesh, relative to the reference
};

void run_benchmark(const Benchmark& b, bool thin = false, int step = 1) {
  double last = 0.0;
  for (int n : b.meshes) {
    last = displacement(shell_deck(b.name, b.etype, n, thin), b.point, b.component, step);
    report(fmt::format("{}{} {} {}: U{} / reference", b.name, thin ? " thin" : "", b.etype, n, b.component + 1),
           last / b.reference);
  }
  EXPECT_NEAR(last, b.reference, b.tolerance * std::abs(b.reference)) << b.name << " " << b.etype;
}

// Scordelis–Lo roof: vertical displacement at the middle of the free edge −0.3024.
TEST(Shells, ScordelisLoRoof) {
  run_benchmark({"scordelis_lo", "POINT", 2, -0.3024, "S4", {4, 8, 16}, 0.02});
  run_benchmark({"scordelis_lo", "POINT", 2, -0.3024, "S8R", {4, 8}, 0.02});
  run_benchmark({"scordelis_lo", "POINT", 2, -0.3024, "S3", {16, 32}, 0.03});
  run_benchmark({"scordelis_lo", "POINT", 2, -0.3024, "S6", {8, 16}, 0.02});
}

// Pinched cylinder with end diaphragms: displacement under the load −1.8248e-5.
TEST(Shells, PinchedCylinder) {
  run_benchmark({"pinched", "POINT", 2, -1.8248e-5, "S4", {8, 16, 32}, 0.02});
  run_benchmark({"pinched", "POINT", 2, -1.8248e-5, "S8R", {8, 16}, 0.02});
}

// Pinched hemisphere with an 18° hole: radial displacement under the loads 0.094.
TEST(Shells, PinchedHemisphere) {
  run_benchmark({"hemisphere", "LOADX", 0, 0.094, "S4", {8, 16}, 0.02});
  run_benchmark({"hemisphere", "LOADX", 0, 0.094, "S8R", {8, 16}, 0.02});
}

// Twisted beam, thick (t = 0.32, P = 1) and thin (t = 0.0032, P = 1e-6): tip displacement along
// the load, in plane (step 1) and out of plane (step 2).
TEST(Shells, TwistedBeam) {
  run_benchmark({"twisted", "CENTRE", 2, 5.424e-3, "S4", {2, 4}, 0.02});
  run_benchmark({"twisted", "CENTRE", 1, 1.754e-3, "S4", {2, 4, 8}, 0.02}, false, 2);
  run_benchmark({"twisted", "CENTRE", 2, 5.256e-3, "S4", {2, 4}, 0.02}, true);
  run_benchmark({"twisted", "CENTRE", 1, 1.294e-3, "S4", {2, 4}, 0.02}, true, 2);
}

}  // namespace
}  // namespace inpact::verification

namespace inpact::verification {
namespace {

// A plate of S4 shells pressed by P = 1 onto a C3D8 block (decks/verification/
// shell_on_block_s4.inp), contact at the shells' reference surface (NO THICKNESS): the block's
// bottom carries the 4 of the load (1e-9) and every slave node's CPRESS is the pressure within
// 1 % (the block's top sags a little under the plate: measured 0.35 % at worst).
TEST(Shells, APlatePressedOnABlockPassesItsPressureThroughContact) {
  const auto r = run_deck(deck_path("shell_on_block_s4.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  double bottom = 0.0;
  for (std::int32_t n : nset(r->model(), "BOTTOM")) bottom += nodal(f, "RF", static_cast<std::size_t>(n), 2);
  EXPECT_NEAR(bottom, 4.0, 1e-9 * 4.0);
  const auto* cpress = field(f, "CPRESS");
  ASSERT_NE(cpress, nullptr);
  ASSERT_EQ(cpress->values.size(), 25u);
  double worst = 0.0;
  for (double p : cpress->values) worst = std::max(worst, std::abs(p - 1.0));
  EXPECT_LT(worst, 1e-2);
  report("shell on block: worst |CPRESS - P| / P", worst);
}

/// The block's bottom carries the 4 (1e-9); every slave node's CPRESS is the pressure within
/// `pressure_tol` and its COPEN within `gap_tol` of zero.
void expect_plate_on_block(const Run& r, const std::string& what, double pressure_tol, double gap_tol) {
  const solver::Frame& f = r.capture.last();
  double bottom = 0.0;
  for (std::int32_t n : nset(r.model(), "BOTTOM")) bottom += nodal(f, "RF", static_cast<std::size_t>(n), 2);
  EXPECT_NEAR(bottom, 4.0, 1e-9 * 4.0) << what;
  const auto* cpress = field(f, "CPRESS");
  const auto* copen = field(f, "COPEN");
  ASSERT_TRUE(cpress && copen) << what;
  ASSERT_EQ(cpress->values.size(), 25u);
  double worst_p = 0.0, worst_gap = 0.0;
  for (double p : cpress->values) worst_p = std::max(worst_p, std::abs(p - 1.0));
  for (double g : copen->values) worst_gap = std::max(worst_gap, std::abs(g));
  EXPECT_LT(worst_p, pressure_tol) << what;
  EXPECT_LT(worst_gap, gap_tol) << what;
  report(what + ": worst |CPRESS - P| / P", worst_p);
  report(what + ": worst |COPEN|", worst_gap);
}

// Without NO THICKNESS the contact is on the shell's face, as Abaqus has it: the plate of the
// deck above with its midsurface half a thickness above the block (shell_on_block_offset_s4.inp),
// and with OFFSET=SPOS its nodes a whole thickness above (shell_on_block_spos_s4.inp). The
// underside touches the block: the block carries the load, CPRESS is the pressure and COPEN is
// zero (node to surface, direct) or p/k (surface to surface, penalty), so the plate sits t/2
// (t) above the block's top. Measured, node to surface: CPRESS within 0.35 % / 0.90 %, COPEN
// ≤ 3e-16; surface to surface: 0.79 % / 2.0 % (the mortar rows at the plate's edges), COPEN
// 3.8e-8 (p/k).
TEST(Shells, APlateTouchesTheBlockWithItsFaceNotItsNodes) {
  for (const std::string deck : {"shell_on_block_offset_s4.inp", "shell_on_block_spos_s4.inp"}) {
    const auto nts = run_deck(deck_path(deck));
    ASSERT_TRUE(nts->outcome.completed) << deck << ": " << nts->outcome.message;
    expect_plate_on_block(*nts, deck + ", node to surface", 1e-2, 1e-12);
    const auto path = edited_deck(deck, "shell-s2s", [](const std::string& line) {
      if (line.starts_with("*CONTACT PAIR")) return std::vector<std::string>{line + ", TYPE=SURFACE TO SURFACE"};
      return std::vector<std::string>{line};
    });
    const auto s2s = run_deck(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(s2s->outcome.completed) << deck << ": " << s2s->outcome.message;
    expect_plate_on_block(*s2s, deck + ", surface to surface", 3e-2, 1e-6);
  }
}

// Two shell plates stacked, the upper one's SNEG face on the lower one's SPOS face
// (shells_stacked_s4.inp): both surfaces are offset. The lower plate is held along z, so the
// contact passes the pressure unchanged: CPRESS = 1 and the lower plate's reactions carry 4, and
// the upper plate does not move. Measured: CPRESS 1 to 7e-16, U3 of the upper plate 0.
TEST(Shells, StackedShellsTouchOnTheirFaces) {
  const auto r = run_deck(deck_path("shells_stacked_s4.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  double lower = 0.0, worst_u = 0.0, worst_p = 0.0;
  for (std::int32_t n : nset(r->model(), "LOWER_NODES")) lower += nodal(f, "RF", static_cast<std::size_t>(n), 2);
  for (std::int32_t n : nset(r->model(), "UPPER_NODES"))
    worst_u = std::max(worst_u, std::abs(nodal(f, "U", static_cast<std::size_t>(n), 2)));
  const auto* cpress = field(f, "CPRESS");
  ASSERT_NE(cpress, nullptr);
  for (double p : cpress->values) worst_p = std::max(worst_p, std::abs(p - 1.0));
  EXPECT_NEAR(lower, 4.0, 1e-9 * 4.0);
  EXPECT_LT(worst_p, 1e-9);
  EXPECT_LT(worst_u, 1e-12);
  report("stacked shells: worst |CPRESS - P| / P", worst_p);
  report("stacked shells: worst |U3| of the upper plate", worst_u);
}

// A shell master whose faces lie at different distances from their nodes (two thicknesses) is a
// deck error at the pair's line, found before the analysis starts (`inpact check` too).
TEST(Shells, AShellMasterOfTwoThicknessesIsRefusedAtThePairsLine) {
  const auto path = edited_deck("shells_stacked_s4.inp", "shell-master-two-t", [](const std::string& line) {
    if (line == "*SHELL SECTION, ELSET=LOWER, MATERIAL=STEEL")
      return std::vector<std::string>{"*ELSET, ELSET=L1", "1, 2", "*ELSET, ELSET=L2, GENERATE", "3, 16, 1",
                                      "*SHELL SECTION, ELSET=L1, MATERIAL=STEEL", "0.2",
                                      "*SHELL SECTION, ELSET=L2, MATERIAL=STEEL"};
    return std::vector<std::string>{line};
  });
  const std::string message = stop_message(path);
  EXPECT_NE(message.find(".inp:114:1: error: *CONTACT PAIR: the master surface LOWER_TOP lies on shells whose faces "
                         "are at different distances from their nodes (0.1 and 0.05"),
            std::string::npos)
      << message;
}

// General contact's ALL EXTERIOR, and an inclusion's empty field (the exterior), are made of the
// solids' faces; with shells in the model they would leave their contact out without a word, so
// each is a deck error at the inclusion's line.
TEST(Shells, GeneralContactOnTheExteriorInAModelWithShellsIsRefused) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"*CONTACT INCLUSIONS, ALL EXTERIOR"}, "ALL EXTERIOR would leave out the 16 shell elements that no *CONTACT"},
      {{"*CONTACT INCLUSIONS", ", TOP"}, "the exterior surface (an empty field) would leave out the 16 shell"}};
  for (const auto& [inclusion, expected] : cases) {
    const auto path = edited_deck("shell_on_block_spos_s4.inp", "shell-exterior", [&](const std::string& line) {
      if (line.starts_with("*CONTACT PAIR")) {
        std::vector<std::string> out{"*CONTACT"};
        out.insert(out.end(), inclusion.begin(), inclusion.end());
        out.insert(out.end(), {"*CONTACT PROPERTY ASSIGNMENT", ", , HARD"});
        return out;
      }
      if (line == "UNDERSIDE, TOP") return std::vector<std::string>{};
      return std::vector<std::string>{line};
    });
    const std::string message = stop_message(path);
    EXPECT_NE(message.find(": error: *CONTACT INCLUSIONS: " + expected), std::string::npos) << message;
  }
}

// With a *CONTACT PAIR on the shells' faces, general contact may take the solids: the plate on the
// block runs as with the pair alone, and a note says the shells are left to the pair.
TEST(Shells, AllExteriorBesideAPairOnTheShellsRuns) {
  const auto path = edited_deck("shell_on_block_spos_s4.inp", "shell-pair-and-general", [](const std::string& line) {
    if (line == "UNDERSIDE, TOP")
      return std::vector<std::string>{line, "*CONTACT", "*CONTACT INCLUSIONS, ALL EXTERIOR"};
    return std::vector<std::string>{line};
  });
  const auto r = run_deck(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  expect_plate_on_block(*r, "pair beside ALL EXTERIOR", 1e-2, 1e-12);
  EXPECT_TRUE(std::any_of(r->capture.messages.begin(), r->capture.messages.end(), [](const std::string& m) {
    return m.find("general contact: the 16 shell elements are not in ALL EXTERIOR") != std::string::npos;
  }));
}

}  // namespace
}  // namespace inpact::verification
