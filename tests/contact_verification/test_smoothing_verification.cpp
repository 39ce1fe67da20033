// Smoothing verification (issue 5, "Verification": "the same with a spherical seat (sphere in a
// spherical socket) and a toroidal surface"), on the decks of decks/contact_verification/ through
// run_analysis: surface-to-surface pairs whose master and slave surfaces are both smoothed
// (*SURFACE SMOOTHING named by the pair's GEOMETRIC CORRECTION, [AX] 38.1.3), non-matching
// first-order meshes, the overclosure δ resolved in the first increment.
//   spherical_seat_axi  a ball in a spherical socket, axisymmetric, SPHERICAL: against the
//                       thick-walled sphere (seat_pressure(), contact_verification.hpp)
//   spherical_seat_3d   the same as a 3D octant, C3D8 (the longest test here: 10 s of CPU)
//   oring_axi           an O-ring in a toroidal sleeve, axisymmetric, TOROIDAL: no closed form,
//                       against the same smoothed deck 4× finer
// Each smoothed deck has an unsmoothed twin: its scatter is reported, and asserted to be far
// larger (else the test would show nothing). Every tolerance is stated at its assertion; every
// figure, with the wall time of each run and of each test, is printed as "[contact-verification] ...".
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

using Params = std::map<std::string, std::string>;

const std::vector<std::pair<std::string, Params>> kMethods = {
    {"direct", {{"method", "DIRECT"}}},
    {"penalty", {{"method", "PENALTY"}}},
    {"nonlinear penalty", {{"method", "PENALTY=NONLINEAR"}}},
    {"augmented Lagrange", {{"method", "AUGMENTED LAGRANGE"}}},
};

/// Reports the wall time of a whole test when it ends, and the process's CPU time over it (on a
/// shared machine the wall time says more about the neighbours than about the test).
class TestClock {
 public:
  explicit TestClock(std::string label)
      : label_(std::move(label)), t0_(std::chrono::steady_clock::now()), cpu0_(std::clock()) {}
  ~TestClock() {
    report(label_ + ": test wall time, s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count());
    report(label_ + ": test CPU time, s", static_cast<double>(std::clock() - cpu0_) / CLOCKS_PER_SEC);
  }
  TestClock(const TestClock&) = delete;
  TestClock& operator=(const TestClock&) = delete;

 private:
  std::string label_;
  std::chrono::steady_clock::time_point t0_;
  std::clock_t cpu0_;
};

/// CPRESS of every slave node against a reference pressure at its position.
struct Deviation {
  double min = 1e300, max = -1e300;  ///< CPRESS / p_ref − 1
  double mean = 0.0;                 ///< Σ CPRESS·CNAREA / Σ p_ref·CNAREA − 1
  double max_penetration = 0.0;
  std::size_t n_closed = 0, n = 0;
  double scatter() const { return max - min; }
  double worst() const { return std::max(std::abs(min), std::abs(max)); }
};

template <class Reference>
Deviation deviation(const SlaveValues& s, Reference&& p_ref) {
  Deviation d;
  double force = 0.0, ref_force = 0.0;
  for (std::size_t i = 0; i < s.cpress.size(); ++i) {
    const double ref = p_ref(s.x[i]);
    d.min = std::min(d.min, s.cpress[i] / ref - 1.0);
    d.max = std::max(d.max, s.cpress[i] / ref - 1.0);
    force += s.cpress[i] * s.cnarea[i];
    ref_force += ref * s.cnarea[i];
    if (s.cpress[i] > 0.0) {
      ++d.n_closed;
      d.max_penetration = std::max(d.max_penetration, -s.copen[i]);
    }
  }
  d.n = s.cpress.size();
  d.mean = ref_force > 0.0 ? force / ref_force - 1.0 : 0.0;
  return d;
}

void report_deviation(const std::string& label, const Deviation& d, const Run& r) {
  report(label + ": min CPRESS / reference - 1", d.min);
  report(label + ": max CPRESS / reference - 1", d.max);
  report(label + ": mean CPRESS / reference - 1", d.mean);
  report(label + ": max penetration / delta", d.max_penetration / kSeatDelta);
  report(label + ": run wall time, s", r.seconds);
}

/// Σ RF component c over the node set `set` on the last frame.
double sum_rf(const Run& r, const std::string& set, int c) {
  double s = 0.0;
  for (auto row : verification::nset(r.deck.model, set)) s += verification::nodal(r.capture.last(), "RF", row, c);
  return s;
}

/// Σ CFN component c over the slave nodes on the last frame: the contact force on the slave
/// (CPRESS × CNAREA along the contact normal, the master's, pointing at the slave).
double sum_cfn(const Run& r, int c) {
  const auto* f = verification::field(r.capture.last(), "CFN");
  if (!f) {
    ADD_FAILURE() << "the frame lacks CFN";
    return 0.0;
  }
  const std::size_t n = f->component_labels.size();
  double s = 0.0;
  for (std::size_t i = 0; i * n < f->values.size(); ++i) s += f->values[i * n + static_cast<std::size_t>(c)];
  return s;
}

// --- Spherical seat -----------------------------------------------------------------------------

// Axisymmetric (CAX4, the r–z plane, a half meridian with U2 = 0 on the equator): the ball
// (radius b + δ = 1.01, 24 elements along the arc) in the socket (b = 1 … c = 2, 34 elements:
// non-matching), both smoothed SPHERICAL about the origin; slave the socket. Every slave node
// within 2 % of the thick-walled sphere's p, for every method (plus its penetration h, which
// takes h/δ off the interference). Measured, CPRESS / p − 1 over the 35 slave nodes:
//   direct              −1.33 … +0.38 % (the pole node the lowest, every other one within
//                       ±0.8 %), mean −0.10 %
//   penalty             −1.83 … −0.61 %, penetration 0.81 % of δ
//   nonlinear penalty   −6.2 … −5.1 %, penetration 5.3 % of δ
//   augmented Lagrange  as direct (−1.34 … +0.37 %)
// Unsmoothed, direct: surface to surface −100 … +63 % (the pole node opens), scatter 1.63 p;
// node to surface −39 … +48 %, scatter 0.88 p — against 0.017 p smoothed.
// Equilibrium: the ball's reaction on the equator plane is the axial contact force over the
// hemisphere, p π b_c² with b_c = b + u_socket(b) the deformed contact radius (the contact area
// is the current one; against π b² it reads +1.2 %): measured −0.12 % (direct), −0.93 % (penalty).
TEST(SmoothedSphericalSeat, AxisymmetricEverySlaveNodeWithinTwoPercentOfTheThickSphere) {
  TestClock clock("spherical_seat_axi");
  const double p = seat_pressure();
  const double b_c = kSeatB + seat_socket_displacement(p);
  report("spherical_seat_axi: thick-sphere pressure p", p);
  double smoothed_scatter = 0.0;
  for (const auto& [name, params] : kMethods) {
    auto r = run(deck_path("spherical_seat_axi_smoothed"), params);
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const std::string label = "spherical_seat_axi smoothed, " + name;
    const Deviation d = deviation(slave_values(*r, r->capture.last()), [&](const auto&) { return p; });
    report_deviation(label, d, *r);
    EXPECT_EQ(d.n_closed, d.n) << label;
    const double tol = 0.02 + d.max_penetration / kSeatDelta;  // 2 % plus the method's own error
    EXPECT_LE(d.worst(), tol) << label;
    if (name == "direct") {
      smoothed_scatter = d.scatter();
      EXPECT_LE(d.scatter(), 0.02) << label;  // the scatter itself (measured 1.7 %)
    }
    // Reactions: the two bodies' equator reactions balance (the pair's forces are equal and
    // opposite, to the Newton tolerance), the slave's CFN carries the same axial force (CPRESS
    // and CNAREA are what was applied), and it is p π b_c² (1 %, plus the penetration).
    const double ball = sum_rf(*r, "BALL_EQUATOR", 1), socket = sum_rf(*r, "SOCKET_EQUATOR", 1);
    const double p_equilibrium = ball / (std::numbers::pi * b_c * b_c);
    report(label + ": ball reaction / (p pi b_c^2) - 1", p_equilibrium / p - 1.0);
    EXPECT_NEAR(ball + socket, 0.0, 1e-6 * ball) << label;
    EXPECT_NEAR(sum_cfn(*r, 1), ball, 2e-3 * ball) << label;
    EXPECT_NEAR(p_equilibrium, p, tol * p) << label;
  }
  for (const auto& [name, type] : {std::pair<std::string, std::string>{"surface to surface", "SURFACE TO SURFACE"},
                                   {"node to surface", "NODE TO SURFACE"}}) {
    auto r = run(deck_path("spherical_seat_axi"), {{"method", "DIRECT"}, {"type", type}});
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const std::string label = "spherical_seat_axi unsmoothed, " + name + ", direct";
    const Deviation d = deviation(slave_values(*r, r->capture.last()), [&](const auto&) { return p; });
    report_deviation(label, d, *r);
    report(label + ": scatter (max - min CPRESS) / p", d.scatter());
    // Smoothing is what removes the scatter: without it, at least ten times as large.
    EXPECT_GE(d.scatter(), 10.0 * smoothed_scatter) << label;
  }
}

// The seat as a 3D octant (C3D8, symmetry on the three coordinate planes). Both bodies are
// cube-sphere meshes: the octant's sphere in three patches (12 and 16 elements along a quarter
// great circle: non-matching), the ball with a core cube; 8 layers through the socket. Measured
// (direct, 217 slave nodes): −0.67 … +3.3 %, mean −0.01 %; every node within
// −0.67 … +0.59 % except the one vertex where the three patches meet, (1, 1, 1)/√3, +3.3 %.
// That outlier is the solid mesh's, not the smoothing's: both meshes have a three-element vertex
// there, and under a uniform pressure (no contact) the socket's vertex moves 0.27 % of δ less
// than its pole nodes — stiffer, it draws more pressure. It shrinks with the mesh: at level 2
// (3 min) +1.3 %, every other node −0.81 … −0.22 %, mean −0.50 %. (With 4 layers through the
// socket instead of 8, level 1's mean reads +1.6 %: the socket's own discretisation.)
// Equilibrium: the ball's reaction on y = 0 is p π b_c² / 4 within −0.21 %.
// Unsmoothed, direct: −43 … +62 %. The two runs take 10 s of CPU (15 s wall on a shared machine).
TEST(SmoothedSphericalSeat, Octant3dEveryRegularNodeWithinTwoPercentOfTheThickSphere) {
  TestClock clock("spherical_seat_3d");
  const double p = seat_pressure();
  const double b_c = kSeatB + seat_socket_displacement(p);
  const double vertex = 1.0 / std::sqrt(3.0);
  auto at_vertex = [&](const std::array<double, 3>& x) {
    return std::abs(x[0] - vertex) + std::abs(x[1] - vertex) + std::abs(x[2] - vertex) < 1e-6;
  };
  auto r = run(deck_path("spherical_seat_3d_smoothed"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const std::string label = "spherical_seat_3d smoothed, direct";
  const SlaveValues s = slave_values(*r, r->capture.last());
  const Deviation d = deviation(s, [&](const auto&) { return p; });
  report_deviation(label, d, *r);
  EXPECT_EQ(d.n_closed, d.n) << label;
  EXPECT_NEAR(d.mean, 0.0, 0.01) << label;  // mean within 1 %
  for (std::size_t i = 0; i < s.cpress.size(); ++i) {
    const double e = s.cpress[i] / p - 1.0;
    if (at_vertex(s.x[i])) {
      report(label + ": CPRESS / p - 1 at the patches' common vertex", e);
      EXPECT_LE(std::abs(e), 0.04) << label << ": the three-element vertex, within 4 %";
    } else {
      EXPECT_LE(std::abs(e), 0.02) << label << " at (" << s.x[i][0] << ", " << s.x[i][1] << ", " << s.x[i][2] << ")";
    }
  }
  // The octant's equator plane carries p × a quarter of π b_c².
  const double ball = sum_rf(*r, "BALL_EQUATOR", 1);
  report(label + ": ball reaction / (p pi b_c^2 / 4) - 1", ball / (0.25 * std::numbers::pi * b_c * b_c * p) - 1.0);
  EXPECT_NEAR(ball + sum_rf(*r, "SOCKET_EQUATOR", 1), 0.0, 1e-6 * ball);
  EXPECT_NEAR(sum_cfn(*r, 1), ball, 2e-3 * ball);
  EXPECT_NEAR(ball, 0.25 * std::numbers::pi * b_c * b_c * p, 0.01 * ball);

  auto u = run(deck_path("spherical_seat_3d"));
  ASSERT_TRUE(u->outcome.completed) << u->outcome.message;
  const Deviation du = deviation(slave_values(*u, u->capture.last()), [&](const auto&) { return p; });
  report_deviation("spherical_seat_3d unsmoothed, direct", du, *u);
  EXPECT_GE(du.scatter(), 10.0 * d.scatter());
}

// --- Toroidal surface: an O-ring in a sleeve --------------------------------------------------

/// ψ: the angle of a point of the r–z plane about the tube's centre (R, 0), 0 on the outside,
/// π/2 at the crown, π on the side of the axis.
double tube_angle(const std::array<double, 3>& x) { return std::atan2(x[1], x[0] - kTorusR); }

/// CPRESS along the sleeve as a function of ψ, interpolated linearly between the slave nodes.
class TubeProfile {
 public:
  explicit TubeProfile(const SlaveValues& s) {
    for (std::size_t i = 0; i < s.cpress.size(); ++i) points_.push_back({tube_angle(s.x[i]), s.cpress[i]});
    std::sort(points_.begin(), points_.end());
  }
  double at(double psi) const {
    auto it = std::lower_bound(points_.begin(), points_.end(), std::pair<double, double>{psi, -1e300});
    if (it == points_.begin()) return it->second;
    if (it == points_.end()) return points_.back().second;
    const auto& [a, pa] = *(it - 1);
    const auto& [b, pb] = *it;
    return pa + (pb - pa) * (psi - a) / (b - a);
  }
  const std::vector<std::pair<double, double>>& points() const { return points_; }

 private:
  std::vector<std::pair<double, double>> points_;
};

/// The area-weighted mean CPRESS over n equal windows of ψ ∈ [0, π].
std::vector<double> window_means(const SlaveValues& s, int n) {
  std::vector<double> force(static_cast<std::size_t>(n), 0.0), area(static_cast<std::size_t>(n), 0.0);
  for (std::size_t i = 0; i < s.cpress.size(); ++i) {
    const int w_int = std::clamp(static_cast<int>(tube_angle(s.x[i]) / std::numbers::pi * n), 0, n - 1);
    const auto w = static_cast<std::size_t>(w_int);
    force[w] += s.cpress[i] * s.cnarea[i];
    area[w] += s.cnarea[i];
  }
  for (std::size_t w = 0; w < force.size(); ++w) force[w] /= area[w];
  return force;
}

/// The reference: the smoothed O-ring 4× finer (level 3: 272 elements along the sleeve's half
/// cross-section, 32 through it), direct.
std::unique_ptr<Run> fine_reference() {
  auto r = run(deck_at_level("oring_axi_smoothed", 3));
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
  if (r->outcome.completed) report("oring_axi smoothed, level 3 reference: run wall time, s", r->seconds);
  return r;
}

// The O-ring (axisymmetric, CAX4, half the cross-section with U2 = 0 on y = 0): a solid ring of
// tube radius ρ + δ = 1.01 about the circle R = 4 (48 elements along its half arc) in a sleeve
// ρ = 1 … 2 about the same circle (68 elements: non-matching), both smoothed TOROIDAL about the
// y axis with R; slave the sleeve. The pressure is not uniform — 827 outside (ψ = 0), 800 near
// the crown, 1064 on the axis side (ψ = π), the ring's hoop stiffness growing toward the axis —
// and has no closed form: the reference is the same smoothed deck 4× finer, interpolated in ψ
// (its own convergence and its agreement with the unsmoothed fine mesh: the test below).
// Every slave node within 2 % of it, plus the method's penetration. Measured (CPRESS / reference − 1):
//   direct              −0.32 … +0.84 %
//   penalty             −0.75 … +0.35 %, penetration 0.50 % of δ
//   nonlinear penalty   −4.5 … −3.1 %, penetration 4.7 % of δ
//   augmented Lagrange  +0.08 … +0.35 %, penetration 0.005 % of δ (its default 1000 k_e)
// Unsmoothed, direct: −44 … +34 %.
// Physics: the two bodies' reactions on y = 0 balance, and the ring's is the axial contact force
// Σ CFN2 of the sleeve (measured −1.8e-4 apart).
// 2.7 s of CPU, nearly all of it the level-3 reference (wall time 3.8 s on a busy machine).
TEST(SmoothedToroidalSurface, EverySlaveNodeWithinTwoPercentOfTheFineMesh) {
  TestClock clock("oring_axi");
  const auto fine = fine_reference();
  ASSERT_TRUE(fine->outcome.completed);
  const TubeProfile ref(slave_values(*fine, fine->capture.last()));
  auto p_ref = [&](const std::array<double, 3>& x) { return ref.at(tube_angle(x)); };
  double smoothed_worst = 0.0;
  for (const auto& [name, params] : kMethods) {
    auto r = run(deck_path("oring_axi_smoothed"), params);
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const std::string label = "oring_axi smoothed, " + name;
    const Deviation d = deviation(slave_values(*r, r->capture.last()), p_ref);
    report_deviation(label, d, *r);
    EXPECT_EQ(d.n_closed, d.n) << label;
    EXPECT_LE(d.worst(), 0.02 + d.max_penetration / kTorusDelta) << label;  // 2 % plus the method's own error
    if (name == "direct") smoothed_worst = d.worst();
    const double ring = sum_rf(*r, "RING_PLANE", 1), sleeve = sum_rf(*r, "SLEEVE_PLANE", 1);
    report(label + ": ring reaction / sum CFN2 - 1", ring / sum_cfn(*r, 1) - 1.0);
    EXPECT_NEAR(ring + sleeve, 0.0, 1e-6 * ring) << label;
    EXPECT_NEAR(sum_cfn(*r, 1), ring, 2e-3 * ring) << label;
  }
  auto u = run(deck_path("oring_axi"));
  ASSERT_TRUE(u->outcome.completed) << u->outcome.message;
  const Deviation du = deviation(slave_values(*u, u->capture.last()), p_ref);
  report_deviation("oring_axi unsmoothed, direct", du, *u);
  EXPECT_GE(du.worst(), 10.0 * smoothed_worst);
}

// The reference of the test above, checked (6 s of CPU, 12 s wall on a shared machine):
// - converged: level 2 (2× finer) smoothed lies within 1 % of level 3 at every node (measured
//   −0.77 … +0.50 %: the smoothed pressures keep a node-to-node ripple of about ±0.5 % on every
//   mesh; level 1 reads −0.32 … +0.84 %);
// - not biased by the smoothing: the unsmoothed deck at level 3 still scatters node to node
//   (−11 … +9 % of the reference; the faceting noise falls only as h), but averaged over 16
//   windows of ψ (17 nodes each) it agrees within 1.5 % (measured 0.67 %), and its total contact
//   force (the ring's reaction) converges onto the smoothed one as h², like the facets' sag:
//   −1.6 %, −0.42 %, −0.11 % at levels 1, 2, 3 (smoothed level 1: +0.21 %).
TEST(SmoothedToroidalSurface, FineReferenceHasConvergedAndAgreesWithTheUnsmoothedFineMesh) {
  TestClock clock("oring_axi reference");
  const auto fine = fine_reference();
  ASSERT_TRUE(fine->outcome.completed);
  const SlaveValues fs = slave_values(*fine, fine->capture.last());
  const TubeProfile ref(fs);
  const double force = sum_rf(*fine, "RING_PLANE", 1);

  auto half = run(deck_at_level("oring_axi_smoothed", 2));
  ASSERT_TRUE(half->outcome.completed) << half->outcome.message;
  auto p_ref = [&](const std::array<double, 3>& x) { return ref.at(tube_angle(x)); };
  const Deviation dh = deviation(slave_values(*half, half->capture.last()), p_ref);
  report_deviation("oring_axi smoothed level 2 against level 3", dh, *half);
  EXPECT_LE(dh.worst(), 0.01);

  std::vector<double> force_error;
  for (int level : {1, 2, 3}) {
    auto u = run(deck_at_level("oring_axi", level));
    ASSERT_TRUE(u->outcome.completed) << u->outcome.message;
    const std::string label = "oring_axi unsmoothed level " + std::to_string(level) + " against smoothed level 3";
    const SlaveValues us = slave_values(*u, u->capture.last());
    report_deviation(label, deviation(us, p_ref), *u);
    force_error.push_back(sum_rf(*u, "RING_PLANE", 1) / force - 1.0);
    report(label + ": ring reaction / reference - 1", force_error.back());
    if (level == 3) {
      const auto a = window_means(us, 16), b = window_means(fs, 16);
      double worst = 0.0;
      for (std::size_t w = 0; w < a.size(); ++w) worst = std::max(worst, std::abs(a[w] / b[w] - 1.0));
      report(label + ": worst of 16 window means / reference - 1", worst);
      EXPECT_LE(worst, 0.015);
    }
  }
  // The unsmoothed force error shrinks by at least 3× a level (h²: 4×), down to 0.3 %.
  EXPECT_LE(std::abs(force_error[1]), std::abs(force_error[0]) / 3.0);
  EXPECT_LE(std::abs(force_error[2]), std::abs(force_error[1]) / 3.0);
  EXPECT_LE(std::abs(force_error[2]), 0.003);
}

// Augmented Lagrange at its default stiffness (1000 k_e = 2.13e9 per unit area) on the O-ring,
// smoothed or not. Measured: the first increment in 4 iterations smoothed (8 unsmoothed), the
// second in 1. Before Newton took the law's exact tangent at every node (solver/newton.cpp,
// limit_correction), nodes at the edges of the contact zone that had crossed the law's kink kept
// its stiffness while open: the residual then stalled at 1.4e3 (1.9 times the average force)
// with corrections below a micrometre, and the step stopped after 5 cutbacks.
TEST(SmoothedToroidalSurface, AugmentedLagrangeAtItsDefaultStiffnessEndsInEquilibrium) {
  for (const char* deck : {"oring_axi_smoothed", "oring_axi"}) {
    auto r = run(deck_path(deck), {{"method", "AUGMENTED LAGRANGE"}});
    ASSERT_TRUE(r->outcome.completed) << deck << ": " << r->outcome.message;
    const Deviation d = deviation(slave_values(*r, r->capture.last()), [](const auto&) { return 1.0; });
    EXPECT_EQ(d.n_closed, d.n) << deck;
    const double ring = sum_rf(*r, "RING_PLANE", 1);
    EXPECT_NEAR(sum_cfn(*r, 1), ring, 2e-3 * ring) << deck;
  }
}

}  // namespace
}  // namespace inpact::contact_verification
