// Loads and boundary conditions over a step's time, by Abaqus's rules: ramp from the previous
// value, OP=NEW ramps removed loads down, amplitudes scale the magnitude, a released boundary
// condition leaves its reaction as a load that ramps to zero.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/step_conditions.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::one_cube_deck;

namespace {
const char* kSteps = R"(*AMPLITUDE, NAME=TRI
0., 0., 0.5, 1., 1., 0.
*STEP
*STATIC
*CLOAD
7, 3, 10.
*BOUNDARY
1, 1, 3, 0.
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
8, 3, 4.
*CLOAD, AMPLITUDE=TRI
6, 1, 2.
*BOUNDARY, OP=NEW
*END STEP
)";
constexpr std::int64_t dof(int node_label, int component) { return (node_label - 1) * 3 + component - 1; }
}  // namespace

TEST(StepConditions, RampsAmplitudesAndOpNew) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck(kSteps));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  std::vector<double> f(am.n_dof());

  solver::StepConditions s1(am, r.model.steps[0], solver::initial_history(am), 0.0);
  EXPECT_EQ(s1.prescribed()[dof(1, 2)], 1);
  s1.external_force(0.25, f);
  EXPECT_DOUBLE_EQ(f[dof(7, 3)], 2.5);  // ramps from 0 to 10 over the step

  std::vector<double> reactions(am.n_dof(), 0.0);
  reactions[dof(1, 3)] = -10.0;
  const auto history = s1.end_state(reactions);
  solver::StepConditions s2(am, r.model.steps[1], history, 1.0);
  EXPECT_EQ(s2.prescribed()[dof(1, 3)], 0);  // released by OP=NEW
  s2.external_force(0.5, f);
  EXPECT_DOUBLE_EQ(f[dof(7, 3)], 5.0);   // removed by OP=NEW: ramps down from 10
  EXPECT_DOUBLE_EQ(f[dof(8, 3)], 2.0);   // new: ramps up to 4
  EXPECT_DOUBLE_EQ(f[dof(6, 1)], 2.0);   // magnitude 2 × TRI(0.5) = 2
  EXPECT_DOUBLE_EQ(f[dof(1, 3)], -5.0);  // the released reaction, half way down to zero
  s2.external_force(1.0, f);
  EXPECT_DOUBLE_EQ(f[dof(7, 3)], 0.0);
  EXPECT_DOUBLE_EQ(f[dof(6, 1)], 0.0);
  EXPECT_DOUBLE_EQ(f[dof(1, 3)], 0.0);
}

TEST(StepConditions, PrescribedValuesRampFromWhereTheDofWas) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*STEP\n*STATIC\n*BOUNDARY\n7, 3, 3, 0.4\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  solver::StepConditions s(am, r.model.steps[0], solver::initial_history(am), 0.0);
  std::vector<double> u_start(am.n_dof(), 0.0), u(am.n_dof(), 0.0);
  u_start[dof(7, 3)] = 0.1;
  s.apply_prescribed(0.5, u_start, u);
  EXPECT_DOUBLE_EQ(u[dof(7, 3)], 0.1 + (0.4 - 0.1) * 0.5);
}

// *BOUNDARY, FIXED: the DOF stays where the step found it (a value on the data line is ignored,
// and so is an amplitude), in this step and in the next one that does not redefine it.
TEST(StepConditions, FixedHoldsTheStepStartValue) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck(R"(*AMPLITUDE, NAME=TRI
0., 0., 0.5, 1., 1., 0.
*STEP
*STATIC
*BOUNDARY, FIXED, AMPLITUDE=TRI
7, 3, 3
*END STEP
*STEP
*STATIC
*CLOAD
7, 1, 1.
*END STEP
*STEP
*STATIC
*BOUNDARY
7, 3, 3, 0.5
*END STEP
)"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  std::vector<double> u_start(am.n_dof(), 0.0), u(am.n_dof(), 0.0);
  u_start[dof(7, 3)] = 0.125;  // where the previous step left it
  solver::StepConditions s1(am, r.model.steps[0], solver::initial_history(am), 0.0);
  ASSERT_EQ(s1.prescribed()[dof(7, 3)], 1);
  for (double t : {0.25, 0.5, 1.0}) {
    s1.apply_prescribed(t, u_start, u);
    EXPECT_EQ(u[dof(7, 3)], 0.125) << "t = " << t;
  }
  const std::vector<double> reactions(am.n_dof(), 0.0);
  solver::StepConditions s2(am, r.model.steps[1], s1.end_state(reactions), 1.0);
  ASSERT_EQ(s2.prescribed()[dof(7, 3)], 1);
  s2.apply_prescribed(0.5, u_start, u);
  EXPECT_EQ(u[dof(7, 3)], 0.125) << "carried over, FIXED keeps holding";
  solver::StepConditions s3(am, r.model.steps[2], s2.end_state(reactions), 2.0);
  s3.apply_prescribed(0.5, u_start, u);
  EXPECT_DOUBLE_EQ(u[dof(7, 3)], 0.125 + 0.5 * (0.5 - 0.125)) << "redefined: ramps from where it was";
}

// *TEMPERATURE, OP=NEW removes the earlier temperatures: a node it does not give again returns to
// its *INITIAL CONDITIONS value (0 where none), over the step by the step's own ramp, whatever
// AMPLITUDE the new lines name [K *TEMPERATURE, OP]; and it stays there in the next step.
TEST(StepConditions, TemperaturesRemovedByOpNewRampBackToTheirInitialValues) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck(R"(*AMPLITUDE, NAME=HOLD
0., 1., 1., 1.
*INITIAL CONDITIONS, TYPE=TEMPERATURE
1, 20.
*STEP
*STATIC
*TEMPERATURE
1, 100.
2, 60.
3, 40.
*END STEP
*STEP
*STATIC
*TEMPERATURE, OP=NEW, AMPLITUDE=HOLD
3, 80.
*END STEP
*STEP
*STATIC
*END STEP
)"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  solver::StepConditions s1(am, r.model.steps[0], solver::initial_history(am), 0.0);
  const auto h1 = s1.end_state(std::vector<double>(am.n_dof(), 0.0));
  solver::StepConditions s2(am, r.model.steps[1], h1, 1.0);
  auto dt = s2.temperature_change(0.5);  // T − T_initial, T_initial = 20 at node 1, 0 elsewhere
  EXPECT_DOUBLE_EQ(dt[0], 40.0);  // node 1: 100 → 20, half way: 60
  EXPECT_DOUBLE_EQ(dt[1], 30.0);  // node 2: 60 → 0, half way
  EXPECT_DOUBLE_EQ(dt[2], 80.0);  // node 3: given again, at once by HOLD
  dt = s2.temperature_change(1.0);
  EXPECT_DOUBLE_EQ(dt[0], 0.0);
  EXPECT_DOUBLE_EQ(dt[1], 0.0);
  solver::StepConditions s3(am, r.model.steps[2], s2.end_state(std::vector<double>(am.n_dof(), 0.0)), 2.0);
  dt = s3.temperature_change(0.5);
  EXPECT_DOUBLE_EQ(dt[0], 0.0);
  EXPECT_DOUBLE_EQ(dt[1], 0.0);
  EXPECT_DOUBLE_EQ(dt[2], 80.0);
}
