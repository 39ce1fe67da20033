// Case 3b: temperature-dependent *ELASTIC and *EXPANSION (decks thermal_table_*.inp, written by
// gen_verification.py). E, ν and α are linear between the rows and held outside them (Abaqus);
// the thermal strain is the secant one from ZERO less its value at the initial temperature,
//   ε_th = α(T)(T − T⁰) − α(Tᴵ)(Tᴵ − T⁰),   T⁰ = 20, Tᴵ = 150,
// at T = 400 (inside the tables), 1300 (above them) and −100 (below them), one step each.
//  - A free C3D8 bar (symmetry planes only): stress free, U = ε_th x, E = ε_th I. Exact in the
//    element space: 1e-12 of max |U|.
//  - Bars held at both ends along their axis, sides free: σ_axial = −E(T) ε_th (C3D8, CPS4,
//    CAX4; CPE4: σ11 = σ33 = −E ε_th/(1 − ν)), the lateral strain (1 + ν(T)) ε_th (CPE4:
//    (1 + ν)/(1 − ν) ε_th); CPS4's thickness strain E33 = (1 + ν(T)) ε_th. Stress to 1e-10 of
//    E ε_th, displacement and strain to 1e-10 of ε_th.
// The closed forms are evaluated here from the tables as written in the decks, not by the
// solver's functions.
#include <array>
#include <vector>

#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double kZero = 20.0, kInitial = 150.0;
constexpr std::array<double, 3> kSteps = {400.0, 1300.0, -100.0};

/// value(T) from (T, value) rows, linear between them and constant outside.
double interpolate(const std::vector<std::array<double, 2>>& rows, double T) {
  if (T <= rows.front()[0]) return rows.front()[1];
  if (T >= rows.back()[0]) return rows.back()[1];
  std::size_t i = 0;
  while (T > rows[i + 1][0]) ++i;
  const double w = (T - rows[i][0]) / (rows[i + 1][0] - rows[i][0]);
  return rows[i][1] + w * (rows[i + 1][1] - rows[i][1]);
}

double youngs(double T) { return interpolate({{0.0, 200000.0}, {500.0, 150000.0}, {1000.0, 100000.0}}, T); }
double poisson(double T) { return interpolate({{0.0, 0.30}, {500.0, 0.32}, {1000.0, 0.35}}, T); }
double alpha(double T) { return interpolate({{0.0, 1.0e-5}, {600.0, 1.4e-5}, {1200.0, 2.0e-5}}, T); }
double thermal_strain(double T) { return alpha(T) * (T - kZero) - alpha(kInitial) * (kInitial - kZero); }

TEST(ThermalTables, FreeBarExpandsByTheSecantThermalStrain) {
  const auto r = run_deck(deck_path("thermal_table_free_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  for (int step = 1; step <= 3; ++step) {
    const double T = kSteps[step - 1], eth = thermal_strain(T);
    const auto& f = *r->capture.of_step(step).back();
    double worst_u = 0, umax = 0;
    for (std::size_t n = 0; n < r->model().mesh.nodes.size(); ++n) {
      const auto x = coords(r->model(), static_cast<std::int32_t>(n));
      for (int c = 0; c < 3; ++c) {
        worst_u = std::max(worst_u, std::abs(nodal(f, "U", n, c) - eth * x[c]));
        umax = std::max(umax, std::abs(eth * x[c]));
      }
    }
    double worst_e = 0;
    for (const auto& p : point_values(*r, f, "E"))
      for (int c = 0; c < 6; ++c) worst_e = std::max(worst_e, std::abs(p.s[c] - (c < 3 ? eth : 0.0)));
    const double s = max_abs(point_values(*r, f, "S"));
    const std::string at = " at T = " + std::to_string(static_cast<int>(T));
    report("free table bar: max |U - eps_th x| / max |U|" + at, worst_u / umax);
    report("free table bar: max |E - eps_th I| / eps_th" + at, worst_e / std::abs(eth));
    report("free table bar: max |S| / (E eps_th)" + at, s / (youngs(T) * std::abs(eth)));
    EXPECT_LE(worst_u, 1e-12 * umax) << at;
    EXPECT_LE(worst_e, 1e-12 * std::abs(eth)) << at;
    EXPECT_LE(s, 1e-10 * youngs(T) * std::abs(eth)) << at;
  }
}

/// What a held deck must show: the axial stress component and value, the stressed transverse
/// component (CPE4's σ33), the lateral displacement direction and its strain factor, the
/// thickness strain (CPS4), in the deck's component order.
struct Held {
  const char* deck;
  int axial;        ///< stress component along the held axis
  int lateral;      ///< the free direction whose displacement is lateral_strain · x_lateral
  bool plane_strain;
  bool plane_stress;
};

void held_bar(const Held& h) {
  const auto r = run_deck(deck_path(h.deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const std::size_t n_comp = r->dim() == 3 ? 6 : 4;
  for (int step = 1; step <= 3; ++step) {
    const double T = kSteps[step - 1], eth = thermal_strain(T), E = youngs(T), nu = poisson(T);
    const double sigma = h.plane_strain ? -E * eth / (1 - nu) : -E * eth;
    const double lateral = h.plane_strain ? (1 + nu) / (1 - nu) * eth : (1 + nu) * eth;
    const auto& f = *r->capture.of_step(step).back();
    std::vector<double> s_exact(n_comp, 0.0);
    s_exact[static_cast<std::size_t>(h.axial)] = sigma;
    if (h.plane_strain) s_exact[2] = sigma;  // ε11 = ε33 = 0, σ22 = 0: σ33 = σ11 by symmetry
    double worst_s = 0;
    for (const auto& p : point_values(*r, f, "S"))
      for (std::size_t c = 0; c < n_comp; ++c) worst_s = std::max(worst_s, std::abs(p.s[c] - s_exact[c]));
    double worst_u = 0;
    for (std::size_t n = 0; n < r->model().mesh.nodes.size(); ++n) {
      const auto x = coords(r->model(), static_cast<std::int32_t>(n));
      worst_u = std::max(worst_u, std::abs(nodal(f, "U", n, h.lateral) - lateral * x[h.lateral]));
    }
    double worst_e33 = 0;
    if (h.plane_stress)
      for (const auto& p : point_values(*r, f, "E")) worst_e33 = std::max(worst_e33, std::abs(p.s[2] - lateral));
    const std::string at = std::string(h.deck) + " at T = " + std::to_string(static_cast<int>(T));
    report("max |S - S_exact| / (E eps_th), " + at, worst_s / std::abs(sigma));
    report("max |U_lat - (1+nu) eps_th x| / eps_th, " + at, worst_u / std::abs(eth));
    EXPECT_LE(worst_s, 1e-10 * std::abs(sigma)) << at;
    EXPECT_LE(worst_u, 1e-10 * std::abs(eth)) << at;
    if (h.plane_stress) {
      report("max |E33 - (1+nu) eps_th| / eps_th, " + at, worst_e33 / std::abs(eth));
      EXPECT_LE(worst_e33, 1e-10 * std::abs(eth)) << at;
    }
    expect_balance(*r, f, {0.0, 0.0, 0.0}, 1e-12, at);
  }
}

TEST(ThermalTables, HeldC3D8BarCarriesMinusEOfTThermalStrain) {
  held_bar({"thermal_table_held_c3d8.inp", 0, 1, false, false});
}
TEST(ThermalTables, HeldPlaneStressBarThicknessStrainTakesNuOfT) {
  held_bar({"thermal_table_held_cps4.inp", 0, 1, false, true});
}
TEST(ThermalTables, HeldPlaneStrainBarCarriesTheConstrainedStress) {
  held_bar({"thermal_table_held_cpe4.inp", 0, 1, true, false});
}
TEST(ThermalTables, HeldAxisymmetricTubeCarriesMinusEOfTThermalStrain) {
  held_bar({"thermal_table_held_cax4.inp", 1, 0, false, false});
}

}  // namespace
}  // namespace inpact::verification
