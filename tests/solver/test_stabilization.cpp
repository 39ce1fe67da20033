// *STATIC, STABILIZE: the parameters as parsed, and the viscous forces F_v = c M* Δu/Δt, their
// tangent c M*/Δt, the dissipated energy and ALLSE on one unit cube, against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/assembler.hpp"
#include "solver/dof_map.hpp"
#include "solver/stabilization.hpp"
#include "solver/step_conditions.hpp"

using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;
namespace solver = inpact::solver;

namespace {

std::string static_step(const std::string& line) {
  return "*BOUNDARY\n1, 1, 3\n*STEP\n" + line + "\n*END STEP\n";
}

TEST(StabilizeKeyword, DefaultsAndValues) {
  DeckDir dir;
  auto plain = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE")));
  ASSERT_TRUE(plain.ok()) << plain.report();
  const auto& s = plain.model.steps[0].static_procedure->stabilize;
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(s->energy_fraction, 2e-4);  // Abaqus's default dissipated energy fraction
  EXPECT_FALSE(s->damping_factor);
  EXPECT_FALSE(s->allsdtol);
  EXPECT_FALSE(s->continue_previous);

  auto given = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE=1e-3, ALLSDTOL=0.05, CONTINUE=YES")));
  ASSERT_TRUE(given.ok()) << given.report();
  const auto& g = *given.model.steps[0].static_procedure->stabilize;
  EXPECT_DOUBLE_EQ(g.energy_fraction, 1e-3);
  EXPECT_DOUBLE_EQ(*g.allsdtol, 0.05);
  EXPECT_TRUE(g.continue_previous);

  auto factor = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE, FACTOR=3.5")));
  ASSERT_TRUE(factor.ok()) << factor.report();
  EXPECT_DOUBLE_EQ(*factor.model.steps[0].static_procedure->stabilize->damping_factor, 3.5);

  auto bare = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE, ALLSDTOL")));
  ASSERT_TRUE(bare.ok()) << bare.report();
  EXPECT_DOUBLE_EQ(*bare.model.steps[0].static_procedure->stabilize->allsdtol, 0.05);
  auto off = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE, ALLSDTOL=0")));
  ASSERT_TRUE(off.ok()) << off.report();
  EXPECT_FALSE(off.model.steps[0].static_procedure->stabilize->allsdtol);

  auto none = dir.read(one_cube_deck(static_step("*STATIC")));
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none.model.steps[0].static_procedure->stabilize);
}

TEST(StabilizeKeyword, Errors) {
  DeckDir dir;
  auto no_stabilize = dir.read(one_cube_deck(static_step("*STATIC, FACTOR=2.")));
  EXPECT_FALSE(no_stabilize.ok());
  EXPECT_TRUE(has_diagnostic(no_stabilize, "FACTOR needs STABILIZE")) << no_stabilize.report();
  auto negative = dir.read(one_cube_deck(static_step("*STATIC, STABILIZE=-1.")));
  EXPECT_FALSE(negative.ok());
  EXPECT_TRUE(has_diagnostic(negative, "must be positive")) << negative.report();
}

/// The unit cube with node 1 fixed in x, y, z: its DOF map and assembler.
struct OneCube {
  OneCube() : read(dir.read(one_cube_deck(static_step("*STATIC, STABILIZE")))), am(solver::build_analysis_model(read.model)),
              conditions(am, read.model.steps[0], solver::initial_history(am), 0.0),
              dofs(solver::DofMap::build(am, conditions.prescribed())), assembler(am, dofs) {}
  DeckDir dir;
  inpact::parser::ReadResult read;
  solver::AnalysisModel am;
  solver::StepConditions conditions;
  solver::DofMap dofs;
  solver::Assembler assembler;

  std::vector<double> mass() {
    std::vector<double> u(am.n_dof(), 0.0), f(am.n_dof());
    assembler.assemble(u, {.tangent = false, .nlgeom = false, .delta_t = {}, .points = true}, f);
    return solver::unit_density_lumped_mass(am, *assembler.points_at(u, {}, false));
  }
};

TEST(Stabilization, LumpedUnitDensityMassOfACube) {
  OneCube cube;
  const std::vector<double> m = cube.mass();
  ASSERT_EQ(m.size(), 24u);
  for (double v : m) EXPECT_NEAR(v, 1.0 / 8.0, 1e-14);  // volume 1 over 8 nodes, every DOF
  EXPECT_NEAR(std::accumulate(m.begin(), m.end(), 0.0), 3.0, 1e-13);
}

TEST(Stabilization, DampingForceTangentAndDissipationByHand) {
  OneCube cube;
  const std::vector<double> m = cube.mass();
  solver::ViscousForces forces(cube.dofs, m);
  const double c = 2.0, dt = 0.5;
  forces.set(c, dt);
  std::vector<double> u_start(24, 0.0), u(24), f(24, 0.0);
  for (std::size_t d = 0; d < 24; ++d) {
    u_start[d] = 0.01 * static_cast<double>(d);
    u[d] = u_start[d] + 1e-3 * static_cast<double>(d % 5 + 1);
  }
  forces.set_start(u_start);
  forces.add_force(u, f);
  double dissipated = 0.0;
  for (std::size_t d = 0; d < 24; ++d) {
    const double du = u[d] - u_start[d];
    // Node 1 (DOFs 0-2) is prescribed: no viscous force there. Elsewhere c m Δu/Δt = 2·(1/8)·Δu/0.5.
    const double expected = d < 3 ? 0.0 : 0.5 * du;
    EXPECT_NEAR(f[d], expected, 1e-15) << "DOF " << d;
    dissipated += expected * du;
  }
  std::vector<double> du(24);
  for (std::size_t d = 0; d < 24; ++d) du[d] = u[d] - u_start[d];
  EXPECT_NEAR(forces.dissipated(du), dissipated, 1e-15);  // F_v·Δu

  // The tangent gets c m/Δt = 0.5 on every free diagonal.
  std::vector<double> zero(24, 0.0), f_int(24);
  cube.assembler.assemble(zero, {}, f_int);
  std::vector<double> diag_before;
  const auto& k = cube.assembler.tangent();
  for (std::int64_t eq = 0; eq < cube.dofs.n_equations(); ++eq) diag_before.push_back(k.values[k.find(eq, eq)]);
  forces.add_tangent(cube.assembler);
  for (std::int64_t eq = 0; eq < cube.dofs.n_equations(); ++eq)
    EXPECT_NEAR(k.values[k.find(eq, eq)] - diag_before[eq], 0.5, 1e-9) << "equation " << eq;
}

TEST(Stabilization, StrainEnergyIsHalfUKU) {
  OneCube cube;
  std::vector<double> u(24), f(24);
  for (std::size_t d = 0; d < 24; ++d) u[d] = 1e-4 * std::sin(1.0 + static_cast<double>(d));
  cube.assembler.assemble(u, {.tangent = false, .nlgeom = false, .delta_t = {}, .points = true}, f);
  const double half_u_f = 0.5 * std::inner_product(u.begin(), u.end(), f.begin(), 0.0);  // ½ uᵀKu (linear)
  const double allse = solver::strain_energy(*cube.assembler.points_at(u, {}, false));
  EXPECT_NEAR(allse, half_u_f, 1e-12 * std::abs(half_u_f));
  EXPECT_GT(allse, 0.0);
}

TEST(Stabilization, FactorFromTheFirstIncrement) {
  // c = f E₁ T / (Δu₁ᵀM*Δu₁): an increment like the first dissipates f E₁ T/Δt₁.
  EXPECT_DOUBLE_EQ(solver::factor_from_first_increment(2e-4, 3.0, 0.5, 2.0), 2e-4 * 3.0 * 2.0 / 0.5);
  EXPECT_EQ(solver::factor_from_first_increment(2e-4, 3.0, 0.0, 1.0), 0.0);  // no motion: unknown
}

}  // namespace
