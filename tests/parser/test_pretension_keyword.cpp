// *PRE-TENSION SECTION: what the keyword reads and how the mesh is cut (parser/kw_pretension.cpp,
// parser/pretension_split.cpp). Two unit cubes stacked in z; the section is the lower cube's top.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

std::string two_cubes(const std::string& section) {
  return R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
9, 0., 0., 2.
10, 1., 0., 2.
11, 1., 1., 2.
12, 0., 1., 2.
50, 0., 0., 9.
*NSET, NSET=PT
50
*ELEMENT, TYPE=C3D8, ELSET=BAR
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 5, 6, 7, 8, 9, 10, 11, 12
*ELSET, ELSET=LOWER
1
*ELSET, ELSET=UPPER
2
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SURFACE, NAME=CUT
LOWER, S2
*SURFACE, NAME=CUT_FROM_ABOVE
UPPER, S1
)" + section + "*STEP\n*STATIC\n*END STEP\n";
}

}  // namespace

TEST(PretensionKeyword, TheUnderlyingElementGetsCopiesOfTheSectionNodes) {
  DeckDir dir;
  auto r = dir.read(two_cubes("*PRE-TENSION SECTION, SURFACE=CUT, NODE=PT\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.pretension_sections.size(), 1u);
  const auto& s = r.model.pretension_sections[0];
  const auto& nodes = r.model.mesh.nodes;
  EXPECT_EQ(nodes.labels[s.node], 50);
  EXPECT_EQ(s.normal, (std::array<double, 3>{0, 0, 1}));  // out of the lower cube
  EXPECT_DOUBLE_EQ(s.area, 1.0);
  EXPECT_EQ(s.n_rewired_elements, 1u);
  ASSERT_EQ(s.node_pairs.size(), 4u);
  ASSERT_EQ(nodes.size(), 17u);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto [orig, copy] = s.node_pairs[k];
    EXPECT_EQ(nodes.labels[orig], static_cast<std::int64_t>(5 + k));
    EXPECT_EQ(nodes.labels[copy], static_cast<std::int64_t>(51 + k)) << "labelled after the largest label";
    EXPECT_EQ(nodes.coords[copy], nodes.coords[orig]);
    EXPECT_EQ(*nodes.index.find(0, 51 + static_cast<std::int64_t>(k)), copy);
  }
  // The lower cube's top now uses the copies, the upper cube keeps the originals.
  const auto lower = r.model.mesh.elements.nodes_of(0);
  const auto upper = r.model.mesh.elements.nodes_of(1);
  for (int a = 4; a < 8; ++a) EXPECT_EQ(nodes.labels[lower[a]], 51 + (a - 4));
  for (int a = 0; a < 4; ++a) EXPECT_EQ(nodes.labels[upper[a]], 5 + a);
}

TEST(PretensionKeyword, AGivenNormalIsNormalisedAndTheOtherSideCanBeTheSurface) {
  DeckDir dir;
  auto r = dir.read(two_cubes("*PRE-TENSION SECTION, SURFACE=CUT_FROM_ABOVE, NODE=50\n0., 0., -2.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.pretension_sections[0];
  EXPECT_EQ(s.normal, (std::array<double, 3>{0, 0, -1}));
  ASSERT_TRUE(s.given_normal);
  const auto upper = r.model.mesh.elements.nodes_of(1);
  for (int a = 0; a < 4; ++a) EXPECT_EQ(r.model.mesh.nodes.labels[upper[a]], 51 + a) << "the upper cube underlies";
}

TEST(PretensionKeyword, AGivenNormalAgainstTheFacesKeepsTheSurfaceSideUnderlying) {
  // CalculiX's pret1 gives its normal against the faces' outward one: the sides are still told
  // apart by the faces, and the constraint takes the normal as given.
  DeckDir dir;
  auto r = dir.read(two_cubes("*PRE-TENSION SECTION, SURFACE=CUT, NODE=50\n0., 0., -1.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.pretension_sections[0];
  EXPECT_EQ(s.normal, (std::array<double, 3>{0, 0, -1}));
  EXPECT_EQ(s.n_rewired_elements, 1u);
  const auto lower = r.model.mesh.elements.nodes_of(0);
  for (int a = 4; a < 8; ++a) EXPECT_EQ(r.model.mesh.nodes.labels[lower[a]], 51 + (a - 4));
}

TEST(PretensionKeyword, BadSectionsAreReportedWithTheirPlace) {
  DeckDir dir;
  // Line 32 is the first line after the base deck.
  auto r = dir.read(two_cubes("*PRE-TENSION SECTION, SURFACE=CUT, NODE=ALL\n"
                              "*PRE-TENSION SECTION, NODE=50\n"
                              "*PRE-TENSION SECTION, SURFACE=CUT, NODE=50, FOLLOWER\n"
                              "*PRE-TENSION SECTION, SURFACE=CUT, NODE=50\n1., 0.\n"
                              "*PRE-TENSION SECTION, SURFACE=CUT, NODE=50\n0., 0., 1.\n"
                              "*PRE-TENSION SECTION, SURFACE=CUT_FROM_ABOVE, NODE=50\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:32:41: error: *PRE-TENSION SECTION: NODE='ALL' holds 13 nodes")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:33:1: error: *PRE-TENSION SECTION: give one of SURFACE= (the element-based "
                                "surface that cuts a solid fastener) and ELEMENT= (a truss element)"))
      << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:34:45: error: *PRE-TENSION SECTION: FOLLOWER=YES")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:36:5: error: *PRE-TENSION SECTION: data line has 2 fields")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:39:52: error: *PRE-TENSION SECTION: the pre-tension node 50 serves another "
                                "section already"))
      << r.report();
  // ELEMENT= takes a two-node truss, and no normal.
  r = dir.read(two_cubes("*PRE-TENSION SECTION, ELEMENT=1, NODE=50\n"));
  EXPECT_NE(r.report().find("element 1 is a C3D8; ELEMENT= takes a two-node truss or beam (T2D2, T3D2, B31)"), std::string::npos)
      << r.report();
}

// ELEMENT=: the normal is the truss's axis from its first node to its second; a data line (as
// CalculiX's pret3 gives one) must say the same, or the deck stops at it.
TEST(PretensionSectionKeyword, ATrussNormalGivenMustBeItsAxis) {
  DeckDir dir;
  const auto truss = [](const std::string& normal) {
    return "*NODE\n1, 0., 0., 0.\n2, 0., 2., 0.\n3, 0., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=BOLT\n1, 1, 2\n"
           "*SOLID SECTION, ELSET=BOLT, MATERIAL=STEEL\n0.5\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
           "*PRE-TENSION SECTION, ELEMENT=1, NODE=3\n" + normal;
  };
  auto r = dir.read(truss("0., 3., 0.\n"));
  EXPECT_TRUE(r.ok()) << r.report();
  EXPECT_NEAR(r.model.pretension_sections.at(0).normal[1], 1.0, 1e-15);
  for (const char* wrong : {"0., -1., 0.\n", "1., 0., 0.\n"}) {
    r = dir.read(truss(wrong));
    EXPECT_TRUE(has_diagnostic(r, "deck.inp:13:1: error: *PRE-TENSION SECTION: the normal")) << r.report();
    EXPECT_NE(r.report().find("is not the axis of element 1 from its first node to its second (0, 1, 0)"), std::string::npos)
        << r.report();
  }
}
