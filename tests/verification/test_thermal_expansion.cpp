// Case 3: thermal expansion (*INITIAL CONDITIONS, TYPE=TEMPERATURE; *TEMPERATURE in the step;
// *EXPANSION). E = 200000, ν = 0.3, α = 1.2e-5, T: 20 → 120 (ΔT = 100).
//  - A free ring (quarter, plane stress CPS8; axisymmetric CAX4 with only z = 0 held):
//    stress free, u_r = α ΔT r (and u_z = α ΔT z). Exact in the element space (linear field):
//    tolerance 1e-9 relative on U, |S| ≤ 1e-9 · E α ΔT.
//  - A bar held at both ends (C3D8, quarter with symmetry planes, lateral faces free):
//    σ11 = −E α ΔT = −240, σ22 = σ33 = 0, u2 = (1+ν) α ΔT y, RF1 on x = L = −E α ΔT · a².
#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double E = 200000.0, nu = 0.3, alpha = 1.2e-5, dT = 100.0;

void free_ring(const char* deck, bool axisymmetric) {
  const auto r = run_deck(deck_path(deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  double worst_u = 0, umax = 0;
  for (std::size_t n = 0; n < r->model().mesh.nodes.size(); ++n) {
    const auto x = coords(r->model(), static_cast<std::int32_t>(n));
    for (int c = 0; c < 2; ++c) {
      const double exact = alpha * dT * x[c];  // u_r = αΔT r ⇔ u = αΔT x (and u_z = αΔT z)
      worst_u = std::max(worst_u, std::abs(nodal(f, "U", n, c) - exact));
      umax = std::max(umax, std::abs(exact));
    }
  }
  const double s = max_abs(point_values(*r, f, "S"));
  report(std::string(deck) + ": max |U - alpha dT x| / max |U|", worst_u / umax);
  report(std::string(deck) + ": max |S| / (E alpha dT)", s / (E * alpha * dT));
  EXPECT_LE(worst_u, 1e-9 * umax) << deck;
  EXPECT_LE(s, 1e-9 * E * alpha * dT) << deck;
  // Case 5: no load, so the reactions sum to zero (they are zero up to round-off); the
  // scale is E α ΔT (the stress scale) for this stress-free problem.
  const auto rf = sum_rf(*r, f);
  for (int c = 0; c < 2; ++c) {
    if (axisymmetric && c == 0) continue;  // radial direction: hoop equilibrium, see Lamé test
    EXPECT_LE(std::abs(rf[c]), 1e-9 * E * alpha * dT) << deck << " direction " << c + 1;
  }
  report(std::string(deck) + ": |sum RF| / (E alpha dT)", std::abs(rf[1]) / (E * alpha * dT));
}

TEST(ThermalExpansion, FreePlaneStressRingExpandsStressFree) { free_ring("thermal_ring_cps8.inp", false); }
TEST(ThermalExpansion, FreeAxisymmetricRingExpandsStressFree) { free_ring("thermal_ring_cax4.inp", true); }

TEST(ThermalExpansion, BarHeldAtBothEndsCarriesMinusEAlphaDeltaT) {
  const auto r = run_deck(deck_path("thermal_bar_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const auto& f = r->capture.last();
  const double s_exact = -E * alpha * dT;
  double worst_s = 0;
  for (const auto& p : point_values(*r, f, "S")) {
    worst_s = std::max(worst_s, std::abs(p.s[0] - s_exact));
    for (int c = 1; c < 6; ++c) worst_s = std::max(worst_s, std::abs(p.s[c]));
  }
  report("thermal bar: max |S - (-E alpha dT, 0...)| / (E alpha dT)", worst_s / (E * alpha * dT));
  EXPECT_LE(worst_s, 1e-9 * E * alpha * dT);
  double worst_u = 0;
  for (std::size_t n = 0; n < r->model().mesh.nodes.size(); ++n) {
    const auto x = coords(r->model(), static_cast<std::int32_t>(n));
    worst_u = std::max({worst_u, std::abs(nodal(f, "U", n, 0)),
                        std::abs(nodal(f, "U", n, 1) - (1 + nu) * alpha * dT * x[1]),
                        std::abs(nodal(f, "U", n, 2) - (1 + nu) * alpha * dT * x[2])});
  }
  report("thermal bar: max |U - exact| / ((1+nu) alpha dT a)", worst_u / ((1 + nu) * alpha * dT));
  EXPECT_LE(worst_u, 1e-9 * (1 + nu) * alpha * dT);
  // Reaction on the x = L face: the wall pushes the bar back, −E α ΔT · a² (a = 1) in x.
  double rf_end = 0;
  for (std::int32_t n : nset(r->model(), "END1")) rf_end += nodal(f, "RF", static_cast<std::size_t>(n), 0);
  report("thermal bar: RF1(x = L) relative error", std::abs(rf_end - s_exact) / (E * alpha * dT));
  EXPECT_NEAR(rf_end, s_exact, 1e-9 * E * alpha * dT);
  expect_balance(*r, f, {0.0, 0.0, 0.0}, 1e-12, "thermal bar");
}

}  // namespace
}  // namespace inpact::verification
