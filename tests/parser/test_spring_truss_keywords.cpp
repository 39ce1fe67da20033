// *SPRING, truss sections and *SOLID SECTION, OFFSET: what is read and the deck errors for data
// that contradicts the mesh.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

const std::string kNodes = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n";
const std::string kMaterial = "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n";

}  // namespace

TEST(SpringKeyword, SpringaTakesTheStiffnessAfterABlankLineOrAtOnce) {
  for (const std::string data : {"\n12.5\n", "12.5\n"}) {
    DeckDir dir;
    auto r = dir.read(kNodes + "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n*SPRING, ELSET=S\n" + data);
    ASSERT_TRUE(r.ok()) << r.report();
    ASSERT_EQ(r.model.mesh.springs.size(), 1u);
    EXPECT_EQ(r.model.mesh.springs[0].stiffness, 12.5);
    EXPECT_EQ(r.model.mesh.springs[0].dof1, 0);
  }
}

TEST(SpringKeyword, Spring2ReadsItsDofsAndNonlinearTables) {
  DeckDir dir;
  auto r = dir.read(kNodes + "*ELEMENT, TYPE=SPRING2, ELSET=S\n1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n1, 2\n"
                             "-5., -1.\n0., 0.\n5., 1.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.springs.at(0);
  EXPECT_EQ(s.dof1, 1);
  EXPECT_EQ(s.dof2, 2);
  ASSERT_EQ(s.table.size(), 3u);
  EXPECT_EQ(s.table[2][0], 5.0);
}

TEST(SpringKeyword, DataThatContradictsTheMeshIsADeckError) {
  struct Case {
    std::string deck, message;
  };
  const std::string springa = kNodes + "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n";
  const std::string spring2 = kNodes + "*ELEMENT, TYPE=SPRING2, ELSET=S\n1, 1, 2\n";
  for (const Case& c : std::vector<Case>{
           {springa + "*SPRING, ELSET=S\n0.\n", "deck.inp:7:1: error: *SPRING: spring stiffness must be positive, found 0"},
           {springa + "*SPRING, ELSET=S\n-3.\n", "spring stiffness must be positive, found -3"},
           {spring2 + "*SPRING, ELSET=S\n10.\n", "deck.inp:6:1: error: *SPRING: SPRING2 element 1 needs the DOFs it acts on"},
           {spring2 + "*SPRING, ELSET=S\n1\n10.\n", "SPRING2 element 1 needs the DOFs"},
           {spring2 + "*SPRING, ELSET=S\n1, 5\n10.\n", "acts on a rotational DOF (5)"},
           {kNodes + "*ELEMENT, TYPE=SPRING2, ELSET=S\n1, 1\n*SPRING, ELSET=S\n1, 1\n10.\n",
            "deck.inp:5:4: error: *ELEMENT: data line has 2 fields, expected 3 (element label and 2 node labels for SPRING2)"},
           {kNodes + "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n", "element 1 has no spring behaviour (assign one with *SPRING)"},
           {kNodes + "*ELEMENT, TYPE=T3D2, ELSET=T\n1, 1, 2\n*SPRING, ELSET=T\n10.\n" + "*SOLID SECTION, ELSET=T, MATERIAL=M\n1.\n" + kMaterial,
            "element 1 (T3D2) in set T is not a spring element"},
           {springa + "*SPRING, ELSET=S, NONLINEAR\n0., 0.\n5., 0.\n", "relative displacements must increase down the table"},
       }) {
    DeckDir dir;
    auto r = dir.read(c.deck);
    EXPECT_FALSE(r.ok()) << c.deck;
    EXPECT_TRUE(has_diagnostic(r, c.message)) << r.report() << "\nexpected: " << c.message;
  }
}

TEST(TrussSection, AreaIsRequiredAndPositiveAndOffsetMustBeZero) {
  const std::string truss = kNodes + "*ELEMENT, TYPE=T3D2, ELSET=T\n1, 1, 2\n" + kMaterial;
  struct Case {
    std::string section, message;
  };
  for (const Case& c : std::vector<Case>{
           {"*SOLID SECTION, ELSET=T, MATERIAL=M\n",
            "deck.inp:9:1: error: *SOLID SECTION: truss element 1 (T3D2) needs its cross-section area"},
           {"*SOLID SECTION, ELSET=T, MATERIAL=M\n-2.\n", "deck.inp:10:1: error: *SOLID SECTION: cross-section area must be positive, found -2"},
           {"*SOLID SECTION, ELSET=T, MATERIAL=M, OFFSET=0.5\n1.\n",
            "deck.inp:9:45: error: *SOLID SECTION: OFFSET=0.5 has no meaning for a solid or truss section"},
       }) {
    DeckDir dir;
    auto r = dir.read(truss + c.section);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_diagnostic(r, c.message)) << r.report() << "\nexpected: " << c.message;
  }
  DeckDir dir;
  auto r = dir.read(truss + "*SOLID SECTION, ELSET=T, MATERIAL=M, OFFSET=0.\n0.25\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.sections.at(0).thickness, 0.25);
  EXPECT_TRUE(r.model.mesh.sections.at(0).value_given);
}
