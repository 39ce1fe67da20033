// A shell layer's lamina (shell_lamina.hpp): plane-stress condensation and the turn into the
// shell's axes against the textbook formulas for a ply at 45° (Jones, Mechanics of Composite
// Materials, §2.6).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/elements/shell_lamina.hpp"
#include "model/elastic_stiffness.hpp"

using namespace inpact;
using namespace inpact::solver::elements;

namespace {

model::Elastic engineering_constants() {
  model::Elastic e;
  e.type = model::Elastic::Type::EngineeringConstants;
  // E1, E2, E3, ν12, ν13, ν23, G12, G13, G23
  e.constants = {1.4e5, 1e4, 1.2e4, 0.3, 0.25, 0.4, 5e3, 4e3, 3e3};
  return e;
}

}  // namespace

// Condensed for σ33 = 0, an orthotropic material gives the lamina's Q: Q11 = E1/(1 − ν12ν21),
// Q12 = ν12 E2/(1 − ν12ν21), Q22 = E2/(1 − ν12ν21), Q66 = G12, and G13, G23.
TEST(ShellLamina, PlaneStressCondensationGivesTheLaminaStiffness) {
  const ShellLamina l = condensed_lamina(model::material_stiffness(engineering_constants()), false, 0.0);
  const double nu21 = 0.3 * 1e4 / 1.4e5, den = 1 - 0.3 * nu21;
  EXPECT_NEAR(l.in_plane[0][0], 1.4e5 / den, 1e-9 * 1.4e5);
  EXPECT_NEAR(l.in_plane[0][1], 0.3 * 1e4 / den, 1e-9 * 1.4e5);
  EXPECT_NEAR(l.in_plane[1][1], 1e4 / den, 1e-9 * 1.4e5);
  EXPECT_NEAR(l.in_plane[2][2], 5e3, 1e-9 * 1.4e5);
  EXPECT_NEAR(l.in_plane[0][2], 0.0, 1e-9 * 1.4e5);
  EXPECT_NEAR(l.shear[0][0], 4e3, 1e-9 * 1e4);
  EXPECT_NEAR(l.shear[1][1], 3e3, 1e-9 * 1e4);
  // TYPE=LAMINA with the same in-plane constants gives the same Q.
  model::Elastic lamina;
  lamina.type = model::Elastic::Type::Lamina;
  lamina.constants = {1.4e5, 1e4, 0.3, 5e3, 4e3, 3e3};
  const ShellLamina given = condensed_lamina(model::material_stiffness(lamina), true, 0.0);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(given.in_plane[a][b], l.in_plane[a][b], 1e-9 * 1.4e5) << a << b;
}

// Q̄ at θ = 45°: Q̄11 = Q̄22 = (Q11 + Q22 + 2Q12 + 4Q66)/4, Q̄12 = (Q11 + Q22 − 4Q66)/4 + Q12/2,
// Q̄66 = (Q11 + Q22 − 2Q12)/4, Q̄16 = Q̄26 = (Q11 − Q22)/4; Ḡ = (G13 + G23)/2 ± (G13 − G23)/2.
TEST(ShellLamina, APlyAt45DegreesMatchesTheTransformedStiffness) {
  const ShellLamina l = condensed_lamina(model::material_stiffness(engineering_constants()), false, 0.0);
  const double q11 = l.in_plane[0][0], q22 = l.in_plane[1][1], q12 = l.in_plane[0][1], q66 = l.in_plane[2][2];
  const ShellLamina t = turned_lamina(l, std::numbers::pi / 4);
  const double tol = 1e-9 * q11;
  EXPECT_NEAR(t.in_plane[0][0], (q11 + q22 + 2 * q12 + 4 * q66) / 4, tol);
  EXPECT_NEAR(t.in_plane[1][1], (q11 + q22 + 2 * q12 + 4 * q66) / 4, tol);
  EXPECT_NEAR(t.in_plane[0][1], (q11 + q22 - 4 * q66) / 4 + q12 / 2, tol);
  EXPECT_NEAR(t.in_plane[2][2], (q11 + q22 - 2 * q12) / 4, tol);
  EXPECT_NEAR(t.in_plane[0][2], (q11 - q22) / 4, tol);
  EXPECT_NEAR(t.in_plane[1][2], (q11 - q22) / 4, tol);
  EXPECT_NEAR(t.shear[0][0], 3.5e3, 1e-9 * 4e3);
  EXPECT_NEAR(t.shear[1][1], 3.5e3, 1e-9 * 4e3);
  EXPECT_NEAR(t.shear[0][1], 0.5e3, 1e-9 * 4e3);
}

// The stress a turned ply gives in the shell's axes, turned back into the ply's axes, is the
// ply's own Q applied to the strains turned into them.
TEST(ShellLamina, StressesAndStrainsTurnConsistently) {
  const ShellLamina l = condensed_lamina(model::material_stiffness(engineering_constants()), false, 0.0);
  const double theta = 0.7;
  const ShellLamina t = turned_lamina(l, theta);
  const std::array<double, 5> e = {1e-3, -4e-4, 7e-4, 2e-4, -3e-4};
  std::array<double, 5> s{};
  for (int a = 0; a < 3; ++a) s[a] = t.in_plane[a][0] * e[0] + t.in_plane[a][1] * e[1] + t.in_plane[a][2] * e[2];
  for (int a = 0; a < 2; ++a) s[3 + a] = t.shear[a][0] * e[3] + t.shear[a][1] * e[4];
  const std::array<double, 5> sm = stresses_in_material_axes(s, theta), em = strains_in_material_axes(e, theta);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(sm[a], l.in_plane[a][0] * em[0] + l.in_plane[a][1] * em[1] + l.in_plane[a][2] * em[2], 1e-9) << a;
  for (int a = 0; a < 2; ++a) EXPECT_NEAR(sm[3 + a], l.shear[a][0] * em[3] + l.shear[a][1] * em[4], 1e-9) << a;
}
