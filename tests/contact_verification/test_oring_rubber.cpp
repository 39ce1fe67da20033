// A rubber O-ring squeezed between flat plates (decks/contact_verification/oring_rubber_cax4h.inp,
// gen_oring_rubber.py): neo-Hooke C10 = 0.5, D1 = 0.02 in CAX4H, squeezed by 15 % of its
// diameter, node-to-surface contact with a linear penalty (k = 1000). No closed form; the
// reference is CalculiX 2.20 on the same model with CAX8R (reduced quadratic elements lock
// little; CalculiX has no hybrid axisymmetric elements): its plate reaction, times 180 for its
// 2° segment, is 14.007 for the whole ring (its CAX4 gives 14.837, inpact's CAX4 14.84, CAX8R
// and CAX8H 14.02: the figures of the deck's generator with --element). Tolerance 1.5 %
// (measured 0.6 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

constexpr double kCalculixCax8r = 14.007;

double sum_rf2(const Run& r, const solver::Frame& f, const std::string& set) {
  const solver::FieldData* rf = nullptr;
  for (const auto& fd : f.fields)
    if (fd.key == "RF") rf = &fd;
  if (!rf) throw std::runtime_error("no RF in the frame");
  const std::size_t ncomp = rf->component_labels.size();
  double s = 0.0;
  for (std::int32_t n : r.deck.model.mesh.nsets.at(set).rows) {
    std::size_t loc = static_cast<std::size_t>(n);
    if (!rf->nodes.empty())
      loc = static_cast<std::size_t>(std::find(rf->nodes.begin(), rf->nodes.end(), n) - rf->nodes.begin());
    s += rf->values[loc * ncomp + 1];
  }
  return s;
}

/// Runs `deck` to the end of its squeeze and holds the plate reaction to CalculiX's within
/// `tolerance` (relative).
void check_squeeze(const std::string& deck, double tolerance) {
  const auto r = run(deck_path(deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const solver::Frame& f = r->capture.last();
  EXPECT_NEAR(f.step_time, 1.0, 1e-12);
  const double force = -sum_rf2(*r, f, "PLATE_TOP");
  EXPECT_NEAR(force, kCalculixCax8r, tolerance * kCalculixCax8r);
  report(deck + ": plate reaction (whole ring)", force);
  report(deck + ": / CalculiX CAX8R", force / kCalculixCax8r);
}

TEST(OringRubber, SqueezeForceMatchesCalculix) { check_squeeze("oring_rubber_cax4h", 0.015); }

// The same ring smoothed (oring_rubber_cax4h_smoothed.inp, gen_oring_rubber.py --smoothing): the
// ring's surface corrected toward its torus (*SURFACE SMOOTHING, TOROIDAL about the y axis,
// R = 5), the pair surface to surface with the ring the slave, whose integration points the
// correction moves onto the circle (the plate is flat: nothing to correct). CalculiX's CAX8R ring
// is the same 48-chord polygon (straight-edged midsides), so the smoothed ring, the true torus,
// stands above it: measured 14.166 (+1.1 %; faceted 13.932, -0.5 %); inpact's own mesh-converged
// reaction (ring and plate refined 4×) is 14.18 faceted, 14.20 smoothed. Tolerance 2 %, the
// issue's criterion.
TEST(OringRubber, SmoothedSqueezeForceMatchesCalculix) { check_squeeze("oring_rubber_cax4h_smoothed", 0.02); }

}  // namespace
}  // namespace inpact::contact_verification
