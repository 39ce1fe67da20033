// *COUPLING with *KINEMATIC or *DISTRIBUTING: what the keywords read, the coupling nodes and
// rotation node the complete deck gives them, and the deck errors (parser/kw_coupling.cpp,
// parser/couplings.cpp). One unit cube, its top face TOPS, and two free nodes 50 and 51 above.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

std::string cube(const std::string& coupling) {
  return R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
50, 0.5, 0.5, 2.
51, 0.5, 0.5, 2.
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*SURFACE, NAME=TOPS
CUBE, S2
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
)" + coupling + "*STEP\n*STATIC\n*END STEP\n";
}

}  // namespace

TEST(CouplingKeyword, KinematicReadsItsDofLinesAndGetsARotationNode) {
  DeckDir dir;
  auto r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*KINEMATIC\n1, 2\n3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.couplings.size(), 1u);
  const model::Coupling& c = r.model.couplings[0];
  EXPECT_EQ(c.kind, model::Coupling::Kind::Kinematic);
  EXPECT_EQ(c.dofs, (std::array<bool, 6>{true, true, true, false, false, false}));
  EXPECT_EQ(c.nodes, (std::vector<std::int32_t>{4, 5, 6, 7}));  // rows of nodes 5–8
  ASSERT_EQ(r.model.mesh.nodes.size(), 11u);
  EXPECT_EQ(c.rot_node, 10);
  EXPECT_EQ(r.model.mesh.nodes.labels[10], 52);
  ASSERT_EQ(r.model.preprocessing_notes.size(), 1u);
  EXPECT_NE(r.model.preprocessing_notes[0].find("*COUPLING 'C1' (line 20): node 52 added to hold the rotations of "
                                                "reference node 50"),
            std::string::npos)
      << r.model.preprocessing_notes[0];
}

TEST(CouplingKeyword, DistributingOfTranslationsNeedsNoRotationNode) {
  DeckDir dir;
  auto r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS, INFLUENCE RADIUS=2.\n"
                         "*DISTRIBUTING, WEIGHTING METHOD=CUBIC\n1, 3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const model::Coupling& c = r.model.couplings.at(0);
  EXPECT_EQ(c.kind, model::Coupling::Kind::Distributing);
  EXPECT_EQ(c.weighting, model::Coupling::Weighting::Cubic);
  EXPECT_DOUBLE_EQ(c.influence_radius, 2.0);
  EXPECT_EQ(c.nodes.size(), 4u);
  EXPECT_EQ(c.rot_node, -1);
  EXPECT_EQ(r.model.mesh.nodes.size(), 10u);
  // Only rotations can be released: the translations are coupled whatever the lines say.
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*DISTRIBUTING\n6, 6\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.couplings.at(0).dofs, (std::array<bool, 6>{true, true, true, false, false, true}));
  EXPECT_EQ(r.model.couplings.at(0).rot_node, 10);
  // Every corner of the face is √(0.5 + 1) ≈ 1.22 from node 50: outside the radius.
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS, INFLUENCE RADIUS=0.8\n*DISTRIBUTING\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:53: error: *COUPLING: coupling 'C1' has no coupling node: surface 'TOPS' "
                                "has no node within the influence radius"))
      << r.report();
}

TEST(CouplingKeyword, DeckErrorsNameTheLineAndWhatIsExpected) {
  DeckDir dir;
  auto r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *COUPLING: coupling 'C1' is followed by neither *KINEMATIC nor "
                                "*DISTRIBUTING"))
      << r.report();
  r = dir.read(cube("*KINEMATIC\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *KINEMATIC: must follow *COUPLING")) << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOP\n*KINEMATIC\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:53: error: *COUPLING: surface 'TOP' is not defined (did you mean 'TOPS'?)"))
      << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=5, SURFACE=TOPS\n*KINEMATIC\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:41: error: *COUPLING: the reference node 5 is a node of solid or plane "
                                "elements; give the coupling a node of its own (one no element but springs or trusses "
                                "connects)"))
      << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*KINEMATIC\n"
                    "*COUPLING, CONSTRAINT NAME=C2, REF NODE=50, SURFACE=TOPS\n*DISTRIBUTING\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:41: error: *COUPLING: coupling 'C2': the reference node 50 is already a "
                                "rigid body's node or another coupling's reference node; give each constraint its own"))
      << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*KINEMATIC\n5, 6\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *KINEMATIC: only rotations (DOFs 4–6) are coupled, and the "
                                "coupling nodes of solid and plane elements have none; couple a translation (DOFs 1–3)"))
      << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*KINEMATIC\n3, 1\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:4: error: *KINEMATIC: the last DOF 1 is below the first 3")) << r.report();
  EXPECT_EQ(r.report().find("is followed by neither"), std::string::npos) << r.report();  // one error, not two
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS, ORIENTATION=OR\n*KINEMATIC\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:71: error: *COUPLING: orientation 'OR' is not defined")) << r.report();
  r = dir.read(cube("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n"
                    "*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS, ORIENTATION=OR\n*DISTRIBUTING\n"));
  EXPECT_NE(r.report().find("ORIENTATION on the *COUPLING of a *DISTRIBUTING is not supported yet"), std::string::npos)
      << r.report();
  r = dir.read(cube("*COUPLING, CONSTRAINT NAME=C1, REF NODE=50, SURFACE=TOPS\n*DISTRIBUTING, COUPLING=STRUCTURAL\n"));
  EXPECT_NE(r.report().find("COUPLING=STRUCTURAL (coupling nodes with rotations) is not supported yet"),
            std::string::npos)
      << r.report();
}

// *DISTRIBUTING COUPLING (CalculiX's node-based form): the DCOUP3D element's node is the
// reference node, the lines give nodes or node sets (defined anywhere in the deck) and weights;
// translations only, so no rotation node.
TEST(CouplingKeyword, NodeBasedDistributingCouplingTakesItsReferenceNodeFromADcoupElement) {
  DeckDir dir;
  auto r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\n5, 1.\n"
                         "TOPN, 2.\n*NSET, NSET=TOPN\n6, 7\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.couplings.size(), 1u);
  const model::Coupling& c = r.model.couplings[0];
  const auto& labels = r.model.mesh.nodes.labels;
  EXPECT_EQ(c.kind, model::Coupling::Kind::Distributing);
  EXPECT_EQ(labels[static_cast<std::size_t>(c.ref_node)], 50);
  ASSERT_EQ(c.nodes.size(), 3u);
  EXPECT_EQ(labels[static_cast<std::size_t>(c.nodes[0])], 5);
  EXPECT_EQ(labels[static_cast<std::size_t>(c.nodes[2])], 7);
  EXPECT_EQ(c.given_weights, (std::vector<double>{1.0, 2.0, 2.0}));
  EXPECT_EQ(c.rot_node, -1);
  EXPECT_FALSE(c.dofs[3] || c.dofs[4] || c.dofs[5]);
}

TEST(CouplingKeyword, NodeBasedDistributingCouplingErrorsNameTheLine) {
  DeckDir dir;
  auto r = dir.read(cube("*DISTRIBUTING COUPLING, ELSET=NONE\n5, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:31: error: *DISTRIBUTING COUPLING: element set 'NONE' holds 0 distributing "
                                "coupling elements"))
      << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D\n9, 50\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:20:1: error: *ELEMENT: distributing coupling elements need ELSET="))
      << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\nNOPE, 1.\n5, 1.\n5, 2.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:1: error: *DISTRIBUTING COUPLING: node set 'NOPE' is not defined")) << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\n5, 1.\n5, 2.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:24:1: error: *DISTRIBUTING COUPLING: node 5 is listed twice")) << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\n5, -1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:4: error: *DISTRIBUTING COUPLING: the weight -1 is negative; expected a "
                                "weight >= 0"))
      << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\n5, 0.\n6, 0.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:1: error: *DISTRIBUTING COUPLING: every weight is zero")) << r.report();
  r = dir.read(cube("*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n9, 50\n*DISTRIBUTING COUPLING, ELSET=DC\n50, 1.\n5, 1.\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:21:4: error: *DISTRIBUTING COUPLING: coupling 'DC': the reference node 50 is "
                                "one of its coupling nodes"))
      << r.report();
}
