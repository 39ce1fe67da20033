// Case 9a: a bar in uniaxial tension with Mises plasticity and linear hardening, loaded then
// unloaded (decks/verification/plastic_bar_c3d8.inp: 4 × 1 × 1, 4 C3D8, symmetry planes; and
// plastic_plate_cps4.inp, the same as a plane-stress plate of 4 CPS4).
// E = 200000, ν = 0.3, σ_y = 250 + H ε̄ᵖ, H = 20000, E_t = E H/(E + H).
//  Step LOAD (10 increments): the end driven to strain ε(t) = 8e-3 t; closed form
//    σ = E ε (ε ≤ ε_y = σ_y/E), σ = σ_y + E_t (ε − ε_y) beyond; εᵖ = (σ − σ_y)/H.
//  Step UNLOAD (4 increments): the end released, its reaction ramps to zero: σ = σ_max (1 − t),
//    elastic; at the end σ = 0, PEEQ = PE11 = εᵖ_max, PE22 = PE33 = −εᵖ_max/2 and the end at
//    u1 = L εᵖ_max (zero stress: the strain left is the plastic one).
// The homogeneous field is in the element space and backward Euler is exact on this radial
// path: every value exact to round-off (tolerance 1e-10 relative, stated per check).
#include <cmath>
#include <fstream>
#include <iterator>
#include <tuple>

#include "fixtures/deck_fixture.hpp"

#include "verification_fixture.hpp"

namespace inpact::verification {
namespace {

constexpr double E = 200000.0, nu = 0.3, sy = 250.0, H = 20000.0, L = 4.0, eps_max = 8e-3;

double face_u1(const Run& r, const solver::Frame& f, const char* set) {
  double s = 0;
  const auto rows = nset(r.model(), set);
  for (std::int32_t n : rows) s += nodal(f, "U", static_cast<std::size_t>(n), 0);
  return s / static_cast<double>(rows.size());
}

/// The largest deviation of component c of a point field from `want` over every point.
double worst_of(const Run& r, const solver::Frame& f, const std::string& key, int c, double want) {
  double worst = 0;
  for (const auto& p : point_values(r, f, key)) worst = std::max(worst, std::abs(p.s[static_cast<std::size_t>(c)] - want));
  return worst;
}

/// `thickness_strain`: whether the deck's elements report E33 (a shell's section points do not).
void check_bar(const std::string& deck, bool thickness_strain = true) {
  SCOPED_TRACE(deck);
  const auto r = run_deck(deck_path(deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  const double Et = E * H / (E + H), eps_y = sy / E;
  const double s_max = sy + Et * (eps_max - eps_y), ep_max = (s_max - sy) / H;
  const double tol = 1e-10;  // relative to σ_y for stresses, to εᵖ_max for strains
  double worst_s = 0, worst_ep = 0;

  const auto load = r->capture.of_step(1);
  ASSERT_EQ(load.size(), 10u);
  for (const auto* f : load) {
    const double eps = eps_max * f->step_time;
    const double s = eps <= eps_y ? E * eps : sy + Et * (eps - eps_y);
    const double ep = std::max(0.0, (s - sy) / H);
    const double ds = std::max({worst_of(*r, *f, "S", 0, s), worst_of(*r, *f, "S", 1, 0.0), worst_of(*r, *f, "S", 3, 0.0)});
    const double dep = std::max({worst_of(*r, *f, "PEEQ", 0, ep), worst_of(*r, *f, "PE", 0, ep),
                                 worst_of(*r, *f, "PE", 1, -ep / 2), worst_of(*r, *f, "PEMAG", 0, ep)});
    EXPECT_LE(ds, tol * sy) << "LOAD t = " << f->step_time;
    EXPECT_LE(dep, tol * ep_max) << "LOAD t = " << f->step_time;
    // Total strain E11 = ε exactly (prescribed), lateral E22 = E33 = −ν σ/E − εᵖ/2 (in plane
    // stress E33 is the thickness strain of the material's σ33 = 0 iteration).
    EXPECT_LE(worst_of(*r, *f, "E", 1, -nu * s / E - ep / 2), tol * eps_max) << "LOAD t = " << f->step_time;
    if (thickness_strain) {
      EXPECT_LE(worst_of(*r, *f, "E", 2, -nu * s / E - ep / 2), tol * eps_max) << "LOAD t = " << f->step_time;
    }
    worst_s = std::max(worst_s, ds);
    worst_ep = std::max(worst_ep, dep);
  }
  const auto unload = r->capture.of_step(2);
  ASSERT_EQ(unload.size(), 4u);
  for (const auto* f : unload) {
    const double s = s_max * (1 - f->step_time);
    const double ds = worst_of(*r, *f, "S", 0, s);
    const double dep = std::max(worst_of(*r, *f, "PEEQ", 0, ep_max), worst_of(*r, *f, "PE", 0, ep_max));
    EXPECT_LE(ds, tol * sy) << "UNLOAD t = " << f->step_time;
    EXPECT_LE(dep, tol * ep_max) << "UNLOAD t = " << f->step_time;
    EXPECT_NEAR(face_u1(*r, *f, "RIGHT"), L * (s / E + ep_max), tol * L * eps_max) << "UNLOAD t = " << f->step_time;
    worst_s = std::max(worst_s, ds);
    worst_ep = std::max(worst_ep, dep);
  }
  const auto& end = *unload.back();
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * ep_max, tol * L * eps_max);  // the residual elongation
  EXPECT_LE(worst_of(*r, end, "PE", 2, -ep_max / 2), tol * ep_max);
  report(deck + ": worst |S11 - closed form| / sigma_y", worst_s / sy);
  report(deck + ": worst |PEEQ, PE - closed form| / eps_p_max", worst_ep / ep_max);
  expect_balance(*r, *load.back(), {0, 0, 0}, 1e-12, deck + " at full load");  // reactions only
}

TEST(PlasticBar, StressAtEveryIncrementAndResidualPlasticStrainAreExact) { check_bar("plastic_bar_c3d8.inp"); }

// The plane-stress plate: the same closed forms through the material's local σ33 = 0 iteration.
TEST(PlasticBar, PlaneStressPlateIsExactToo) { check_bar("plastic_plate_cps4.inp"); }

// The plate with the same curve as linear kinematic hardening through the Chaboche law (C = H,
// γ = 0): the same closed forms, through the plane-stress condensation of a 3D law.
TEST(PlasticBar, PlaneStressCombinedHardeningPlateIsExactToo) { check_bar("plastic_plate_combined_cps4.inp"); }

// The same plate of S4 shells held in their plane: each section point's plane-stress law (the
// Chaboche law through the condensation, as in the CPS4 plate) gives the same closed forms. Its
// *EL PRINT of S11, PE11 and PEEQ prints them at SNEG and SPOS: unloaded, 0, εᵖ_max, εᵖ_max.
TEST(PlasticBar, ShellMembraneWithCombinedHardeningIsExactToo) {
  check_bar("plastic_plate_combined_s4.inp", false);
  const auto r = run_deck(deck_path("plastic_plate_combined_s4.inp"));
  ASSERT_FALSE(r->capture.prints.empty());
  const solver::PrintTable& t = r->capture.prints.back().tables.at(0);
  ASSERT_TRUE(t.at_section_points);
  ASSERT_EQ(t.columns, (std::vector<std::string>{"S11", "PE11", "PEEQ"}));
  ASSERT_EQ(t.section_point.size(), 4u * 4 * 2);
  const double Et = E * H / (E + H), ep_max = (sy + Et * (eps_max - sy / E) - sy) / H;
  for (std::size_t row = 0; row < t.section_point.size(); ++row) {
    EXPECT_NEAR(t.values[3 * row], 0.0, 1e-10 * sy) << row;
    EXPECT_NEAR(t.values[3 * row + 1], ep_max, 1e-10 * ep_max) << row;
    EXPECT_NEAR(t.values[3 * row + 2], ep_max, 1e-10 * ep_max) << row;
  }
}

// The S4 plate again, perfectly plastic with a yield stress of its temperature, σ_y(T) = 200 − T
// (given at T = 0 and 100), at T = 50 + 80 z through its thickness (*INITIAL CONDITIONS with the
// gradient 80): stretched to 8 times the first yield strain, every section point flows at its own
// σ_y, Mises = 190 at SNEG (z = −0.5) and 110 at SPOS, to 1e-9. Isotropic, and kinematic with
// several temperatures (the Chaboche law's temperature sets). The points share the membrane's
// ε22 while their flow differs, so S22 is not zero at them: Mises, not S11, is the closed form.
TEST(PlasticBar, ShellSectionPointsYieldAtTheirOwnTemperature) {
  for (const std::string hardening : {"", ", HARDENING=KINEMATIC"}) {
    SCOPED_TRACE(hardening);
    std::ifstream in(deck_path("plastic_plate_combined_s4.inp"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string plastic = "*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250.0, 20000.0, 0.\n";
    ASSERT_NE(text.find(plastic), std::string::npos);
    text.replace(text.find(plastic), plastic.size(), "*PLASTIC" + hardening + "\n200., 0., 0.\n100., 0., 100.\n"
                 "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 50., 80.\n");
    const test::DeckDir dir;
    const auto r = run_deck(dir.write("deck.inp", text));
    ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
    const solver::FieldData& s = *field(*r->capture.of_step(1).back(), "S");
    const std::size_t n = s.component_labels.size();
    ASSERT_EQ(s.elements.size(), 4u * 4 * 2);  // SNEG and SPOS at 4 points of 4 elements
    for (std::size_t i = 0; i < s.elements.size(); ++i) {
      const double s11 = s.values[i * n], s22 = s.values[i * n + 1], s12 = s.values[i * n + 3];
      const double mises = std::sqrt(s11 * s11 - s11 * s22 + s22 * s22 + 3 * s12 * s12);
      EXPECT_NEAR(mises, s.section_point[i] == 1 ? 190.0 : 110.0, 1e-9 * 200) << "sp " << s.section_point[i];
    }
  }
}

// Case 9b: the same bar stretched to λ = 1.5 with NLGEOM (plastic_bar_nlgeom_c3d8.inp), the
// finite-strain law (solver/elements/finite_strain_mises.hpp), H = 1000 on the Kirchhoff stress.
// Closed form at LE11 = ln λ: ε̄ᵖ = (LE11 − σ_y/E)/(1 + H/E), τ = σ_y + H ε̄ᵖ, Cauchy S11 = τ/J,
// J = exp((1 − 2ν)τ/E), LE22 = −ν τ/E − ε̄ᵖ/2, the end's reaction τ A0/λ. The path is proportional
// with fixed principal axes, where the exponential map is exact: every value to round-off
// (1e-10 relative). Unloading is elastic to zero stress: the end at L(exp ε̄ᵖ − 1).
void check_nlgeom_bar(const std::string& deck) {
  SCOPED_TRACE(deck);
  const auto r = run_deck(deck_path(deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double Hn = 1000.0, tol = 1e-10;
  double worst_s = 0, worst_e = 0;
  const auto load = r->capture.of_step(1);
  ASSERT_EQ(load.size(), 20u);
  double ep_end = 0;
  for (const auto* f : load) {
    const double lambda = 1 + 0.5 * f->step_time, le = std::log(lambda);
    const double ep = std::max(0.0, (le - sy / E) / (1 + Hn / E));
    const double tau = ep > 0 ? sy + Hn * ep : E * le;
    const double cauchy = tau / std::exp((1 - 2 * nu) * tau / E);
    const double ds = std::max({worst_of(*r, *f, "S", 0, cauchy), worst_of(*r, *f, "S", 1, 0.0), worst_of(*r, *f, "S", 3, 0.0)});
    const double de = std::max({worst_of(*r, *f, "E", 0, le), worst_of(*r, *f, "E", 1, -nu * tau / E - ep / 2),
                                worst_of(*r, *f, "LE", 0, le), worst_of(*r, *f, "LE", 2, -nu * tau / E - ep / 2),
                                worst_of(*r, *f, "PEEQ", 0, ep), worst_of(*r, *f, "PE", 0, ep), worst_of(*r, *f, "PE", 2, -ep / 2)});
    EXPECT_LE(ds, tol * sy) << "t = " << f->step_time;
    EXPECT_LE(de, tol * le) << "t = " << f->step_time;
    double reaction = 0;
    for (std::int32_t n : nset(r->model(), "RIGHT")) reaction += nodal(*f, "RF", static_cast<std::size_t>(n), 0);
    EXPECT_NEAR(reaction, tau * 1.0 / lambda, tol * sy) << "t = " << f->step_time;
    worst_s = std::max(worst_s, ds);
    worst_e = std::max(worst_e, de);
    ep_end = ep;
  }
  const auto& end = *r->capture.of_step(2).back();
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * (std::exp(ep_end) - 1), tol * L);
  EXPECT_LE(worst_of(*r, end, "S", 0, 0.0), tol * sy);
  EXPECT_LE(worst_of(*r, end, "E", 0, ep_end), tol * ep_end);
  report(deck + ": worst |S11 - closed form| / sigma_y", worst_s / sy);
  report(deck + ": worst |LE, PE, PEEQ - closed form| / LE11", worst_e);
}

TEST(PlasticBar, LargeStrainNlgeomBarFollowsTheClosedForm) { check_nlgeom_bar("plastic_bar_nlgeom_c3d8.inp"); }

// The same as a plane-stress plate (CPS4): the exponential-map law through the plane-stress
// condensation (S33 = 0 at each point, solved in ln λ3), LE33 = LE22 from the thickness stretch.
TEST(PlasticBar, LargeStrainNlgeomPlaneStressPlateFollowsTheClosedForm) {
  check_nlgeom_bar("plastic_bar_nlgeom_cps4.inp");
}

// Case 9c: combined (Chaboche) hardening with a Voce surface (plastic_bar_combined_c3d8.inp):
// one plastic increment from the virgin state, where backward Euler gives a closed form
// (the deck's header), then released elastically. Exact to round-off (1e-10 relative).
TEST(PlasticBar, CombinedHardeningBarFollowsTheBackwardEulerClosedForm) {
  const auto r = run_deck(deck_path("plastic_bar_combined_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double dg = 0.002, tol = 1e-10;
  const double x = 40000.0 * dg / (1 + 400.0 * dg), s = 250.0 + 80.0 * (1 - std::exp(-10.0 * dg)) + x;
  const auto& load = *r->capture.of_step(1).back();
  EXPECT_LE(worst_of(*r, load, "S", 0, s), tol * s);
  EXPECT_LE(worst_of(*r, load, "S", 1, 0.0), tol * s);
  EXPECT_LE(std::max(worst_of(*r, load, "PEEQ", 0, dg), worst_of(*r, load, "PE", 1, -dg / 2)), tol * dg);
  const auto& end = *r->capture.of_step(2).back();
  EXPECT_LE(worst_of(*r, end, "S", 0, 0.0), tol * s);
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * dg, tol * L * dg);
  report("plastic_bar_combined_c3d8: |S11 - closed form| / S11", worst_of(*r, load, "S", 0, s) / s);
}

// Case 9d: temperature-dependent yield curves (plastic_bar_temperature_c3d8.inp, the deck's
// header gives the data and the closed forms). Pulled at T = 20 (linear hardening H0), heated
// to 420 at fixed length: with s = (T − 20)/400, σ_y(ε̄ᵖ, T) = A(s) + B(s) ε̄ᵖ on the first
// segment of both curves, so ε̄ᵖ = (E ε − A)/(E + B), σ = E (ε − ε̄ᵖ) at every increment; cooled
// back (the surface grows: elastic, σ constant); released to zero stress. Exact to round-off
// (1e-10 relative). CalculiX 2.20 on the same deck prints the same S11 and PEEQ to its 7 digits
// through the pull, the heating and the cooling.
TEST(PlasticBar, TemperatureDependentYieldFollowsTheTemperatureAtFixedStrain) {
  const auto r = run_deck(deck_path("plastic_bar_temperature_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double eps = 4e-3, H0 = 500.0, tol = 1e-10;
  const auto pull = r->capture.of_step(1);
  ASSERT_EQ(pull.size(), 4u);
  for (const auto* f : pull) {
    const double e = eps * f->step_time, Et = E * H0 / (E + H0), ey = sy / E;
    const double s = e <= ey ? E * e : sy + Et * (e - ey);
    EXPECT_LE(worst_of(*r, *f, "S", 0, s), tol * sy) << "PULL t = " << f->step_time;
    EXPECT_LE(worst_of(*r, *f, "PEEQ", 0, std::max(0.0, (s - sy) / H0)), tol * eps) << "PULL t = " << f->step_time;
  }
  const auto heat = r->capture.of_step(2);
  ASSERT_EQ(heat.size(), 10u);
  double s_hot = 0, ep_hot = 0, worst = 0;
  for (const auto* f : heat) {
    const double t = f->step_time, A = 250.0 - 100.0 * t, B = 500.0 - 250.0 * t;
    ep_hot = (E * eps - A) / (E + B);
    s_hot = E * (eps - ep_hot);
    worst = std::max(worst, worst_of(*r, *f, "S", 0, s_hot));
    EXPECT_LE(worst_of(*r, *f, "S", 0, s_hot), tol * sy) << "HEAT t = " << t;
    EXPECT_LE(worst_of(*r, *f, "PEEQ", 0, ep_hot), tol * eps) << "HEAT t = " << t;
    EXPECT_LE(worst_of(*r, *f, "PE", 1, -ep_hot / 2), tol * eps) << "HEAT t = " << t;
  }
  for (const auto* f : r->capture.of_step(3)) {
    EXPECT_LE(worst_of(*r, *f, "S", 0, s_hot), tol * sy) << "COOL t = " << f->step_time;
    EXPECT_LE(worst_of(*r, *f, "PEEQ", 0, ep_hot), tol * eps) << "COOL t = " << f->step_time;
  }
  const auto& end = *r->capture.of_step(4).back();
  EXPECT_LE(worst_of(*r, end, "S", 0, 0.0), tol * sy);
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * ep_hot, tol * L * eps);
  report("plastic_bar_temperature_c3d8: worst |S11 - closed form| / sigma_y while heated", worst / sy);
}

// Case 9f: combined hardening given as half-cycle test data (plastic_bar_half_cycle_c3d8.inp):
// rows on σ|0 + C/γ (1 − e^{−γ ε̄ᵖ}) with C = 40000, γ = 400, from which the analysis fits C and
// γ; two single-increment plastic steps then give backward Euler's closed form, which depends
// on both (the deck's header). Exact to round-off (1e-10 relative) when the fit recovers them.
TEST(PlasticBar, HalfCycleDataGiveTheBackstressTheyWereSampledFrom) {
  const auto r = run_deck(deck_path("plastic_bar_half_cycle_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double C = 40000.0, g = 400.0, dg1 = 0.002, dg2 = 0.005, tol = 1e-10;
  const double x1 = C * dg1 / (1 + g * dg1), x2 = (x1 + C * (dg2 - dg1)) / (1 + g * (dg2 - dg1));
  double worst = 0;
  for (auto [step, x, dg] : {std::tuple{1, x1, dg1}, std::tuple{2, x2, dg2}}) {
    const auto& f = *r->capture.of_step(step).back();
    worst = std::max(worst, worst_of(*r, f, "S", 0, sy + x) / (sy + x));
    EXPECT_LE(worst_of(*r, f, "S", 0, sy + x), tol * (sy + x)) << "step " << step;
    EXPECT_LE(worst_of(*r, f, "PEEQ", 0, dg), tol * dg) << "step " << step;
  }
  const auto& end = *r->capture.of_step(3).back();
  EXPECT_LE(worst_of(*r, end, "S", 0, 0.0), tol * sy);
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * dg2, tol * L * dg2);
  report("plastic_bar_half_cycle_c3d8: |S11 - closed form| / S11", worst);
}

// Case 9g: linear kinematic hardening given at two temperatures
// (plastic_bar_kinematic_temperature_c3d8.inp, the deck's header): pulled at T = 20, heated to
// 420 at fixed length. Abaqus's backstress carries the term (1/C)(dC/dT) α Ṫ, so uniaxially
// X = C(T) ε̄ᵖ and ε̄ᵖ = (E ε − σ|0(T))/(E + C(T)) at every increment of the heating; released
// elastically. Exact to round-off (1e-10 relative).
TEST(PlasticBar, KinematicHardeningFollowsTheTemperatureOfItsModulus) {
  const auto r = run_deck(deck_path("plastic_bar_kinematic_temperature_c3d8.inp"));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double eps = 4e-3, tol = 1e-10;
  auto plastic_strain = [&](double s) { return (E * eps - (250.0 - 100.0 * s)) / (E + 20000.0 - 10000.0 * s); };
  const auto& pulled = *r->capture.of_step(1).back();
  EXPECT_LE(worst_of(*r, pulled, "PEEQ", 0, plastic_strain(0.0)), tol * eps);
  const auto heat = r->capture.of_step(2);
  ASSERT_EQ(heat.size(), 10u);
  double worst = 0;
  for (const auto* f : heat) {
    const double ep = plastic_strain(f->step_time), s = E * (eps - ep);
    worst = std::max(worst, worst_of(*r, *f, "S", 0, s) / sy);
    EXPECT_LE(worst_of(*r, *f, "S", 0, s), tol * sy) << "HEAT t = " << f->step_time;
    EXPECT_LE(worst_of(*r, *f, "PEEQ", 0, ep), tol * eps) << "HEAT t = " << f->step_time;
    EXPECT_LE(worst_of(*r, *f, "PE", 1, -ep / 2), tol * eps) << "HEAT t = " << f->step_time;
  }
  const auto& end = *r->capture.of_step(3).back();
  EXPECT_LE(worst_of(*r, end, "S", 0, 0.0), tol * sy);
  EXPECT_NEAR(face_u1(*r, end, "RIGHT"), L * plastic_strain(1.0), tol * L * eps);
  report("plastic_bar_kinematic_temperature_c3d8: worst |S11 - closed form| / sigma_y while heated", worst);
}

// Case 9e: linear kinematic hardening at large strain (plastic_bar_nlgeom_kinematic_c3d8.inp), the
// law in the Lagrangian logarithmic strain (log_strain_plasticity.hpp). The principal axes stay
// fixed, so in LE11 = ln λ it is the 1D small-strain law with τ the Kirchhoff stress (the deck's
// header): stretched to λ = 1.5, then pushed back to λ = 1.1 through elastic unloading and
// reversed yield at τ_max − 2σ⁰ (Bauschinger). Every increment to round-off (1e-10 relative).
void check_nlgeom_kinematic_bar(const std::string& deck) {
  SCOPED_TRACE(deck);
  const auto r = run_deck(deck_path(deck));
  ASSERT_TRUE(r->outcome.completed) << r->outcome.message;
  constexpr double C = 1000.0, tol = 1e-10;
  double ep_max = 0, tau_max = 0, worst = 0;
  bool reversed_yield = false;
  auto check = [&](const solver::Frame& f, double lambda, double ep, double peeq, double tau, const char* step) {
    const double le = std::log(lambda), cauchy = tau / std::exp((1 - 2 * nu) * tau / E);
    const double ds = std::max(worst_of(*r, f, "S", 0, cauchy), worst_of(*r, f, "S", 1, 0.0));
    const double de = std::max({worst_of(*r, f, "LE", 0, le), worst_of(*r, f, "LE", 1, -nu * tau / E - ep / 2),
                                worst_of(*r, f, "PE", 0, ep), worst_of(*r, f, "PEEQ", 0, peeq)});
    EXPECT_LE(ds, tol * sy) << step << " t = " << f.step_time;
    EXPECT_LE(de, tol * std::log(1.5)) << step << " t = " << f.step_time;
    double reaction = 0;
    for (std::int32_t n : nset(r->model(), "RIGHT")) reaction += nodal(f, "RF", static_cast<std::size_t>(n), 0);
    EXPECT_NEAR(reaction, tau / lambda, tol * sy) << step << " t = " << f.step_time;
    worst = std::max(worst, ds);
  };
  const auto load = r->capture.of_step(1);
  ASSERT_EQ(load.size(), 20u);
  for (const auto* f : load) {
    const double lambda = 1 + 0.5 * f->step_time, le = std::log(lambda);
    ep_max = std::max(0.0, (le - sy / E) / (1 + C / E));
    tau_max = ep_max > 0 ? sy + C * ep_max : E * le;
    check(*f, lambda, ep_max, ep_max, tau_max, "LOAD");
  }
  const auto reverse = r->capture.of_step(2);
  ASSERT_EQ(reverse.size(), 20u);
  for (const auto* f : reverse) {
    const double lambda = 1.5 - 0.4 * f->step_time, le = std::log(lambda);
    double tau = E * (le - ep_max), ep = ep_max;
    if (tau < tau_max - 2 * sy) {  // reversed yield: τ = C εᵖ − σ⁰
      ep = (le + sy / E) / (1 + C / E);
      tau = C * ep - sy;
      reversed_yield = true;
    }
    check(*f, lambda, ep, ep_max + (ep_max - ep), tau, "REVERSE");
  }
  EXPECT_TRUE(reversed_yield);
  report(deck + ": worst |S11 - closed form| / sigma_y", worst / sy);
}

TEST(PlasticBar, KinematicHardeningAtLargeStrainReversesYieldAtTwiceTheInitialYieldStress) {
  check_nlgeom_kinematic_bar("plastic_bar_nlgeom_kinematic_c3d8.inp");
}

TEST(PlasticBar, KinematicHardeningAtLargeStrainInPlaneStressToo) {
  check_nlgeom_kinematic_bar("plastic_bar_nlgeom_kinematic_cps4.inp");
}

}  // namespace
}  // namespace inpact::verification
