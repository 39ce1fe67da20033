// The DOF map: free, prescribed, dependent (*EQUATION) and unused DOFs, and the errors an
// inconsistent set of constraints gets.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"
#include "solver/dof_map.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::one_cube_deck;

namespace {
solver::DofMap map_of(const model::Model& m, std::vector<std::int64_t> prescribed_dofs) {
  const auto am = solver::build_analysis_model(m);
  std::vector<std::uint8_t> p(am.n_dof(), 0);
  for (auto d : prescribed_dofs) p[d] = 1;
  return solver::DofMap::build(am, p);
}
}  // namespace

TEST(DofMap, FreePrescribedAndUnusedDofs) {
  DeckDir dir;
  // Node 9 belongs to no element: its DOFs are unused and get no equation.
  auto r = dir.read(one_cube_deck("*NODE\n9, 5, 5, 5\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto map = map_of(r.model, {0, 1, 2});
  EXPECT_EQ(map.n_dof(), 27);
  EXPECT_EQ(map.n_equations(), 24 - 3);
  EXPECT_EQ(map.kind(0), solver::DofMap::Kind::Prescribed);
  EXPECT_EQ(map.equation(0), -1);
  EXPECT_EQ(map.equation(3), 0);  // equations are numbered in DOF order over the free ones
  EXPECT_EQ(map.kind(24), solver::DofMap::Kind::Unused);
  EXPECT_TRUE(map.masters(24).empty());
}

TEST(DofMap, EquationsEliminateTheirFirstDofThroughChains) {
  DeckDir dir;
  // u(2,1) = u(3,1) / 2 and u(3,1) = −2 u(4,1) + u(1,1)  ⇒  u(2,1) = −u(4,1) + u(1,1)/2.
  auto r = dir.read(one_cube_deck("*EQUATION\n2\n2, 1, 2., 3, 1, -1.\n3\n3, 1, 1., 4, 1, 2., 1, 1, -1.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto map = map_of(r.model, {});
  EXPECT_EQ(map.kind(3), solver::DofMap::Kind::Dependent);   // node 2 DOF 1 (row 1 · 3 + 0)
  EXPECT_EQ(map.kind(6), solver::DofMap::Kind::Dependent);   // node 3 DOF 1
  EXPECT_EQ(map.n_equations(), 24 - 2);
  std::vector<double> u(24, 0.0);
  u[0] = 4.0;   // node 1 DOF 1
  u[9] = 1.5;   // node 4 DOF 1
  map.update_dependent(u);
  EXPECT_DOUBLE_EQ(u[6], -2.0 * 1.5 + 4.0);
  EXPECT_DOUBLE_EQ(u[3], -1.5 + 4.0 / 2);
}

TEST(DofMap, EliminatedDofWithABoundaryConditionIsAnError) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*EQUATION\n2\n2, 1, 1., 3, 1, -1.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  try {
    map_of(r.model, {3});
    FAIL() << "expected an AnalysisError";
  } catch (const solver::AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:17:1: error: *EQUATION: the first (eliminated) degree of freedom, node 2 dof 1"),
              std::string::npos)
        << e.what();
  }
}

TEST(DofMap, EquationsThatEliminateEachOtherAreACycle) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*EQUATION\n2\n2, 1, 1., 3, 1, -1.\n2\n3, 1, 1., 2, 1, -1.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_THROW(map_of(r.model, {}), solver::AnalysisError);
}

// *PRE-TENSION SECTION on the cube's top face, a second cube on it: the copies of its four nodes are dependent,
// u_copy = u_orig + n u_P1 (n = (0, 0, 1)); the pre-tension node's DOF 1 is an unknown though no
// element connects it, its DOFs 2 and 3 stay unused; prescribed, DOF 1 has no equation.
TEST(DofMap, PretensionCopiesFollowTheirOriginalsPlusTheTightening) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*NODE\n9, 0, 0, 2\n10, 1, 0, 2\n11, 1, 1, 2\n12, 0, 1, 2\n13, 5, 5, 5\n"
                                  "*ELEMENT, TYPE=C3D8, ELSET=UPPER\n2, 5, 6, 7, 8, 9, 10, 11, 12\n"
                                  "*SOLID SECTION, ELSET=UPPER, MATERIAL=STEEL\n*ELSET, ELSET=LOWER\n1\n"
                                  "*SURFACE, NAME=TOP\nLOWER, S2\n*PRE-TENSION SECTION, SURFACE=TOP, NODE=13\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.pretension_sections.at(0);
  const std::int64_t p = static_cast<std::int64_t>(s.node) * 3;
  const auto map = map_of(r.model, {});
  EXPECT_EQ(map.kind(p), solver::DofMap::Kind::Free);
  EXPECT_EQ(map.kind(p + 1), solver::DofMap::Kind::Unused);
  EXPECT_EQ(map.kind(p + 2), solver::DofMap::Kind::Unused);
  EXPECT_EQ(map.n_equations(), 12 * 3 + 1) << "the twelve nodes and DOF 1 of the pre-tension node";
  for (const auto& [orig, copy] : s.node_pairs)
    for (int c = 0; c < 3; ++c) {
      const std::int64_t d = static_cast<std::int64_t>(copy) * 3 + c;
      ASSERT_EQ(map.kind(d), solver::DofMap::Kind::Dependent);
      const auto m = map.masters(d);
      ASSERT_EQ(m.size(), c == 2 ? 2u : 1u);
      EXPECT_EQ(m[0].dof, static_cast<std::int64_t>(orig) * 3 + c);
      EXPECT_EQ(m[0].weight, 1.0);
      if (c == 2) {
        EXPECT_EQ(m[1].dof, p);
        EXPECT_EQ(m[1].weight, 1.0);
      }
    }
  const auto held = map_of(r.model, {p});
  EXPECT_EQ(held.kind(p), solver::DofMap::Kind::Prescribed);
  EXPECT_EQ(held.equation(p), -1);
}
