// The pin-in-hole of [AX] 38.1.3 (Figure 38.1.31, issue 5): decks/pin_in_hole.inp, a C3D8 pin with
// a hemispherical tip pushed 3.25 mm into a hub through a conical lead-in, radial interference
// δ = 0.025 mm, general contact (balanced penalty, surface to surface) with μ = 0.1, smoothing by
// *SURFACE PROPERTY ASSIGNMENT (SPHERICAL tip, CIRCUMFERENTIAL body and hole). The deck's axis is
// X, so CSHEAR1 and CSLIP1 are axial. Every figure is printed as "[contact-verification] ...";
// the tolerances are at the assertions. bench/smoothing_trade/ runs the finer meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

// The deck's data (decks/gen_pin_in_hole.py).
constexpr double kHoleRadius = 5.0, kInterference = 0.025, kHubRadius = 10.0;
constexpr double kChamferDepth = 1.5, kChamferSlope = 0.08;
constexpr double kEquatorEnd = -4.0;  // the tip's equator at the end: Z0 − push = −0.75 − 3.25
constexpr double kMu = 0.1;
// N of the smoothed level 3 mesh (8/11 facets per quarter, 0.5 mm along the axis; 14 s CPU,
// bench/smoothing_trade/); level 2 gives 15483 N, level 1 (the deck) 15698 N.
constexpr double kNormalLevel3 = 15790.4;

/// Open-ended (plane stress) Lamé pressure of a solid shaft in a hub of the same material.
double lame_pressure_open() {
  const double b = kHoleRadius, c = kHubRadius;
  return kE * kInterference * (c * c - b * b) / (2.0 * b * c * c);
}

/// The engaged length, weighted by the local interference over δ: the cylinder from the chamfer's
/// foot down to the equator, the last δ/slope of the chamfer (interference falling linearly to 0),
/// and the band of the tip sphere still larger than the hole (∫ (√(R² − s²) − b) ds / δ).
double engaged_length() {
  const double R = kHoleRadius + kInterference, b = kHoleRadius;
  const double cylinder = -kChamferDepth - kEquatorEnd;
  const double chamfer = 0.5 * kInterference / kChamferSlope;
  const double s_max = std::sqrt(R * R - b * b);
  double band = 0.0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double s = (i + 0.5) * s_max / n;
    band += (std::sqrt(R * R - s * s) - b) * s_max / n;
  }
  return cylinder + chamfer + band / kInterference;
}

std::string pin_deck() { return std::string(INPACT_SOURCE_DIR) + "/decks/pin_in_hole.inp"; }

/// The same deck without smoothing, generated into the temporary folder.
std::string faceted_deck() {
  const auto dir = std::filesystem::temp_directory_path() / ("inpact-pin-in-hole-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string cmd = "python3 " + std::string(INPACT_SOURCE_DIR) + "/decks/gen_pin_in_hole.py --faceted --out " +
                          dir.string();
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return (dir / "pin_in_hole_faceted.inp").string();
}

/// One ring of slave nodes: one pass (pair row) at one axial position.
struct Ring {
  int pair = 0;
  double x = 0.0;  ///< reference axial coordinate
  double mean = 0.0, min = 1e300, max = 0.0;
  int nodes = 0, closed = 0;
};

struct PinFigures {
  double push = 0.0;     ///< −Σ RF1 over PIN_TOP: the force pushing the pin in (this quarter)
  double balance = 0.0;  ///< |Σ RF1 (PIN_TOP) + Σ RF1 (HUB_END)| / push
  double normal = 0.0;   ///< N = Σ CPRESS·CNAREA over both passes (each carries half the area)
  double shear = 0.0;    ///< Σ |CSHEAR1|·CNAREA over both passes
  double coulomb = 0.0;  ///< largest | |CSHEAR1| / (μ CPRESS) − 1 | over the closed nodes
  int closed = 0, slipping = 0, wrong_sign = 0;
  std::vector<Ring> rings;
};

PinFigures pin_figures(const Run& r, double mu) {
  PinFigures p;
  const auto& m = r.deck.model;
  const solver::Frame& f = r.capture.last();
  double top = 0.0, end = 0.0;
  for (auto row : verification::nset(m, "PIN_TOP")) top += verification::nodal(f, "RF", row, 0);
  for (auto row : verification::nset(m, "HUB_END")) end += verification::nodal(f, "RF", row, 0);
  p.push = -top;
  p.balance = std::abs(top + end) / std::max(std::abs(top), 1e-30);
  const auto* cp = verification::field(f, "CPRESS");
  const auto* ca = verification::field(f, "CNAREA");
  const auto* cs = verification::field(f, "CSHEAR1");
  const auto* st = verification::field(f, "CSTATUS");
  if (!cp || !ca || !cs || !st) {
    ADD_FAILURE() << "the frame lacks CPRESS, CNAREA, CSHEAR1 or CSTATUS";
    return p;
  }
  std::map<std::pair<int, long long>, Ring> rings;
  for (std::size_t i = 0; i < cp->values.size(); ++i) {
    const double pr = cp->values[i], a = ca->values[i], tau = cs->values[i];
    const auto x = verification::coords(m, static_cast<std::int32_t>(cp->nodes[i]));
    Ring& ring = rings[{cp->pair[i], std::llround(x[0] * 1e6)}];
    ring.pair = cp->pair[i];
    ring.x = x[0];
    ++ring.nodes;
    ring.mean += pr;
    ring.min = std::min(ring.min, pr);
    ring.max = std::max(ring.max, pr);
    if (pr <= 0.0) continue;
    ++ring.closed;
    ++p.closed;
    p.normal += pr * a;
    p.shear += std::abs(tau) * a;
    if (st->values[i] == 2.0) ++p.slipping;  // CSTATUS: 0 open, 1 sticking, 2 slipping
    p.coulomb = std::max(p.coulomb, std::abs(std::abs(tau) / (mu * pr) - 1.0));
    // The friction opposes the pin's motion (−X): +X on the pin (the slave of PIN/HOLE, row 0),
    // −X on the hub (the slave of HOLE/PIN, row 1).
    if ((cp->pair[i] == 0) != (tau > 0.0)) ++p.wrong_sign;
  }
  for (auto& [key, ring] : rings) {
    ring.mean /= ring.nodes;
    p.rings.push_back(ring);
  }
  return p;
}

/// Runs `path`, timing its CPU.
std::unique_ptr<Run> timed_run(const std::string& path, const std::map<std::string, std::string>& params,
                               double& cpu_seconds) {
  const std::clock_t c0 = std::clock();
  auto r = run(path, params);
  cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

// The committed deck (level 1: 4 facets per quarter on the pin, 6 on the hole, 1 mm along the
// axis). Measured: push force 1627 N on this quarter, N = 15698 N, push / (μ N) = 1.036, every
// closed node slipping with |CSHEAR1| = μ CPRESS (to 1.6e-5); N / N_Lamé = 1.70, N 0.6 % below the
// level 3 mesh's; ring spreads 0.9 … 4.5 % of the ring mean; 4 increments, 17 iterations,
// 2.8-3.1 s CPU (load average 1.1-1.4 on 2 shared cores).
// The nodal pressures themselves are 2.3 … 5 p_Lamé on this mesh: each pass has two closed rings
// over the 3 mm fit (the rings at its ends open under the averaged gap) and the fit's ends carry
// the edge peaks of a short press fit; bench/smoothing_trade/ shows the finer meshes.
TEST(PinInHole, PushForceIsTheSlidingFrictionOfTheFit) {
  double cpu = 0.0;
  auto r = timed_run(pin_deck(), {}, cpu);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const PinFigures p = pin_figures(*r, kMu);
  const double p_lame = lame_pressure_open();
  const double area = 0.5 * std::numbers::pi * kHoleRadius * engaged_length();  // a quarter
  const double n_lame = p_lame * area;
  report("pin_in_hole: push force (quarter)", p.push);
  report("pin_in_hole: N = sum CPRESS CNAREA", p.normal);
  report("pin_in_hole: push / (mu N)", p.push / (kMu * p.normal));
  report("pin_in_hole: sum |CSHEAR1| CNAREA / (mu N)", p.shear / (kMu * p.normal));
  report("pin_in_hole: max | |CSHEAR1|/(mu CPRESS) - 1 |", p.coulomb);
  report("pin_in_hole: open-ended Lame pressure", p_lame);
  report("pin_in_hole: engaged length (interference-weighted)", engaged_length());
  report("pin_in_hole: N / (Lame pressure x engaged area)", p.normal / n_lame);
  report("pin_in_hole: reaction balance", p.balance);
  report("pin_in_hole: increments", static_cast<double>(r->capture.frames.size()));
  report("pin_in_hole: Newton iterations", r->iterations);
  report("pin_in_hole: CPU seconds", cpu);

  // The push goes through the contact into the hub's held end: equilibrium to round-off.
  EXPECT_LE(p.balance, 1e-8);
  // Coulomb at every closed node: all slip at the end (each slid at least 0.8 mm, the last
  // increment, against an elastic slip of 0.005 l_char) and carry μ p along the axis, in the
  // direction that opposes the motion on each body.
  EXPECT_GT(p.closed, 0);
  EXPECT_EQ(p.slipping, p.closed);
  // (|CSHEAR1| falls short of μ p by the hoop part of the slip, CSHEAR2: measured 1.6e-5)
  EXPECT_LE(p.coulomb, 1e-4);
  EXPECT_EQ(p.wrong_sign, 0);
  EXPECT_NEAR(p.shear, kMu * p.normal, 1e-4 * kMu * p.normal);
  // The push force is the sliding friction μ N plus the axial part of the normal pressure on the
  // chamfer and the tip (below 0.01 N, the frictionless test below): within −2 % … +10 % of μ N
  // (measured +3.6 %).
  // A ring of nodes that closes during the last increment would stick and lower it (the anchor
  // of elastic slip is where a node first touches): with dt = 0.34 instead of 0.25 the last
  // frame gives 0.57, so this holds for the deck's incrementation, not for any.
  EXPECT_GE(p.push, 0.98 * kMu * p.normal);
  EXPECT_LE(p.push, 1.10 * kMu * p.normal);
  // Lamé, open-ended, over the engaged length is a lower bound of N: the unloaded parts of the pin
  // and the hub around the short fit (L/b ≈ 0.6) only stiffen it. 5 % below it for the penalty's
  // penetration (≈ 4 % of δ at the end rings) and the discretisation.
  EXPECT_GE(p.normal, 0.95 * n_lame);
  // Against the finest mesh: level 2 is 1.9 % below level 3, so 3 % (measured −0.59 %).
  report("pin_in_hole: N / N of the smoothed level 3 mesh - 1", p.normal / kNormalLevel3 - 1.0);
  EXPECT_NEAR(p.normal, kNormalLevel3, 0.03 * kNormalLevel3);

  // Smoothing: around each ring of slave nodes (one pass, one axial position) the pressure is
  // uniform, as the axisymmetric solution is. Every ring with a closed node varies by at most 4 %
  // of the largest ring mean (measured ≤ 2.1 %); the rings carrying at least a quarter of it by at
  // most 6 % of their own mean (measured ≤ 4.5 %). A ring at an end of the engagement, where the
  // averaged gap only just closes, has a small mean and a larger relative spread (measured 25 % of
  // 0.27 p_Lamé): the second bound leaves it out.
  double top = 0.0;
  for (const Ring& ring : p.rings) top = std::max(top, ring.mean);
  int loaded = 0;
  for (const Ring& ring : p.rings) {
    if (ring.closed == 0) continue;
    const double spread = (ring.max - ring.min) / ring.mean;
    const std::string label = "pin_in_hole: ring " + std::string(ring.pair == 0 ? "PIN" : "HOLE") + " X0 = " +
                              std::to_string(ring.x);
    report(label + ": mean CPRESS / Lame", ring.mean / p_lame);
    report(label + ": (max - min) / mean", spread);
    report(label + ": (max - min) / largest ring mean", (ring.max - ring.min) / top);
    EXPECT_LE(ring.max - ring.min, 0.04 * top) << label;
    if (ring.mean < 0.25 * top) continue;
    ++loaded;
    EXPECT_EQ(ring.closed, ring.nodes) << label;
    EXPECT_LE(spread, 0.06) << label;
  }
  EXPECT_GE(loaded, 3);
}

// Without smoothing the same mesh loses the fit: the pin's chords (sag 0.096 mm) lie on average
// 0.010 mm inside the hole's (sag 0.043 mm) although the pin is 0.025 mm larger, and surface to
// surface contact averages the gap over the facets, so the pin slides in freely. Measured: N = 0,
// push force 0 (1.3 s CPU).
TEST(PinInHole, WithoutSmoothingTheCoarseMeshLosesTheFit) {
  double cpu = 0.0;
  auto faceted = timed_run(faceted_deck(), {}, cpu);
  ASSERT_TRUE(faceted->outcome.completed) << faceted->outcome.message;
  const PinFigures f = pin_figures(*faceted, kMu);
  const double n_lame = lame_pressure_open() * 0.5 * std::numbers::pi * kHoleRadius * engaged_length();
  report("pin_in_hole faceted: push force", f.push);
  report("pin_in_hole faceted: N / (Lame pressure x engaged area)", f.normal / n_lame);
  report("pin_in_hole faceted: CPU seconds", cpu);
  EXPECT_LE(f.normal, 0.01 * n_lame);
  EXPECT_LE(std::abs(f.push), 0.01 * kMu * n_lame);
}

// Without friction the push is only the axial part of the normal pressure on the chamfer and the
// tip's band, and the fit is the same. Measured: push 54.1 N = 0.0035 N (3.3 % of the frictional
// push, which is μ N + 0.0036 N), N 1.3 % below the frictional run's, 1.68 N_Lamé (2.3 s CPU).
TEST(PinInHole, WithoutFrictionThePushIsTheNormalPressureOnTheSlopes) {
  double cpu = 0.0;
  auto r = timed_run(pin_deck(), {{"mu", "0"}}, cpu);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const PinFigures z = pin_figures(*r, 1.0);
  const double n_lame = lame_pressure_open() * 0.5 * std::numbers::pi * kHoleRadius * engaged_length();
  report("pin_in_hole mu = 0: push force", z.push);
  report("pin_in_hole mu = 0: push / N", z.push / z.normal);
  report("pin_in_hole mu = 0: N / (Lame pressure x engaged area)", z.normal / n_lame);
  report("pin_in_hole mu = 0: CPU seconds", cpu);
  EXPECT_LE(z.balance, 1e-8);
  // The contact normal is radial on the cylinders and tilted by at most 0.1 (the tip's band below
  // the equator; 0.08 on the chamfer): the axial part is ≥ 0 and below 0.1 N everywhere; these
  // bands carry little of N, so below 0.01 N in all (measured 0.0035 N).
  EXPECT_GE(z.push, 0.0);
  EXPECT_LE(z.push, 0.01 * z.normal);
  EXPECT_GE(z.normal, 0.95 * n_lame);
}

}  // namespace
}  // namespace inpact::contact_verification
