// *NODE *ELEMENT *NSET *ELSET *SURFACE *SOLID SECTION *MATERIAL into the model database.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

TEST(Mesh, NodesElementsAndSetsOfTheCube) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck());
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model.mesh;
  ASSERT_EQ(m.nodes.size(), 8u);
  ASSERT_EQ(m.elements.size(), 1u);
  EXPECT_EQ(model::element_type(m.elements.type[0]).name, "C3D8");
  EXPECT_DOUBLE_EQ(m.nodes.coords[6][0], 1.0);
  EXPECT_DOUBLE_EQ(m.nodes.coords[6][2], 1.0);
  EXPECT_EQ(m.nsets.at("ALL").rows.size(), 8u);
  EXPECT_EQ(r.model.materials.at("STEEL").elastic->youngs_modulus, 210000.0);
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.sections[0].elset, "CUBE");
}

TEST(Mesh, SecondOrderElementContinuesOnTheNextLine) {
  DeckDir dir;
  std::string nodes = "*NODE\n";
  for (int i = 1; i <= 20; ++i) nodes += std::to_string(i) + ", " + std::to_string(i) + ".0, 0, 0\n";
  auto r = dir.read(nodes + "*ELEMENT, TYPE=C3D20R, ELSET=E\n7, 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,\n16,17,18,19,20\n"
                    "*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n");
  ASSERT_TRUE(r.ok()) << r.report();
  auto conn = r.model.mesh.elements.nodes_of(0);
  ASSERT_EQ(conn.size(), 20u);
  EXPECT_EQ(r.model.mesh.nodes.labels[conn[19]], 20);
}

TEST(Mesh, ElementsMayComeBeforeTheirNodes) {
  DeckDir dir;
  auto r = dir.read("*ELEMENT, TYPE=CPE4, ELSET=E\n1, 10, 20, 30, 40\n*NODE\n10,0,0\n20,1,0\n30,1,1\n40,0,1\n"
                    "*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.nodes.labels[r.model.mesh.elements.nodes_of(0)[2]], 30);
}

TEST(Mesh, ElementWithAMissingNodeCitesTheField) {
  DeckDir dir;
  auto r = dir.read("*NODE\n1,0,0\n2,1,0\n3,1,1\n*ELEMENT, TYPE=CPS4, ELSET=E\n1, 1, 2, 3, 99\n"
                    "*SOLID SECTION, ELSET=E, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n");
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:6:13: error: *ELEMENT: node 99 is not defined")) << r.report();
}

TEST(Mesh, DuplicateLabelsAndWrongFieldCounts) {
  DeckDir dir;
  auto r = dir.read("*NODE\n1,0,0,0\n1,1,0,0\n*ELEMENT, TYPE=C3D4\n1, 1, 1\n");
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:3:1: error: *NODE: node 1 is defined twice")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:5:7: error: *ELEMENT: data line has 3 fields, expected 5")) << r.report();
}

TEST(Mesh, UnknownElementTypeSuggestsOne) {
  DeckDir dir;
  auto r = dir.read("*NODE\n1,0,0,0\n*ELEMENT, TYPE=C3D8X\n1, 1\n");
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:3:16: error: *ELEMENT: element type 'C3D8X' is not supported (did you mean C3D8?)"))
      << r.report();
}

TEST(Mesh, SetsFromLabelsOtherSetsAndGenerate) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*NSET, NSET=BOTTOM\n1, 2, 3, 4\n*NSET, NSET=ODD, GENERATE\n1, 7, 2\n"
                                  "*NSET, NSET=MIX\nBOTTOM, 8\n*NSET, NSET=CUBEN, ELSET=CUBE\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& ns = r.model.mesh.nsets;
  EXPECT_EQ(ns.at("BOTTOM").rows, (std::vector<std::int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(ns.at("ODD").rows, (std::vector<std::int32_t>{0, 2, 4, 6}));
  EXPECT_EQ(ns.at("MIX").rows, (std::vector<std::int32_t>{0, 1, 2, 3, 7}));
  EXPECT_EQ(ns.at("CUBEN").rows.size(), 8u);
}

TEST(Mesh, UndefinedSetIsAnErrorWithASuggestion) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*NSET, NSET=BOTTOM\n1, 2, 3, 4\n*NSET, NSET=X\nBOTOM\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:19:1: error: *NSET: node set 'BOTOM' is not defined (did you mean 'BOTTOM'?)"))
      << r.report();
}

TEST(Mesh, SurfaceFromFaceIdsAndFromFreeFaces) {
  DeckDir dir;
  // Two cubes stacked in z: the shared face is not exterior.
  auto r = dir.read(one_cube_deck("*NODE\n9,0,0,2\n10,1,0,2\n11,1,1,2\n12,0,1,2\n"
                                  "*ELEMENT, TYPE=C3D8, ELSET=CUBE\n2, 5,6,7,8,9,10,11,12\n"
                                  "*SURFACE, NAME=TOP\nCUBE, S2\n*SURFACE, NAME=SKIN\nCUBE\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.surfaces.at("TOP").faces.size(), 2u);
  EXPECT_EQ(r.model.mesh.surfaces.at("SKIN").faces.size(), 10u);  // 12 faces less the shared pair
}

TEST(Mesh, FaceThatTheElementTypeDoesNotHave) {
  DeckDir dir;
  auto r = dir.read("*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n*ELEMENT, TYPE=C3D4, ELSET=T\n1,1,2,3,4\n"
                    "*SURFACE, NAME=S\nT, S5\n*SOLID SECTION, ELSET=T, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n");
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:9:4: error: *SURFACE: element 1 (C3D4) has no face S5: it has S1..S4")) << r.report();
}

TEST(Mesh, NodeSurfaceWithAreas) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*SURFACE, NAME=PTS, TYPE=NODE\n1, 0.25\nALL\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.surfaces.at("PTS");
  EXPECT_EQ(s.nodes.size(), 9u);
  EXPECT_DOUBLE_EQ(s.node_areas[0], 0.25);
  EXPECT_DOUBLE_EQ(s.node_areas[1], 1.0);
}

TEST(Materials, SectionWithUndefinedMaterialAndMaterialWithoutElasticity) {
  DeckDir dir;
  auto r = dir.read("*NODE\n1,0,0\n2,1,0\n3,1,1\n*ELEMENT, TYPE=CPE3, ELSET=E\n1,1,2,3\n"
                    "*SOLID SECTION, ELSET=E, MATERIAL=STEL\n*MATERIAL, NAME=STEEL\n*DENSITY\n7.8e-9\n");
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:7:1: error: *SOLID SECTION: material 'STEL' is not defined (did you mean 'STEEL'?)"))
      << r.report();
  auto r2 = dir.read("*NODE\n1,0,0\n2,1,0\n3,1,1\n*ELEMENT, TYPE=CPE3, ELSET=E\n1,1,2,3\n"
                     "*SOLID SECTION, ELSET=E, MATERIAL=STEEL\n*MATERIAL, NAME=STEEL\n*DENSITY\n7.8e-9\n");
  EXPECT_TRUE(has_diagnostic(r2, "material 'STEEL' has no *ELASTIC or *HYPERELASTIC definition")) << r2.report();
}

TEST(Materials, PoissonRatioOutOfRangeAndSubOptionWithoutParent) {
  DeckDir dir;
  auto r = dir.read(one_cube_deck("*MATERIAL, NAME=RUBBER\n*ELASTIC\n1., 0.5\n"));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:18:5: error: *ELASTIC: Poisson's ratio must lie in (-1, 0.5), found 0.5")) << r.report();
  auto r2 = dir.read(one_cube_deck("*NSET, NSET=A\n1\n*DENSITY\n1.\n"));
  EXPECT_TRUE(has_diagnostic(r2, "deck.inp:18:1: error: *DENSITY: must follow *MATERIAL")) << r2.report();
}
