// Case 9: the centrifugal load (*DLOAD CENTRIF, ρω² times the distance vector from the axis).
//
// References:
//  - a free annular disk spinning about its axis, plane stress (Timoshenko & Goodier §32;
//    gen_verification.py spinning_disk_displacement): u_r at the bore and the rim. The quarter
//    (CPS8, about z) is plane stress exactly; the axisymmetric slice (CAX8R, about y) is a thin
//    disk, plane stress to O((H/r)²) with H = 0.1 of its half thickness, r ≥ 10;
//  - a unit cube at 1 ≤ x ≤ 2 built in at z = 0 and spinning about z: its base carries the whole
//    load, Σ RF = −ρω² ∫ (x, y) dV = −ρω² (1.5, 0.5) (the load is linear in x, so the
//    consistent nodal forces integrate it exactly).
#include "verification_fixture.hpp"

#include <cmath>

namespace inpact::verification {
namespace {

constexpr double ri = 10.0, ro = 20.0, rho = 7.8e-9, omega2 = 1.0e6;

/// Radial displacement of the plane-stress spinning disk (as gen_verification.py).
double disk_u_r(double r) {
  const double nu = 0.3, E = 210000.0, a = ri, b = ro;
  const double C = (3 + nu) / 8 * rho * omega2;
  const double s_r = C * (a * a + b * b - a * a * b * b / (r * r) - r * r);
  const double s_t = C * (a * a + b * b + a * a * b * b / (r * r) - (1 + 3 * nu) / (3 + nu) * r * r);
  return r * (s_t - nu * s_r) / E;
}

/// The worst relative u_r error over the nodes at the bore and at the rim.
double worst_disk_error(const char* deck, bool axisymmetric) {
  const auto r = run_deck(deck_path(deck));
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
  if (!r->outcome.completed) return 1.0;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  double worst = 0;
  int n_edge = 0;
  for (std::size_t n = 0; n < m.mesh.nodes.size(); ++n) {
    const auto x = coords(m, static_cast<std::int32_t>(n));
    const double rad = axisymmetric ? x[0] : std::hypot(x[0], x[1]);
    if (std::abs(rad - ri) > 1e-6 && std::abs(rad - ro) > 1e-6) continue;
    const double u1 = nodal(f, "U", n, 0), u2 = nodal(f, "U", n, 1);
    const double ur = axisymmetric ? u1 : (u1 * x[0] + u2 * x[1]) / rad;
    worst = std::max(worst, std::abs(ur / disk_u_r(rad) - 1.0));
    ++n_edge;
  }
  EXPECT_GT(n_edge, 2) << deck;
  report(std::string(deck) + ": u_r at bore and rim, worst relative error", worst);
  return worst;
}

// Measured: CPS8 8×8 7.3e-6, CAX8R 8×1 8.8e-6 (the thin-disk approximation is below the mesh error).
TEST(CentrifugalLoad, SpinningDiskMatchesThePlaneStressSolution) {
  EXPECT_LE(worst_disk_error("spinning_disk_cps8.inp", false), 1e-4);
  EXPECT_LE(worst_disk_error("spinning_disk_cax8r.inp", true), 1e-4);
}

TEST(CentrifugalLoad, BuiltInBaseCarriesTheWholeCentrifugalForce) {
  const auto r = run_deck(deck_path("spinning_block_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double load = rho * omega2;
  expect_balance(*r, r->capture.last(), {1.5 * load, 0.5 * load, 0.0}, 1e-12, "spinning cube");
}

}  // namespace
}  // namespace inpact::verification
