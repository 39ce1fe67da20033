// *MPC (parser/kw_equation.cpp): TIE and PIN become one *EQUATION a DOF, u_dep − u_ind = 0 with
// the dependent node first; the other types are refused with what is supported.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

std::string cube(const std::string& mpc) {
  return "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 0., 0., 1.\n6, 1., 0., 1.\n"
         "7, 1., 1., 1.\n8, 0., 1., 1.\n9, 0., 0., 1.\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
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

TEST(MpcKeyword, OtherTypesAndUserMpcsAreRefused) {
  DeckDir dir;
  auto r = dir.read(cube("*MPC\nBEAM, 9, 5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:1: error: *MPC: MPC type 'BEAM' is not supported yet (TIE and PIN are; "
                                "CalculiX's PLANE, STRAIGHT and BEAM mean other things than Abaqus's BEAM)"))
      << r.report();
  r = dir.read(cube("*MPC, USER\n1, 9, 5\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.report().find("user subroutine MPCs (USER) are not supported"), std::string::npos) << r.report();
}
