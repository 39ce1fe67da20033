// Contact verification against analytic references (issue 4, "Verification"): Hertz line contact
// and a sphere on a block (Johnson, Contact Mechanics, 1985, §4.2), and the thick-cylinder
// interference fit (Lamé), on the decks of decks/contact_verification/, through run_analysis.
// Every reference is computed from the load the run carried (its reaction), every tolerance is
// stated at its assertion, and every measured figure is printed as "[contact-verification] ...".
// The coarse meshes run here; bench/contact_trade/ runs the finer ones and every method variant.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "contact/normal_behavior.hpp"
#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

using Params = std::map<std::string, std::string>;

const std::map<std::string, Params> kMethods = {
    {"direct", {{"method", "DIRECT"}}},
    {"penalty", {{"method", "PENALTY"}}},
    {"nonlinear penalty", {{"method", "PENALTY=NONLINEAR"}}},
    {"augmented Lagrange", {{"method", "AUGMENTED LAGRANGE"}}},
};

/// k_e of the slave surface, as the solver computes it (contact/normal_behavior.cpp).
double slave_ke(const Run& r, const std::string& surface) {
  const auto s = contact::surface_scales(r.deck.model, r.deck.model.mesh.surfaces.at(surface));
  return s ? s->element_stiffness : 0.0;
}
double slave_length(const Run& r, const std::string& surface) {
  const auto s = contact::surface_scales(r.deck.model, r.deck.model.mesh.surfaces.at(surface));
  return s ? s->characteristic_length : 0.0;
}

HertzFigures report_hertz(const Run& r, int dim, const std::string& label) {
  const HertzFigures h = hertz_figures(r, dim);
  report(label + ": P", h.load);
  report(label + ": p0 (CPRESS on the axis) / p0 Hertz - 1", h.p0 / h.p0_ref - 1.0);
  report(label + ": max CPRESS / p0 Hertz - 1", h.p_max / h.p0_ref - 1.0);
  report(label + ": a estimate / a Hertz - 1", h.a_fe / h.a_ref - 1.0);
  report(label + ": (a estimate - a Hertz) / h", (h.a_fe - h.a_ref) / h.h);
  report(label + ": max penetration", h.max_penetration);
  report(label + ": Newton iterations", r.iterations);
  report(label + ": seconds", r.seconds);
  // The load the indenter's top carries arrives at the block's bottom: through the contact only.
  EXPECT_LE(h.balance, 1e-8) << label;
  return h;
}

// --- Hertz line contact, plane strain ---------------------------------------------------------

// Matching node positions along the contact before loading; level L: h = a/2^(L+1) ≈ 0.25, 0.125,
// 0.0625 (a ≈ 1.11). Measured (direct): p0 +0.74 %, +0.96 %, +0.95 % — converged already on the
// coarsest mesh, to the geometry's own error (a/R = 0.056, finite bodies of 10 a); the contact edge
// lies within one element of a at every level (the estimate (a_closed + a_open)/2 is quantised by
// h: −1.5 … +7 %).
TEST(HertzLineContact, DirectPeakPressureAndHalfWidthConvergeUnderRefinement) {
  for (int level : {1, 2, 3}) {
    auto r = run(deck_at_level("hertz_2d", level));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const std::string label = "hertz_2d direct level " + std::to_string(level);
    const HertzFigures h = report_hertz(*r, 2, label);
    EXPECT_NEAR(h.p0, h.p0_ref, 0.02 * h.p0_ref) << label;       // p0 within 2 %
    EXPECT_NEAR(h.p_max, h.p0_ref, 0.02 * h.p0_ref) << label;    // the peak is on the axis, within 2 %
    EXPECT_LE(std::abs(h.a_fe - h.a_ref), h.h) << label;         // a within one element size
    EXPECT_LE(h.a_closed, h.a_ref + 0.5 * h.h) << label;         // no node closed beyond a + h/2
    EXPECT_GE(h.a_open, h.a_ref - 0.5 * h.h) << label;           // no node open inside a − h/2
    EXPECT_LE(h.max_penetration, 1e-10) << label;                // direct: zero penetration
  }
}

// "Each enforcement method on the same deck gives the same pressure within its own error", on the
// coarse mesh. Measured p0 errors: direct +0.74 %, penalty −0.46 %, nonlinear penalty −1.9 %,
// augmented Lagrange +0.74 %.
TEST(HertzLineContact, EveryMethodGivesThePeakPressureWithinItsOwnError) {
  std::map<std::string, double> p0;
  for (const auto& [name, params] : kMethods) {
    auto r = run(deck_path("hertz_2d"), params);
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const HertzFigures h = report_hertz(*r, 2, "hertz_2d " + name);
    p0[name] = h.p0 / h.p0_ref;  // each run's own reference: under prescribed motion the load differs
    const double ke = slave_ke(*r, "INDENTER_S"), l = slave_length(*r, "INDENTER_S");
    if (name == "direct") {
      EXPECT_NEAR(h.p0, h.p0_ref, 0.02 * h.p0_ref);
    } else if (name == "penalty") {
      // Linear penalty k = 10 k_e: penetration = p / k at every closed node (the law, to 1e-9),
      // and the softer contact lowers the peak by about the penetration over the approach.
      const double k = 10.0 * ke;
      const SlaveValues s = slave_values(*r, r->capture.last());
      for (std::size_t i = 0; i < s.cpress.size(); ++i)
        if (s.cpress[i] > 0) {
          EXPECT_NEAR(-s.copen[i], s.cpress[i] / k, 1e-9 * h.p0_ref / k) << i;
        }
      EXPECT_NEAR(h.max_penetration, h.p_max / k, 1e-9 * h.p0_ref / k);
      EXPECT_NEAR(h.p0, h.p0_ref, 0.02 * h.p0_ref);
    } else if (name == "nonlinear penalty") {
      // K_f = 100 k_e, K_i = K_f / 100 below 1 % of the facet: the softest start, the largest error.
      EXPECT_NEAR(h.p0, h.p0_ref, 0.03 * h.p0_ref);
    } else {
      // Augmented Lagrange: every penetration within the default 0.1 % of the characteristic
      // length, and the pressure then that of direct enforcement.
      EXPECT_LE(h.max_penetration, 1e-3 * l);
      EXPECT_NEAR(h.p0, h.p0_ref, 0.02 * h.p0_ref);
    }
  }
  for (const auto& [name, ratio] : p0) EXPECT_NEAR(ratio, p0.at("direct"), 0.03) << name;
}

// Non-matching meshes (master elements 1.25 × the slave's): single-pass node-to-surface contact
// does not pass the patch test there (tests/contact/test_contact_analysis.cpp: 8 %), and the
// Hertz pressure oscillates node to node by as much: measured on the axis −8.3 % (level 1), −7.3 %
// (2), −6.9 % (3) while its neighbour is +2 … +3 %, not converging under refinement. This pins the
// size of that error; surface-to-surface contact or smoothing (issue 5) is what removes it.
TEST(HertzLineContact, NonMatchingMeshesShowTheNodeToSurfaceOscillation) {
  auto r = run(deck_path("hertz_2d_nonmatching"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const HertzFigures h = report_hertz(*r, 2, "hertz_2d_nonmatching direct");
  EXPECT_NEAR(h.p0, h.p0_ref, 0.12 * h.p0_ref);
  EXPECT_GE(std::abs(h.p0 / h.p0_ref - 1.0), 0.02) << "node-to-surface passes here now: tighten the Hertz tests";
  EXPECT_NEAR(h.p_max, h.p0_ref, 0.05 * h.p0_ref);
  EXPECT_LE(std::abs(h.a_fe - h.a_ref), h.h);
}

// --- Sphere on a block ---------------------------------------------------------------------------

// Quarter model, C3D8, matching meshes, h = a/3 at the contact (about 3,500 elements, 1 s).
// Measured (direct): p0 +0.7 %, contact radius estimate +13 % = 0.4 h (quantised by h).
TEST(SphereOnBlock, DirectGivesHertzPressureAndContactRadius) {
  auto r = run(deck_path("sphere_3d"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const HertzFigures h = report_hertz(*r, 3, "sphere_3d direct");
  EXPECT_NEAR(h.p0, h.p0_ref, 0.03 * h.p0_ref);  // p0 within 3 % on this coarse mesh
  EXPECT_LE(std::abs(h.a_fe - h.a_ref), h.h);    // contact radius within one element size
  // Direct: closed nodes on the surface to Newton's contact compatibility tolerance (Abaqus's
  // C_ε = 1e-3 of the increment's displacement, solver/newton.cpp); measured 2.5e-10 of a ≈ 1
  // (the on-surface snap reported 0 for the nodes on facet vertices before).
  EXPECT_LE(h.max_penetration, 1e-9);
}

// --- Thick-cylinder interference fit (Lamé) -------------------------------------------------------

/// The master (inner ring) facets are chords of its circle r = b + δ: between its nodes the
/// surface lies inside the circle by up to sag = (b + δ)(1 − cos(Δθ/2)), and a slave node there
/// sees an overclosure δ − (its local sag). Averaged over the slave nodes, the interference is
/// δ − (2/3) sag: the mean pressure is low by (2/3) sag / δ to first order.
double facet_sag(int n_master_per_quarter) {
  return (kRingB + kDelta) * (1.0 - std::cos(0.25 * std::numbers::pi / n_master_per_quarter));
}

// Level 1 (24 and 34 elements per quarter) and 2 (48 and 68). Measured (direct): mean pressure
// −2.9 % (level 1, predicted by the facet sag −3.6 %) and −0.7 % (level 2, predicted −0.9 %); the
// scatter (max − min)/p is 2.3 and 1.0: the node-to-surface noise on faceted curved surfaces that
// smoothing (issue 5) is to remove.
TEST(InterferenceFit, DirectMeanPressureMatchesLame) {
  for (int level : {1, 2}) {
    auto r = run(deck_at_level("interference_2d", level));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const std::string label = "interference_2d direct level " + std::to_string(level);
    const FitFigures fit = fit_figures(*r, r->capture.last());
    const double sag = facet_sag(24 << (level - 1));
    report(label + ": Lame pressure", fit.p_ref);
    report(label + ": mean CPRESS / Lame - 1", fit.p_mean / fit.p_ref - 1.0);
    report(label + ": predicted by the facet sag, -(2/3) sag/delta", -2.0 / 3.0 * sag / kDelta);
    report(label + ": scatter (max - min CPRESS) / Lame", (fit.p_max - fit.p_min) / fit.p_ref);
    report(label + ": max CPRESS / Lame", fit.p_max / fit.p_ref);
    report(label + ": min CPRESS / Lame", fit.p_min / fit.p_ref);
    report(label + ": closed slave nodes / slave nodes", double(fit.n_closed) / double(fit.n_slave));
    // Mean pressure within the facet-sag error plus 1 %.
    EXPECT_NEAR(fit.p_mean, fit.p_ref, (2.0 / 3.0 * sag / kDelta + 0.01) * fit.p_ref) << label;
    EXPECT_EQ(fit.n_closed, fit.n_slave) << label << ": every slave node is pressed";
    EXPECT_LE(fit.max_penetration, 1e-10) << label;
    // The initial overclosure is resolved in the first increment (Abaqus's rule without
    // *CONTACT INTERFERENCE): its frame (step time 0.5) already holds the whole fit.
    ASSERT_EQ(r->capture.frames.size(), 2u) << label;
    const FitFigures first = fit_figures(*r, r->capture.frames.front().frame);
    // (to the Newton tolerance: the second increment iterates once more, measured 3e-5 of p)
    EXPECT_NEAR(first.p_mean, fit.p_mean, 1e-3 * fit.p_ref) << label;
    EXPECT_EQ(first.n_closed, first.n_slave) << label;
  }
}

// Penalty-type methods on the interference fit. DISABLED: on this deck no external load or
// prescribed motion acts, so the Newton loop's average force q (solver/newton.cpp, average_force)
// counts element forces and loads but not the contact forces, is 0 in iteration 0 (u = 0), and
// `no_force = q <= 0` accepts the increment with the whole overclosure left in: penalty writes
// CPRESS = k δ (×300 the Lamé pressure at the default stiffness), augmented Lagrange augments 50
// times without moving and gives up. Enable once q includes the contact forces.
/// Runs the interference fit with `params` and checks the mean pressure against Lamé.
double interference_mean_pressure(const std::string& name, const Params& params) {
  auto r = run(deck_path("interference_2d"), params);
  EXPECT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
  if (!r->outcome.completed) return 0.0;
  const FitFigures fit = fit_figures(*r, r->capture.last());
  report("interference_2d " + name + ": mean CPRESS / Lame - 1", fit.p_mean / fit.p_ref - 1.0);
  report("interference_2d " + name + ": max penetration", fit.max_penetration);
  EXPECT_NEAR(fit.p_mean, fit.p_ref, 0.06 * fit.p_ref) << name;
  if (name == "augmented Lagrange") {
    EXPECT_LE(fit.max_penetration, 1e-3 * slave_length(*r, "OUTER_S"));
  }
  return fit.p_mean;
}

TEST(InterferenceFit, PenaltyMethodsGiveTheLamePressureAndAgreeWithDirect) {
  const double direct = interference_mean_pressure("direct", kMethods.at("direct"));
  for (const char* name : {"penalty", "nonlinear penalty"})
    EXPECT_NEAR(interference_mean_pressure(name, kMethods.at(name)), direct, 0.05 * direct) << name;
}

// Augmented Lagrange once chattered here: a node whose pressure is a few % of Lamé (faceting
// noise) crossed the law's kink six times in the first increment and was taken for contact
// chattering. A penalty-type law is continuous, so only multiplier methods count flips now.
TEST(InterferenceFit, AugmentedLagrangeGivesTheLamePressure) {
  interference_mean_pressure("augmented Lagrange", kMethods.at("augmented Lagrange"));
}

// --- Surface to surface -----------------------------------------------------------------------

const Params kSurfaceToSurfaceDirect = {{"method", "DIRECT"}, {"type", "SURFACE TO SURFACE"}};

// Hertz with surface to surface (direct, standard mortar-type multipliers). Matching meshes:
// p0 +0.8 % (node to surface +0.7 %). Non-matching (master 1.25 × the slave's), where node to
// surface is −8.3 % on the axis: −3.6 % on the axis, peak +7.3 % beside it — the nodal
// multipliers of a weighted gap still oscillate where the master's kinks fall inside slave faces,
// by less than half as much.
TEST(SurfaceToSurfaceVerification, HertzMatchingAndNonMatchingMeshes) {
  for (const auto& [deck, p0_tol, peak_tol] : {std::tuple<const char*, double, double>{"hertz_2d", 0.02, 0.02},
                                               {"hertz_2d_nonmatching", 0.05, 0.09}}) {
    auto r = run(deck_path(deck), kSurfaceToSurfaceDirect);
    ASSERT_TRUE(r->outcome.completed) << deck << ": " << r->outcome.message;
    const HertzFigures h = report_hertz(*r, 2, std::string(deck) + " surface to surface, direct");
    EXPECT_NEAR(h.p0, h.p0_ref, p0_tol * h.p0_ref) << deck;
    EXPECT_NEAR(h.p_max, h.p0_ref, peak_tol * h.p0_ref) << deck;
    EXPECT_LE(std::abs(h.a_fe - h.a_ref), h.h) << deck;
  }
}

// Sphere on a block, surface to surface, on the coarse mesh (h = a/3): p0 +10 %, contact radius
// −16 % (−0.47 h): the slave facets' chords lie inside the sphere by their sag, and averaging
// the gap over them presses the nodes in. Level 2 (not run here: 14 s): p0 +1.8 %, a −4.5 %,
// converging; node to surface is +0.7 % on level 1. Smoothing (issue 5) removes the sag.
TEST(SurfaceToSurfaceVerification, SphereOnBlockCoarse) {
  auto r = run(deck_path("sphere_3d"), kSurfaceToSurfaceDirect);
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const HertzFigures h = report_hertz(*r, 3, "sphere_3d surface to surface, direct");
  EXPECT_NEAR(h.p0, h.p0_ref, 0.12 * h.p0_ref);
  EXPECT_LE(std::abs(h.a_fe - h.a_ref), h.h);
}

// The interference fit's scatter comes from the faceted circles, which surface to surface
// averages but cannot remove (issue 5's smoothing does): the mean stays within the sag error.
TEST(SurfaceToSurfaceVerification, InterferenceFitMeanPressure) {
  for (const auto& [name, params] : {std::pair<std::string, Params>{"direct", kSurfaceToSurfaceDirect},
                                     {"penalty", {{"method", "PENALTY"}, {"type", "SURFACE TO SURFACE"}}}}) {
    auto r = run(deck_path("interference_2d"), params);
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const FitFigures fit = fit_figures(*r, r->capture.last());
    const std::string label = "interference_2d surface to surface, " + name;
    report(label + ": mean CPRESS / Lame - 1", fit.p_mean / fit.p_ref - 1.0);
    report(label + ": scatter (max - min CPRESS) / Lame", (fit.p_max - fit.p_min) / fit.p_ref);
    EXPECT_NEAR(fit.p_mean, fit.p_ref, (2.0 / 3.0 * facet_sag(24) / kDelta + 0.01) * fit.p_ref) << label;
  }
}

// --- Smoothing (issue 5) ---------------------------------------------------------------------

// The interference fit of [AX] 38.1.3 (two concentric rings, first-order elements of different
// sizes, 24 and 34 around a quarter): with both ring surfaces smoothed toward their circles,
// every slave node's CPRESS lies within 2 % of Lamé on this coarse mesh, for every method.
// Measured: direct +0.15 … +1.16 %, penalty +0.08 … +0.66 %, augmented Lagrange as direct,
// nonlinear penalty −2.5 … −2.4 % (its own penetration).
// Without smoothing the same mesh scatters over 0.93 (surface to surface) and 2.29 (node to
// surface) of the Lamé pressure (the tests above).
TEST(SmoothedInterferenceFit, EverySlaveNodeWithinTwoPercentOfLame) {
  for (const auto& [name, params] : kMethods) {
    auto r = run(deck_path("interference_2d_smoothed"), params);
    ASSERT_TRUE(r->outcome.completed) << name << ": " << r->outcome.message;
    const FitFigures fit = fit_figures(*r, r->capture.last());
    const std::string label = "interference_2d smoothed, " + name;
    report(label + ": min CPRESS / Lame - 1", fit.p_min / fit.p_ref - 1.0);
    report(label + ": max CPRESS / Lame - 1", fit.p_max / fit.p_ref - 1.0);
    report(label + ": mean CPRESS / Lame - 1", fit.p_mean / fit.p_ref - 1.0);
    EXPECT_EQ(fit.n_closed, fit.n_slave) << label;
    // 2 %, plus the method's own error: a penetration h takes h/δ off the interference (the
    // nonlinear penalty's soft start: −2.4 %, its penetration 2.5 % of δ).
    const double tol = 0.02 + fit.max_penetration / kDelta;
    EXPECT_NEAR(fit.p_min, fit.p_ref, tol * fit.p_ref) << label;
    EXPECT_NEAR(fit.p_max, fit.p_ref, tol * fit.p_ref) << label;
    if (name == "direct") {
      EXPECT_LE(fit.p_max - fit.p_min, 0.02 * fit.p_ref) << label;  // the scatter itself
    }
  }
}

}  // namespace
}  // namespace inpact::contact_verification
