// *MPC (parser/kw_equation.cpp): TIE and PIN become one *EQUATION a DOF, u_dep − u_ind = 0 with
// the dependent node first; BEAM lines become rigid bodies, one per independent node; the other
// types are refused with what is supported.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

std::string cube(const std::string& mpc) {
  return "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 0., 0., 1.\n6, 1., 0., 1.\n"
         "7, 1., 1., 1.\n8, 0., 1., 1.\n9, 0., 0., 1.\n10, 0.5, 0.5, 2.\n11, 0.5, 0.5, 3.\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n" +
         mpc + "*STEP\n*STATIC\n*END STEP\n";
}

}  // namespace

TEST(MpcKeyword, TieAndPinAreOneEquationADofWithTheDependentNodeFirst) {
  DeckDir dir;
  auto r = dir.read(cube("*MPC\nTIE, 9, 5\nPIN, 9, 6\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.equations.size(), 6u);
  const auto& eq = r.model.equations[2];  // TIE, DOF 3
  ASSERT_EQ(eq.terms.size(), 2u);
  EXPECT_EQ(r.model.mesh.nodes.labels[eq.terms[0].node], 9);
  EXPECT_EQ(eq.terms[0].dof, 3);
  EXPECT_DOUBLE_EQ(eq.terms[0].coefficient, 1.0);
  EXPECT_EQ(r.model.mesh.nodes.labels[eq.terms[1].node], 5);
  EXPECT_DOUBLE_EQ(eq.terms[1].coefficient, -1.0);
}

TEST(MpcKeyword, BeamLinesSharingTheirIndependentNodeAreOneRigidBody) {
  DeckDir dir;
  auto r = dir.read(cube("*NSET, NSET=TOP\n5, 6, 7, 8\n*MPC\nBEAM, TOP, 10\nBEAM, 9, 11\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.rigid_bodies.size(), 2u);
  const auto& spider = r.model.rigid_bodies[0];
  EXPECT_TRUE(spider.mpc_beam);
  EXPECT_EQ(r.model.mesh.nodes.labels[spider.ref_node], 10);
  EXPECT_EQ(spider.nodes.size(), 4u);
  EXPECT_TRUE(spider.rot_node_added);  // the independent node's rotations
  EXPECT_TRUE(spider.ties_rotation(spider.nodes[0]));
  EXPECT_TRUE(r.model.equations.empty());
}

TEST(MpcKeyword, BeamErrorsNameTheNodes) {
  DeckDir dir;
  // CalculiX's BEAM between two solid nodes: Abaqus's needs rotations at the independent node.
  auto r = dir.read(cube("*MPC\nBEAM, 9, 5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:10: error: *MPC: the independent (second) node 5 of MPC BEAM is a node of "
                                "solid or plane elements, which have no rotations"))
      << r.report();
  r = dir.read(cube("*MPC\nBEAM, 9, 10\nBEAM, 10, 11\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:10: error: *MPC: the independent node 10 follows the *MPC BEAM to node 11 "
                                "at line 21: chains of rigid links"))
      << r.report();
  r = dir.read(cube("*MPC\nBEAM, 10, 10\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:11: error: *MPC: node 10 is both the dependent and the independent node"))
      << r.report();
  r = dir.read(cube("*NSET, NSET=A\n5, 6\n*NSET, NSET=B\n10, 11, 9\n*MPC\nTIE, A, B\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:9: error: *MPC: the independent nodes (3) must be one node or as many as "
                                "the dependent ones (2)"))
      << r.report();
}

TEST(MpcKeyword, OtherTypesAndUserMpcsAreRefused) {
  DeckDir dir;
  auto r = dir.read(cube("*MPC\nSTRAIGHT, 9, 5, 6\n"));
  EXPECT_FALSE(r.ok());
  r = dir.read(cube("*MPC\nSLIDER, 9, 5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *MPC: MPC type 'SLIDER' is not supported yet (TIE, PIN and BEAM "
                                "are; CalculiX's PLANE, STRAIGHT and MEANROT mean other things)"))
      << r.report();
  r = dir.read(cube("*MPC, USER\n1, 9, 5\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.report().find("user subroutine MPCs (USER) are not supported"), std::string::npos) << r.report();
}
