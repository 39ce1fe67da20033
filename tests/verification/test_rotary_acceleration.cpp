// Case 10: the rotary acceleration load (*DLOAD ROTA, the d'Alembert force −ρα n × r).
//
// References (gen_verification.py, section 10):
//  - an annular disk held at its bore, free at its rim, accelerated about its axis: pure shear
//    with u_θ = r ρα/(8G) (r² − a² + b⁴ (1/r² − 1/a²)) and u_r = 0 (closed form from the
//    equilibrium (r² τ)' = ρα r³ with τ(b) = 0);
//  - the unit cube at 1 ≤ x ≤ 2 built in at z = 0 accelerated about z: its base carries the
//    whole load, Σ RF = −ρα (∫y dV, −∫x dV, 0) = −ρα (0.5, −1.5, 0) exactly (the load is linear
//    in x and the consistent nodal forces integrate it exactly).
#include "verification_fixture.hpp"

#include <cmath>

namespace inpact::verification {
namespace {

constexpr double ri = 10.0, ro = 20.0, rho = 7.8e-9, alpha = 1.0e6;

double disk_u_theta(double r) {
  const double E = 210000.0, nu = 0.3, G = E / (2 * (1 + nu)), a = ri, b = ro;
  return r * rho * alpha / (8 * G) * (r * r - a * a + std::pow(b, 4) * (1 / (r * r) - 1 / (a * a)));
}

// Measured: CPS8 4×16: worst u_θ 1.3e-4 of the rim's u_θ; u_r 3e-15 (zero by symmetry, to round-off).
TEST(RotaryAcceleration, HeldDiskShearsAsTheClosedForm) {
  const auto r = run_deck(deck_path("accelerating_disk_cps8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& m = r->model();
  const auto& f = r->capture.last();
  const double rim = disk_u_theta(ro);
  double worst_theta = 0, worst_radial = 0;
  for (std::size_t n = 0; n < m.mesh.nodes.size(); ++n) {
    const auto x = coords(m, static_cast<std::int32_t>(n));
    const double rad = std::hypot(x[0], x[1]);
    const double u1 = nodal(f, "U", n, 0), u2 = nodal(f, "U", n, 1);
    const double u_theta = (-u1 * x[1] + u2 * x[0]) / rad, u_r = (u1 * x[0] + u2 * x[1]) / rad;
    worst_theta = std::max(worst_theta, std::abs(u_theta - disk_u_theta(rad)) / std::abs(rim));
    worst_radial = std::max(worst_radial, std::abs(u_r) / std::abs(rim));
  }
  report("accelerating disk CPS8 4x16: worst |u_theta - exact| / |u_theta(rim)|", worst_theta);
  report("accelerating disk CPS8 4x16: worst |u_r| / |u_theta(rim)|", worst_radial);
  EXPECT_LT(rim, 0.0);  // the d'Alembert force acts against the acceleration
  EXPECT_LE(worst_theta, 1e-3);
  EXPECT_LE(worst_radial, 1e-12);
}

TEST(RotaryAcceleration, BuiltInBaseCarriesTheWholeLoad) {
  const auto r = run_deck(deck_path("accelerating_block_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double load = rho * alpha;
  expect_balance(*r, r->capture.last(), {0.5 * load, -1.5 * load, 0.0}, 1e-12, "accelerated cube");
}

}  // namespace
}  // namespace inpact::verification
