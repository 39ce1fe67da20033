// Method agreement (issue 14, "every method must give the same answer within its own
// tolerance"): direct, penalty, augmented Lagrange and nonlinear penalty on the same decks, each
// against direct enforcement on that deck (the discretisation's own error is then the same for
// every method, and what is left is the method's). The bounds are derived at kNewton and in
// each test's comment from what the method itself reports (its penetration, its law); every
// figure is printed as "[contact-verification] ...".
//
// Why a method differs from direct at all: a penalty-type method's converged state is direct's
// for a problem whose gap at each closed node is shifted by that node's penetration h_i. How
// much the pressure moves for such a shift depends on its shape:
//   - uniform (the interference fit, where Lamé's pressure is linear in the interference δ):
//     the pressure falls by h/δ of itself;
//   - smooth at the scale of the contact (a Hertz profile changed by up to h_max, against its
//     depth a²/2R at the contact edge): p0 moves by about h_max / (a²/2R) of itself;
//   - node to node, at the scale of the mesh: a nodal gap shift h moves the nodal pressure by
//     at most k_e h, k_e being the stiffness of the element layer under a facet per unit
//     overclosure (contact/normal_behavior.cpp: M / thickness).
// On the Hertz decks the linear penalty (10 k_e: h_max = p_max / 10 k_e) and augmented Lagrange
// (1000 k_e; its h_max is at most its tolerance, which the augmentation loop checks, so k_e × tol
// bounds it a priori, and the h_max it reports gives the tighter bound used) are held to the
// node-to-node bound k_e h_max, the largest of the three: the coarse surface-to-surface sphere
// needs it (direct's answer there carries an error at the scale of the mesh, the zone's edge a
// node short, which the penalty's compliance spreads: 3.9 % against a profile bound of 1.8 %).
// The nonlinear penalty, whose soft start (K_i = k_e for the first 1 % of l_char) makes k_e h_max
// exceed p0, is held to the profile bound. On the interference fit every method is held to h/δ. Where the methods stood before (issue 14): on the smoothed
// interference fit in general contact augmented Lagrange scattered −16 … +12 % of Lamé while
// direct lay within +0.15 … +1.16 % — its two balanced rows of 1000 k_e shared each contact by
// the difference of the gaps the two discretisations measure (contact/interaction_table.hpp,
// general_contact_one_row).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "contact/normal_behavior.hpp"
#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

using Params = std::map<std::string, std::string>;

struct Method {
  std::string name, keyword;  ///< label, *SURFACE BEHAVIOR parameter
};
const std::vector<Method> kMethods = {
    {"direct", "DIRECT"},
    {"penalty", "PENALTY"},
    {"augmented Lagrange", "AUGMENTED LAGRANGE"},
    {"nonlinear penalty", "PENALTY=NONLINEAR"},
};

/// What Newton's convergence leaves in a pressure: the residual criterion (5e-3 of the time-
/// averaged force, solver/convergence.cpp) at a contact node, against that node's contact force,
/// is at most this fraction of it on these decks (the contact nodes carry more than the average
/// force). Added to every bound.
constexpr double kNewton = 5e-3;

/// The element stiffness k_e of the slave surface, as the solver computes it.
double slave_ke(const Run& r, const std::string& surface) {
  const auto s = contact::surface_scales(r.deck.model, r.deck.model.mesh.surfaces.at(surface));
  return s ? s->element_stiffness : 0.0;
}

int cutbacks(const Run& r) {
  int n = 0;
  for (const auto& row : r.capture.rows) n += row.cut_back ? 1 : 0;
  return n;
}

void report_run(const std::string& label, const Run& r) {
  report(label + ": Newton iterations", r.iterations);
  report(label + ": augmentations", r.augmentations);
  report(label + ": cutbacks", cutbacks(r));
  report(label + ": seconds", r.seconds);
}

// --- Hertz, prescribed approach -----------------------------------------------------------------

/// The bound on |p0 / p0_Hertz − p0_direct / p0_Hertz_direct| for a method whose largest
/// penetration is `h` (each run against its own load's reference p0_ref, a_ref).
double hertz_bound(const std::string& method, double h, double ke, double p0_ref, double a_ref) {
  if (method == "nonlinear penalty") return h / (a_ref * a_ref / (2.0 * kRadius)) + kNewton;
  return ke * h / p0_ref + kNewton;
}

/// Every method on `deck` (dimension `dim`) with TYPE=`type`, against direct on the same deck.
void hertz_methods_agree(const std::string& deck, int dim, const std::string& type) {
  double direct_p0 = 0.0;
  for (const Method& m : kMethods) {
    auto r = run(deck_path(deck), {{"method", m.keyword}, {"type", type}});
    ASSERT_TRUE(r->outcome.completed) << m.name << ": " << r->outcome.message;
    const std::string label = deck + " " + type + ", " + m.name;
    const HertzFigures f = hertz_figures(*r, dim);
    const double p0 = f.p0 / f.p0_ref - 1.0;
    report(label + ": p0 / p0 Hertz - 1", p0);
    report(label + ": max penetration", f.max_penetration);
    report_run(label, *r);
    EXPECT_LE(f.balance, 1e-8) << label;
    if (m.name == "direct") {
      direct_p0 = p0;
      continue;
    }
    const double bound = hertz_bound(m.name, f.max_penetration, slave_ke(*r, "INDENTER_S"), f.p0_ref, f.a_ref);
    report(label + ": |p0 - p0 direct| / p0 Hertz", std::abs(p0 - direct_p0));
    report(label + ": its bound", bound);
    EXPECT_LE(std::abs(p0 - direct_p0), bound) << label;
  }
}

// Hertz line contact (hertz_2d, a/h = 4, plane strain). Measured p0 / p0 Hertz − 1 (max
// penetration; bound on the difference from direct):
//   node to surface     direct +0.74 %; penalty +0.46 % (2.8e-4; 10.5 %), augmented Lagrange
//                       +0.74 % (2.8e-6; 0.6 %), nonlinear penalty −1.91 % (2.7e-3; 9.5 %)
//   surface to surface  direct +0.82 %; penalty +1.03 %, augmented Lagrange +0.83 %, nonlinear
//                       penalty −1.21 % (about the same penetrations and bounds)
TEST(MethodAgreement, HertzLineContactEveryMethodAgreesWithDirect) {
  hertz_methods_agree("hertz_2d", 2, "NODE TO SURFACE");
  hertz_methods_agree("hertz_2d", 2, "SURFACE TO SURFACE");
}

// The sphere on a block (sphere_3d, quarter model, a/h = 3: the coarse 3D mesh of the issue).
// Measured p0 / p0 Hertz − 1 (max penetration; bound on the difference from direct):
//   node to surface     direct +0.74 %; penalty −0.07 % (4.1e-4; 10.5 %), augmented Lagrange
//                       +0.73 % (4.2e-6; 0.6 %), nonlinear penalty −6.6 % (3.8e-3; 16.4 %)
//   surface to surface  direct +10.0 % (the coarse mesh: the node at r = a ≈ 3h has a positive
//                       weighted gap and stays open, so the edge of the zone falls a node short
//                       and the pole carries more; node to surface closes it); penalty +6.2 %
//                       (4.4e-4; 11 %: its compliance spreads that edge), augmented Lagrange
//                       +9.95 % (4.6e-6; 0.6 %), nonlinear penalty −2.0 % (3.9e-3; 17 %)
// The figures (+11 % penalty, +42 % augmented Lagrange, on a deck of its own at a/h ≈ 4)
// are not what this deck gives today.
TEST(MethodAgreement, SphereOnBlockCoarseEveryMethodAgreesWithDirect) {
  hertz_methods_agree("sphere_3d", 3, "NODE TO SURFACE");
  hertz_methods_agree("sphere_3d", 3, "SURFACE TO SURFACE");
}

// --- The smoothed interference fit, as a pair and in general contact ---------------------------

/// CPRESS / Lamé − 1 over every slave node of every row.
struct FitRange {
  double min = 1e300, max = -1e300, mean = 0.0, max_penetration = 0.0;
  std::size_t n_closed = 0, n = 0;
};

FitRange fit_range(const Run& r) {
  const FitFigures f = fit_figures(r, r.capture.last());
  return {f.p_min / f.p_ref - 1.0, f.p_max / f.p_ref - 1.0, f.p_mean / f.p_ref - 1.0, f.max_penetration, f.n_closed,
          f.n_slave};
}

/// Every method on `deck` against direct: a penetration h takes h/δ off the interference, so a
/// method's nodal pressures lie in [direct's lowest − h_max/δ − kNewton, direct's highest +
/// kNewton], and its mean within [direct's − h_max/δ − kNewton, direct's + kNewton].
void fit_methods_agree(const std::string& deck) {
  FitRange direct;
  for (const Method& m : kMethods) {
    auto r = run(deck_path(deck), {{"method", m.keyword}});
    ASSERT_TRUE(r->outcome.completed) << m.name << ": " << r->outcome.message;
    const std::string label = deck + ", " + m.name;
    const FitRange f = fit_range(*r);
    report(label + ": min CPRESS / Lame - 1", f.min);
    report(label + ": max CPRESS / Lame - 1", f.max);
    report(label + ": mean CPRESS / Lame - 1", f.mean);
    report(label + ": max penetration / delta", f.max_penetration / kDelta);
    report(label + ": slave nodes (every row)", static_cast<double>(f.n));
    report_run(label, *r);
    EXPECT_EQ(f.n_closed, f.n) << label;
    if (m.name == "direct") {
      direct = f;
      continue;
    }
    // Augmented Lagrange is one row, as direct, in general contact too (general_contact_one_row).
    if (m.name == "augmented Lagrange") {
      EXPECT_EQ(f.n, direct.n) << label;
    }
    const double own = f.max_penetration / kDelta;
    EXPECT_GE(f.min, direct.min - own - kNewton) << label;
    EXPECT_LE(f.max, direct.max + kNewton) << label;
    EXPECT_GE(f.mean, direct.mean - own - kNewton) << label;
    EXPECT_LE(f.mean, direct.mean + kNewton) << label;
  }
}

// The pair (interference_2d_smoothed, surface to surface, both rings smoothed). Measured
// CPRESS / Lamé − 1 over the 35 slave nodes (max penetration / δ):
//   direct +0.15 … +1.16 %; penalty +0.08 … +0.66 % (0.33 %); augmented Lagrange +0.15 … +1.15 %
//   (0.003 %); nonlinear penalty −2.51 … −2.35 % (3.2 %)
TEST(MethodAgreement, SmoothedInterferenceFitPairEveryMethodAgreesWithDirect) {
  fit_methods_agree("interference_2d_smoothed");
}

// General contact with the one inclusion pair, smoothed by *SURFACE PROPERTY ASSIGNMENT
// (interference_2d_general): direct and augmented Lagrange one row (35 slave nodes), the
// penalty laws two balanced rows (60 nodes, both surfaces). Measured CPRESS / Lamé − 1:
//   direct +0.15 … +1.16 %; penalty +0.01 … +1.08 % (0.31 %); augmented Lagrange +0.15 … +1.15 %
//   (0.003 %; before it was one row: −15.6 … +11.8 %, mean +0.75 %); nonlinear penalty −2.33 …
//   −2.14 % (3.0 %)
TEST(MethodAgreement, SmoothedInterferenceFitInGeneralContactEveryMethodAgreesWithDirect) {
  fit_methods_agree("interference_2d_general");
}

// --- A sphere resting on a block, pushed by a force -------------------------------------------

// The deck's load (gen_contact_verification.py sphere_3d_force): P = 4 E* a³ / (3R) for a = 1.
constexpr double kSphereA = 1.0;
const double kSphereLoad = 4.0 * kEStar * kSphereA * kSphereA * kSphereA / (3.0 * kRadius);
const double kSphereP0 = 3.0 * kSphereLoad / (2.0 * std::numbers::pi * kSphereA * kSphereA);

struct SphereForceFigures {
  double p0 = 0.0;        ///< CPRESS at the pole
  double a_moment = 0.0;  ///< the contact radius from the second moment of the contact force
  double a_closed = 0.0;  ///< r of the outermost closed slave node
  double contact_force = 0.0;  ///< Σ CPRESS·CNAREA (the quarter's)
  double foundation = 0.0;     ///< Σ RF₃ over the block's bottom (the quarter's)
  double max_penetration = 0.0;
  bool first_attempt_cut_back = false;
};

/// Hertz's p = p0 √(1 − r²/a²) has ∫ p r² dA / ∫ p dA = 2a²/5, so a = √(5/2 Σ F r² / Σ F) over
/// the slave nodes' contact forces F = CPRESS·CNAREA: every node counts, and the estimate is not
/// quantised by the node spacing as the outermost closed node is (±h/2, 12 % of a at a/h = 4).
/// Its own error is the lumping of the pressure into nodal forces, O(h²): node to surface, direct,
/// +0.81 % at a/h = 4.
double moment_radius(const SlaveValues& s) {
  double force = 0.0, moment = 0.0;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double f = s.cpress[i] * s.cnarea[i], r2 = s.x[i][0] * s.x[i][0] + s.x[i][1] * s.x[i][1];
    force += f;
    moment += f * r2;
  }
  return std::sqrt(2.5 * moment / force);
}

SphereForceFigures sphere_force_figures(const Run& r) {
  SphereForceFigures out;
  const SlaveValues s = slave_values(r, r.capture.last());
  double r_min = 1e300;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double radius = std::hypot(s.x[i][0], s.x[i][1]);
    if (radius < r_min) {
      r_min = radius;
      out.p0 = s.cpress[i];
    }
    out.contact_force += s.cpress[i] * s.cnarea[i];
    if (s.cpress[i] > 0.0) {
      out.a_closed = std::max(out.a_closed, radius);
      out.max_penetration = std::max(out.max_penetration, -s.copen[i]);
    }
  }
  out.a_moment = moment_radius(s);
  for (auto row : verification::nset(r.deck.model, "BLOCK_BOTTOM"))
    out.foundation += verification::nodal(r.capture.last(), "RF", row, 2);
  out.first_attempt_cut_back = r.capture.rows.front().cut_back;
  return out;
}

/// Every method on the force-driven sphere at `path` with TYPE=`type`: p0 and a within
/// `tolerance` of Hertz for the deck's load; the nonlinear penalty within its own bound of
/// direct (hertz_bound: its soft start is an error of its law, not of the contact).
void sphere_force_within(const std::string& path, const std::string& level, const std::string& type,
                         double tolerance) {
  double direct_p0 = 0.0;
  for (const Method& m : kMethods) {
    auto r = run(path, {{"method", m.keyword}, {"type", type}});
    ASSERT_TRUE(r->outcome.completed) << m.name << ": " << r->outcome.message;
    const std::string label = "sphere_3d_force " + level + " " + type + ", " + m.name;
    const SphereForceFigures f = sphere_force_figures(*r);
    const double p0 = f.p0 / kSphereP0 - 1.0;
    report(label + ": p0 / p0 Hertz - 1", p0);
    report(label + ": a (second moment) / a Hertz - 1", f.a_moment / kSphereA - 1.0);
    report(label + ": outermost closed node r / a", f.a_closed / kSphereA);
    report(label + ": 4 sum CPRESS CNAREA / P - 1", 4.0 * f.contact_force / kSphereLoad - 1.0);
    report(label + ": max penetration", f.max_penetration);
    report(label + ": first attempt cut back", f.first_attempt_cut_back ? 1.0 : 0.0);
    report_run(label, *r);
    // The foundation carries the deck's load (to round-off: the reactions include the residual).
    EXPECT_NEAR(4.0 * f.foundation, kSphereLoad, 1e-9 * kSphereLoad) << label;
    // Surface to surface, the first system is regular (the pole starts closed) and the first
    // increment converges in its first attempt.
    if (type == "SURFACE TO SURFACE") {
      EXPECT_FALSE(f.first_attempt_cut_back) << label;
    }
    if (m.name == "direct") direct_p0 = p0;
    if (m.name == "nonlinear penalty") {
      EXPECT_LE(std::abs(p0 - direct_p0), hertz_bound(m.name, f.max_penetration, 0.0, kSphereP0, kSphereA)) << label;
      continue;
    }
    EXPECT_NEAR(f.p0, kSphereP0, tolerance * kSphereP0) << label;
    EXPECT_NEAR(f.a_moment, kSphereA, tolerance * kSphereA) << label;
  }
}

// The sphere resting on the block and pushed by a force (sphere_3d_force, a/h = 4 at the
// contact, the coarse mesh): p0 and a within 5 % of Hertz, every method, both
// discretisations, each from a first increment of 25 % of the load. Measured (p0, a; max
// penetration; Newton iterations, cutbacks):
//   surface to surface  direct +2.30 %, −3.94 % (19, 0); penalty +1.51 %, −3.35 % (3.2e-4; 15, 0);
//                       augmented Lagrange +2.26 %, −3.93 % (3.4e-6; 21, 0); nonlinear penalty
//                       −2.22 %, +0.06 % (3.1e-3; 20, 0; 4.5 % from direct, its bound 12.8 %)
//   node to surface     direct +0.48 %, +0.81 % (19, 0); penalty −0.11 %, +1.27 % (3.1e-4; 86,
//                       1); augmented Lagrange +0.48 %, +0.82 % (3.2e-6; 20, 0); nonlinear
//                       penalty −4.92 %, +4.65 % (3.0e-3; 46, 2; 5.4 % from direct)
// Node to surface, the penalty laws' first attempt is cut back after iterations that keep
// changing the contact status around the pole; surface to surface no first attempt is.
// Augmented Lagrange at 1000 k_e: no augmentation is ever needed (its penetration stays below
// 1 % of the tolerance). Where a ring of nodes closes, the sphere, pushed by a force, sinks
// into the ring's open nodes in one correction, and their penetration's force throws it off
// again. Newton cuts such corrections back to where no such node goes deeper than the pair's
// deepest (limit_correction in solver/newton.cpp); surface to surface took 144 iterations and 3
// cutbacks from a first increment of 25 % before it did, and 60 and 1 while the limit was 1 %
// of the tolerance (tens of times the depth of p0 at 1000 k_e). At a/h = 3 (sphere_3d's mesh) surface to surface closes the
// zone a node short: direct +9.7 % on p0, −6.7 % on a.
TEST(SphereUnderAForce, CoarseSurfaceToSurfaceEveryMethodWithinFivePercentOfHertz) {
  sphere_force_within(deck_path("sphere_3d_force"), "level 1", "SURFACE TO SURFACE", 0.05);
}

TEST(SphereUnderAForce, CoarseNodeToSurfaceEveryMethodWithinFivePercentOfHertz) {
  sphere_force_within(deck_path("sphere_3d_force"), "level 1", "NODE TO SURFACE", 0.05);
}

// A rigid sphere as an analytical surface of revolution on the same block (sphere_3d_analytical,
// the block the slave, the load P/4 on the sphere's reference node): rigid-indenter Hertz,
// E* = E/(1 − ν²), P for a = 1, a/h = 4. Measured (p0, a by the second moment; Newton
// iterations; the first increment 1 % of the load):
//   surface to surface  direct +3.71 %, −4.28 % (31); penalty +2.67 %, −3.17 % (31)
//   node to surface     direct +1.82 %, +0.44 % (31); penalty +0.56 %, +1.38 % (32)
// (the deformable pair on this mesh, above: within 2.3 % and 3.9 %).
TEST(SphereUnderAForce, RigidAnalyticalSphereWithinFivePercentOfHertz) {
  const double e_star = 2.0 * kEStar;
  const double load = 4.0 * e_star * kSphereA * kSphereA * kSphereA / (3.0 * kRadius);
  const double p0_ref = 3.0 * load / (2.0 * std::numbers::pi * kSphereA * kSphereA);
  for (const std::string type : {"SURFACE TO SURFACE", "NODE TO SURFACE"})
    for (const std::string method : {"DIRECT", "PENALTY"}) {
      auto r = run(deck_path("sphere_3d_analytical"), {{"method", method}, {"type", type}, {"inc0", "0.01"}});
      const std::string label = "sphere_3d_analytical " + type + ", " + method;
      ASSERT_TRUE(r->outcome.completed) << label << ": " << r->outcome.message;
      const SphereForceFigures f = sphere_force_figures(*r);
      report(label + ": p0 / p0 Hertz - 1", f.p0 / p0_ref - 1.0);
      report(label + ": a (second moment) / a Hertz - 1", f.a_moment / kSphereA - 1.0);
      report_run(label, *r);
      EXPECT_NEAR(4.0 * f.foundation, load, 1e-9 * load) << label;
      EXPECT_NEAR(f.p0, p0_ref, 0.05 * p0_ref) << label;
      EXPECT_NEAR(f.a_moment, kSphereA, 0.05 * kSphereA) << label;
    }
}

// The same at level 2 (a/h = 8, 11,666 nodes): every method within 2 %. Disabled: each run
// takes minutes (120–300 s of wall time on the shared machine of the measurement, 25 min in
// all). Measured on 2026-12-07 (p0, a; Newton iterations, cutbacks):
//   surface to surface  direct +1.11 %, −0.90 % (30, 0); penalty +0.86 %, −0.74 % (26, 0);
//                       augmented Lagrange +1.11 %, −0.90 % (66, 1); nonlinear penalty −1.55 %,
//                       +1.10 %
//   node to surface     direct +0.50 %, +0.33 % (1 cutback); penalty +0.21 %, +0.54 % (2);
//                       augmented Lagrange +0.50 %, +0.33 % (0); nonlinear penalty −2.22 %,
//                       +2.24 % (3; within its bound from direct)
// The one expectation it misses: augmented Lagrange, surface to surface, cuts its first attempt
// back once. (Before Newton limited its overshooting corrections it had reached 5 % of the
// load after 17 minutes.)
TEST(SphereUnderAForce, DISABLED_RefinedEveryMethodWithinTwoPercentOfHertz) {
  const std::string deck = deck_at_level("sphere_3d_force", 2);
  sphere_force_within(deck, "level 2", "SURFACE TO SURFACE", 0.02);
  sphere_force_within(deck, "level 2", "NODE TO SURFACE", 0.02);
}

}  // namespace
}  // namespace inpact::contact_verification
