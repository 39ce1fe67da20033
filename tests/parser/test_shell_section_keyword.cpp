// *SHELL SECTION, *SHELL GENERAL SECTION, their *TRANSVERSE SHEAR STIFFNESS and *NODAL
// THICKNESS: what is read, the rotation node each shell node gets, and the deck errors.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "model/mesh_queries.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

// Lines 1–7: four nodes and one S4 (deck lines: *NODE 1, nodes 2–5, *ELEMENT 6, element 7).
const std::string kPlate = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n"
                           "*ELEMENT, TYPE=S4, ELSET=P\n1, 1, 2, 3, 4\n";
const std::string kMaterial = "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n";  // lines 8–10

}  // namespace

TEST(ShellSectionKeyword, ReadsThicknessPointsOffsetAndShearStiffness) {
  DeckDir dir;
  auto r = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M, OFFSET=SPOS\n0.2, 7\n"
                                         "*TRANSVERSE SHEAR STIFFNESS\n50., 60.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.mesh.shell_sections.size(), 1u);
  const auto& s = r.model.mesh.shell_sections[0];
  EXPECT_EQ(s.thickness, 0.2);
  EXPECT_EQ(s.section_points, 7);
  EXPECT_EQ(s.offset, 0.5);
  ASSERT_TRUE(s.transverse_shear.has_value());
  EXPECT_EQ((*s.transverse_shear)[0], 50.0);
  EXPECT_EQ((*s.transverse_shear)[1], 60.0);
  // Every shell node gets a rotation node; Abaqus's default of 5 section points, no offset.
  EXPECT_EQ(r.model.node_rotations.size(), 4u);
  auto d = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M, OFFSET=-0.25\n0.2\n");
  ASSERT_TRUE(d.ok()) << d.report();
  EXPECT_EQ(d.model.mesh.shell_sections[0].section_points, 5);
  EXPECT_EQ(d.model.mesh.shell_sections[0].offset, -0.25);
}

TEST(ShellSectionKeyword, DataThatContradictsTheMeshOrIsNotSupportedIsADeckError) {
  DeckDir dir;
  auto even = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2, 4\n");
  EXPECT_TRUE(has_diagnostic(even, "deck.inp:12:6: error: *SHELL SECTION: Simpson's rule through the thickness takes an "
                                   "odd number of section points, at least 3; found 4"))
      << even.report();
  auto composite = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M, COMPOSITE\n0.2\n");
  EXPECT_TRUE(has_diagnostic(composite, "deck.inp:11:35: error: *SHELL SECTION: a COMPOSITE section names a material "
                                        "on each layer's line, not MATERIAL="))
      << composite.report();
  auto no_material = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P\n0.2\n");
  EXPECT_TRUE(has_diagnostic(no_material, "missing parameter MATERIAL (or COMPOSITE with a material on each layer's "
                                          "line)"))
      << no_material.report();
  auto two_lines = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n0.1\n");
  EXPECT_TRUE(has_diagnostic(two_lines, "deck.inp:13:1: error: *SHELL SECTION: expected one data line (a section of "
                                        "layers, one a line, takes COMPOSITE)"))
      << two_lines.report();
  auto nodal = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M, NODAL THICKNESS\n0.2\n"
                                             "*NODAL THICKNESS\n1, 0.1\n2, 0.1\n3, 0.1\n");
  EXPECT_TRUE(has_diagnostic(nodal, "deck.inp:11:1: error: *SHELL SECTION: NODAL THICKNESS: node 4 of element 1 has no "
                                    "*NODAL THICKNESS"))
      << nodal.report();
  auto solid = dir.read(kPlate + kMaterial + "*SOLID SECTION, ELSET=P, MATERIAL=M\n");
  EXPECT_TRUE(has_diagnostic(solid, "element 1 is a shell element: its section is a *SHELL SECTION")) << solid.report();
  auto face = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n*SURFACE, NAME=S\n1, S9\n");
  EXPECT_TRUE(has_diagnostic(face, "deck.inp:14:4: error: *SURFACE: element 1 (S4) has no edge S9: its edges are E1..E4 "
                                   "(CalculiX's S3..S6)"))
      << face.report();
  auto other = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n*SURFACE, NAME=S\n1, TOP\n");
  EXPECT_TRUE(has_diagnostic(other, "element 1 (S4) is a shell element: its faces are SPOS and SNEG (CalculiX's S2 and "
                                    "S1), its edges E1..E4 (CalculiX's S3..S6), not 'TOP'"))
      << other.report();
}

// COMPOSITE: a layer a line from SNEG up, `thickness, points, material, orientation or angle,
// ply`; the section's thickness is the layers' sum.
TEST(ShellSectionKeyword, ReadsCompositeLayers) {
  DeckDir dir;
  const std::string two = "*MATERIAL, NAME=N\n*ELASTIC\n2000., 0.25\n*ORIENTATION, NAME=OR1\n0., 1., 0., -1., 0., 0.\n";
  auto r = dir.read(kPlate + kMaterial + two + "*SHELL SECTION, ELSET=P, COMPOSITE, ORIENTATION=OR1, OFFSET=SNEG\n"
                                               "0.1, 5, M, 45., bottom\n0.3,, n, or1\n0.2, 3, M\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.shell_sections.at(0);
  EXPECT_DOUBLE_EQ(s.thickness, 0.6);
  EXPECT_EQ(s.orientation, "OR1");
  EXPECT_EQ(s.offset, -0.5);
  EXPECT_TRUE(s.material.empty());
  ASSERT_EQ(s.layers.size(), 3u);
  EXPECT_EQ(s.layers[0].section_points, 5);
  EXPECT_EQ(s.layers[0].angle, 45.0);
  EXPECT_EQ(s.layers[0].ply, "bottom");
  EXPECT_EQ(s.layers[1].section_points, 3);  // Abaqus's default for a layer
  EXPECT_EQ(s.layers[1].material, "N");
  EXPECT_EQ(s.layers[1].orientation, "OR1");
  EXPECT_EQ(s.layers[2].thickness, 0.2);
  EXPECT_TRUE(s.layers[2].orientation.empty());
}

TEST(ShellSectionKeyword, CompositeLayerErrorsPointAtTheLayer) {
  DeckDir dir;
  auto material = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, COMPOSITE\n0.1, 3, M\n0.1, 3, X\n");
  EXPECT_TRUE(has_diagnostic(material, "deck.inp:13:9: error: *SHELL SECTION: layer: material 'X' is not defined"))
      << material.report();
  auto orientation = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, COMPOSITE\n0.1, 3, M, OR9\n");
  EXPECT_TRUE(has_diagnostic(orientation, "deck.inp:12:12: error: *SHELL SECTION: layer: orientation 'OR9' is not "
                                          "defined (expected an *ORIENTATION's name or an angle in degrees)"))
      << orientation.report();
  auto thin = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, COMPOSITE\n0., 3, M\n");
  EXPECT_TRUE(has_diagnostic(thin, "deck.inp:12:1: error: *SHELL SECTION: a layer's thickness must be positive, found 0"))
      << thin.report();
  auto points = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, COMPOSITE\n0.1, 2, M\n");
  EXPECT_TRUE(has_diagnostic(points, "deck.inp:12:6: error: *SHELL SECTION: Simpson's rule through the thickness takes "
                                     "an odd number of section points, at least 3; found 2"))
      << points.report();
  auto section = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M, ORIENTATION=OX\n0.1\n");
  EXPECT_TRUE(has_diagnostic(section, "deck.inp:11:50: error: *SHELL SECTION: orientation 'OX' is not defined"))
      << section.report();
}

// GRAV needs the density of every layer (one without it would silently lighten the shell); a
// general section does not use a layer's number of points.
TEST(ShellSectionKeyword, CompositeLayersNeedTheirDensityForGravity) {
  DeckDir dir;
  const std::string dense = "*MATERIAL, NAME=D\n*ELASTIC\n1000., 0.3\n*DENSITY\n7.8e-9\n";
  const std::string step = "*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*DLOAD\nP, GRAV, 9.81, 0., 0., -1.\n*END STEP\n";
  auto light = dir.read(kPlate + kMaterial + dense + "*SHELL SECTION, ELSET=P, COMPOSITE\n0.1, 3, D\n0.1, 3, M\n" + step);
  EXPECT_TRUE(has_diagnostic(light, "GRAV needs the density of material 'M' (add *DENSITY to it)")) << light.report();
  auto general = dir.read(kPlate + dense + "*SHELL GENERAL SECTION, ELSET=P, COMPOSITE\n0.1, 1, D\n0.1, 1, D\n" + step);
  EXPECT_TRUE(general.ok()) << general.report();
}

// CalculiX names a shell's faces S1 (SNEG) and S2 (SPOS).
TEST(ShellSectionKeyword, CalculixShellFacesS1AndS2AreSnegAndSpos) {
  DeckDir dir;
  auto r = dir.read(kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n*SURFACE, NAME=A\n1, S1\n"
                                         "*SURFACE, NAME=B\n1, S2\n*SURFACE, NAME=C\n1, SPOS\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.surfaces;
  EXPECT_EQ(s.at("A").faces.at(0).face, 0);
  EXPECT_EQ(s.at("B").faces.at(0).face, 1);
  EXPECT_EQ(s.at("C").faces.at(0).face, 1);
}

// Edge-based surfaces: Abaqus's E1..E4 (S3: E1..E3), CalculiX's S3..S6; a surface is faces or
// edges; only *DSLOAD, *PRE-TENSION SECTION and a *TIE's slave take edges.
TEST(ShellSectionKeyword, ShellEdgesMakeEdgeBasedSurfaces) {
  DeckDir dir;
  const std::string section = kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n";
  auto r = dir.read(section + "*SURFACE, NAME=A\n1, E2\n1, E4\n*SURFACE, NAME=B\n1, S3\n1, S6\nP, E1\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& a = r.model.mesh.surfaces.at("A");
  EXPECT_TRUE(a.faces.empty());
  ASSERT_EQ(a.edges.size(), 2u);
  EXPECT_EQ(a.edges[0].face, 1);
  EXPECT_EQ(a.edges[1].face, 3);
  const auto& b = r.model.mesh.surfaces.at("B");
  ASSERT_EQ(b.edges.size(), 2u);  // S3 and E1 name the same edge: once
  EXPECT_EQ(b.edges[0].face, 0);
  EXPECT_EQ(b.edges[1].face, 3);
  EXPECT_EQ(model::edge_nodes(r.model.mesh.elements, a.edges[1]), (std::vector<std::int32_t>{3, 0}));

  auto mixed = dir.read(section + "*SURFACE, NAME=A\n1, E2\n1, SPOS\n");
  EXPECT_TRUE(has_diagnostic(mixed, "deck.inp:15:4: error: *SURFACE: surface 'A' has element faces and shell edges: a "
                                    "surface is made of one or the other (define two surfaces)"))
      << mixed.report();
  auto contact = dir.read(section + "*SURFACE, NAME=A\n1, E2\n*SURFACE, NAME=B\n1, SPOS\n*CONTACT PAIR, "
                                    "INTERACTION=I\nA, B\n*SURFACE INTERACTION, NAME=I\n");
  EXPECT_TRUE(has_diagnostic(contact, "*CONTACT PAIR: surface 'A' is made of shell edges, which serve *DSLOAD, "
                                      "*PRE-TENSION SECTION and a *TIE's slave only; *CONTACT PAIR needs element faces "
                                      "(SPOS, SNEG, S1, ...)"))
      << contact.report();
  auto tie = dir.read(section + "*SURFACE, NAME=A\n1, E2\n*SURFACE, NAME=B\n1, E4\n*TIE, NAME=T\nA, B\n");
  EXPECT_TRUE(has_diagnostic(tie, "*TIE: surface 'B' is made of shell edges, which serve *DSLOAD, *PRE-TENSION "
                                  "SECTION and a *TIE's slave only; *TIE needs element faces (SPOS, SNEG, S1, ...)"))
      << tie.report();
  EXPECT_FALSE(has_diagnostic(tie, "surface 'A' is made of shell edges")) << "a tie's slave may be a shell edge";
}

// *DLOAD EDNORn, EDSHRn, EDTn on shells and *DSLOAD EDNOR, EDSHR, EDT on edge-based surfaces.
TEST(ShellSectionKeyword, EdgeLoadsNameAShellEdge) {
  DeckDir dir;
  const std::string model = kPlate + kMaterial + "*SHELL SECTION, ELSET=P, MATERIAL=M\n0.2\n*SURFACE, NAME=E\n1, E3\n"
                                                 "*SURFACE, NAME=F\n1, SPOS\n*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n";
  auto r = dir.read(model + "*DLOAD\nP, EDNOR2, 5.\n1, EDSHR4, 6.\n*DSLOAD\nE, EDT, 7.\n*END STEP\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& d = r.model.steps.at(0).dloads;
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].entries[0].kind, model::DloadEntry::Kind::EdgeLoad);
  EXPECT_EQ(d[0].entries[0].edge_traction, model::EdgeTraction::Normal);
  EXPECT_EQ(d[0].entries[0].faces, (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(d[0].entries[1].edge_traction, model::EdgeTraction::Shear);
  EXPECT_EQ(model::dload_slot(d[0].entries[1], 0), model::edge_load_slot(3, model::EdgeTraction::Shear));
  EXPECT_EQ(d[1].entries[0].edge_traction, model::EdgeTraction::Transverse);
  EXPECT_EQ(d[1].entries[0].faces, (std::vector<std::uint8_t>{2}));
  EXPECT_EQ(d[1].entries[0].magnitude, 7.0);

  auto no_edge = dir.read(model + "*DLOAD\nP, EDNOR5, 5.\n*END STEP\n");
  EXPECT_TRUE(has_diagnostic(no_edge, "deck.inp:22:4: error: *DLOAD: element 1 (S4) has no edge 5: expected "
                                      "EDNOR1..EDNOR4"))
      << no_edge.report();
  auto pressure_on_edges = dir.read(model + "*DSLOAD\nE, P, 5.\n*END STEP\n");
  EXPECT_TRUE(has_diagnostic(pressure_on_edges, "deck.inp:22:4: error: *DSLOAD: surface 'E' is made of shell edges: P "
                                                "loads element faces"))
      << pressure_on_edges.report();
  auto edge_load_on_faces = dir.read(model + "*DSLOAD\nF, EDNOR, 5.\n*END STEP\n");
  EXPECT_TRUE(has_diagnostic(edge_load_on_faces, "deck.inp:22:4: error: *DSLOAD: surface 'F' is made of element faces: "
                                                 "EDNOR loads shell edges (E1, E2, ...)"))
      << edge_load_on_faces.report();
}
