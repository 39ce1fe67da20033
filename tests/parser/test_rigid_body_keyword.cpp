// *RIGID BODY: what the keyword reads, the rotation node an Abaqus deck's body gets, and the
// deck errors (parser/kw_rigid_body.cpp, parser/rigid_bodies.cpp). One unit cube and two free
// nodes 50 and 51 above it.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

std::string cube(const std::string& body) {
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
*NSET, NSET=TOP
5, 6, 7, 8
*NSET, NSET=BOTTOM
1, 2, 3, 4
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
)" + body + "*STEP\n*STATIC\n*END STEP\n";
}

}  // namespace

TEST(RigidBodyKeyword, AnAbaqusBodyGetsARotationNodeBesideItsReferenceNode) {
  DeckDir dir;
  auto r = dir.read(cube("*RIGID BODY, REF NODE=50, TIE NSET=TOP, PIN NSET=BOTTOM\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.rigid_bodies.size(), 1u);
  const auto& b = r.model.rigid_bodies[0];
  const auto& nodes = r.model.mesh.nodes;
  EXPECT_EQ(nodes.labels[b.ref_node], 50);
  EXPECT_TRUE(b.rot_node_added);
  EXPECT_EQ(nodes.labels[b.rot_node], 52);  // the next free label
  EXPECT_EQ(nodes.coords[b.rot_node], nodes.coords[b.ref_node]);
  EXPECT_EQ(b.nodes.size(), 8u);  // TIE NSET and PIN NSET alike
  EXPECT_EQ(b.pinned.size(), 4u);  // but only the pinned ones keep their own rotations
  EXPECT_FALSE(b.ties_rotation(b.pinned[0]));
  ASSERT_EQ(r.model.preprocessing_notes.size(), 1u);
  EXPECT_NE(r.model.preprocessing_notes[0].find("node 52 added to hold the rotations of reference node 50"),
            std::string::npos);
}

TEST(RigidBodyKeyword, CalculiXsRotNodeAndElsetAreRead) {
  DeckDir dir;
  auto r = dir.read(cube("*RIGID BODY, ELSET=CUBE, REF NODE=50, ROT NODE=51\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& b = r.model.rigid_bodies.at(0);
  EXPECT_FALSE(b.rot_node_added);
  EXPECT_EQ(r.model.mesh.nodes.labels[b.rot_node], 51);
  EXPECT_EQ(b.elements.size(), 1u);
  EXPECT_EQ(b.nodes.size(), 8u);  // the ELSET's nodes
  EXPECT_EQ(r.model.mesh.nodes.size(), 10u);  // no node added
}

TEST(RigidBodyKeyword, DeckErrorsNameTheNodeAndTheLine) {
  DeckDir dir;
  // The reference node is a node of the cube.
  auto r = dir.read(cube("*RIGID BODY, REF NODE=5, TIE NSET=BOTTOM\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:23: error: *RIGID BODY: the reference node 5 is a node of solid or plane "
                                "elements; give the body a node of its own (one no element but springs or trusses "
                                "connects)"))
      << r.report();
  // A node in two bodies.
  r = dir.read(cube("*RIGID BODY, REF NODE=50, TIE NSET=TOP\n*RIGID BODY, REF NODE=51, PIN NSET=ALL\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:23:1: error: *RIGID BODY: node 5 follows the rigid body at line 23 and the "
                                "rigid body at line 22; a node can follow one only"))
      << r.report();
  // No nodes, a reference set of two nodes, an analytical surface.
  r = dir.read(cube("*RIGID BODY, REF NODE=50\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:1: error: *RIGID BODY: the rigid body has no nodes: give ELSET=, TIE NSET=, "
                                "PIN NSET= (NSET= in CalculiX) or ANALYTICAL SURFACE="))
      << r.report();
  r = dir.read(cube("*RIGID BODY, REF NODE=TOP, TIE NSET=BOTTOM\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:23: error: *RIGID BODY: REF NODE='TOP' holds 4 nodes; the reference node "
                                "must be exactly one node"))
      << r.report();
  r = dir.read(cube("*RIGID BODY, REF NODE=50, ANALYTICAL SURFACE=DIE\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:22:46: error: *RIGID BODY: 'DIE' is not an analytical surface"))
      << r.report();
}

namespace {

/// The cube with an R3D4 sheet (element 2, nodes 60–63) above it; `rest` adds the body, the
/// surface or what else a case needs.
std::string cube_with_sheet(const std::string& rest) {
  return cube("*NODE\n60, 0., 0., 3.\n61, 1., 0., 3.\n62, 1., 1., 3.\n63, 0., 1., 3.\n"
              "*ELEMENT, TYPE=R3D4, ELSET=SHEET\n2, 60, 61, 62, 63\n" +
              rest);
}

}  // namespace

TEST(RigidBodyKeyword, RigidElementsHaveSposAndSnegFacesAndNeedABody) {
  DeckDir dir;
  auto r = dir.read(cube_with_sheet("*RIGID BODY, REF NODE=50, ELSET=SHEET\n*SURFACE, NAME=DOWN\nSHEET, SNEG\n"
                                    "*SURFACE, NAME=UP\nSHEET, SPOS\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.surfaces.at("DOWN").faces.at(0).face, 0);  // S1 = SNEG
  EXPECT_EQ(r.model.mesh.surfaces.at("UP").faces.at(0).face, 1);    // S2 = SPOS
  EXPECT_EQ(r.model.rigid_bodies.at(0).nodes.size(), 4u);
  // A solid's face name, no face at all, no body, a section.
  r = dir.read(cube_with_sheet("*RIGID BODY, REF NODE=50, ELSET=SHEET\n*SURFACE, NAME=S\nSHEET, S1\n"));
  EXPECT_NE(r.report().find("element 2 (R3D4) is a rigid element: its faces are SPOS and SNEG, not 'S1'"),
            std::string::npos)
      << r.report();
  r = dir.read(cube_with_sheet("*RIGID BODY, REF NODE=50, ELSET=SHEET\n*SURFACE, NAME=S\nSHEET\n"));
  EXPECT_NE(r.report().find("element 2 is a rigid element: give its face, SPOS or SNEG"), std::string::npos)
      << r.report();
  r = dir.read(cube_with_sheet(""));
  EXPECT_NE(r.report().find("element 2 (R3D4) is a rigid element, and no *RIGID BODY, ELSET= holds it"),
            std::string::npos)
      << r.report();
  r = dir.read(cube_with_sheet("*RIGID BODY, REF NODE=50, ELSET=SHEET\n*SOLID SECTION, ELSET=SHEET, MATERIAL=STEEL\n"));
  EXPECT_NE(r.report().find("element 2 is a rigid element and takes no section"), std::string::npos) << r.report();
}
