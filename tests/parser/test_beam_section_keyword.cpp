// *BEAM SECTION, *BEAM GENERAL SECTION and *TRANSVERSE SHEAR STIFFNESS: what is read, the
// rotation node each beam node gets, and the deck errors for data that contradicts the mesh.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "model/reference_nodes.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

// Lines 1–7: three nodes, two B31 (deck lines: *NODE 1, nodes 2–4, *ELEMENT 5, elements 6–7).
const std::string kBeams = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n*ELEMENT, TYPE=B31, ELSET=B\n"
                           "1, 1, 2\n2, 2, 3\n";
const std::string kMaterial = "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n";

}  // namespace

TEST(BeamSectionKeyword, ReadsTheShapeTheN1DirectionAndTheShearStiffness) {
  DeckDir dir;
  auto r = dir.read(kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.3, 0.2\n0., 1., 0.\n"
                                         "*TRANSVERSE SHEAR STIFFNESS\n50., 60.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.mesh.beam_sections.size(), 1u);
  const auto& s = r.model.mesh.beam_sections[0];
  EXPECT_EQ(s.shape, model::BeamSection::Shape::Rect);
  EXPECT_EQ(s.dims, (std::vector<double>{0.3, 0.2}));
  EXPECT_EQ(s.n1, (std::array<double, 3>{0.0, 1.0, 0.0}));
  EXPECT_EQ(s.k23, 50.0);
  EXPECT_EQ(s.k13, 60.0);
  EXPECT_FALSE(s.slenderness_compensation.has_value());
}

TEST(BeamSectionKeyword, EveryBeamNodeGetsOneRotationNodeAndN1DefaultsToMinusZ) {
  DeckDir dir;
  auto r = dir.read(kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.1\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.beam_sections[0].n1, (std::array<double, 3>{0.0, 0.0, -1.0}));
  ASSERT_EQ(r.model.node_rotations.size(), 3u);
  EXPECT_EQ(r.model.mesh.nodes.size(), 6u);
  for (const auto& b : r.model.node_rotations) EXPECT_GE(r.model.mesh.nodes.labels[b.rot_node], 4);
  EXPECT_EQ(model::rotating_nodes(r.model, 3).size(), 3u);
}

// CalculiX's RECT of one width is a square; Abaqus needs both, so the deck is warned.
TEST(BeamSectionKeyword, ARectOfOneWidthIsCalculixsSquare) {
  DeckDir dir;
  auto r = dir.read(kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.05\n");
  ASSERT_TRUE(r.ok());
  const auto& s = r.model.mesh.beam_sections.at(0);
  EXPECT_EQ(s.dims, (std::vector<double>{0.05, 0.05}));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:12:1: warning: *BEAM SECTION: RECT with one width 0.05 is read as CalculiX's "
                                "square"));
}

// CalculiX's CIRC of two numbers is an ellipse of those full axes (n1 first): the model holds
// its semi-axes; a one-number CIRC stays Abaqus's radius.
TEST(BeamSectionKeyword, ACircOfTwoNumbersIsCalculixsEllipse) {
  DeckDir dir;
  auto r = dir.read(kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.3, 0.2\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.beam_sections.at(0);
  EXPECT_EQ(s.circ_semi_axes(), (std::array<double, 2>{0.15, 0.1}));
  EXPECT_TRUE(has_diagnostic(r, "deck.inp:12:1: warning: *BEAM SECTION: CIRC with two numbers is read as CalculiX's "
                                "ellipse: its full axes 0.3 along n1 and 0.2 along n2"))
      << r.report();
  auto circle = dir.read(kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.3\n");
  ASSERT_TRUE(circle.ok()) << circle.report();
  EXPECT_EQ(circle.model.mesh.beam_sections.at(0).circ_semi_axes(), (std::array<double, 2>{0.3, 0.3}));
}

TEST(BeamSectionKeyword, GeneralSectionTakesAreaInertiasAndModuli) {
  DeckDir dir;
  auto r = dir.read(kBeams + "*BEAM GENERAL SECTION, ELSET=B, SECTION=GENERAL\n0.06, 2e-4, 0., 4.5e-4, 3e-4\n"
                             "0., 1., 0.\n2e5, 8e4\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& s = r.model.mesh.beam_sections.at(0);
  EXPECT_EQ(s.shape, model::BeamSection::Shape::General);
  EXPECT_EQ(s.dims.size(), 5u);
  EXPECT_EQ(s.youngs_modulus, 2e5);
  EXPECT_EQ(s.shear_modulus, 8e4);
}

// *SECTION POINTS: (x1, x2) pairs, four a line at most; a (0, 0) ending a line is padding unless
// it is the only point (Abaqus Keywords).
TEST(BeamSectionKeyword, SectionPointsOfAGeneralSectionAreReadInOrder) {
  const std::string general = kBeams + "*BEAM GENERAL SECTION, ELSET=B, SECTION=GENERAL\n0.06, 2e-4, 0., 4.5e-4, 3e-4\n"
                                       "0., 1., 0.\n2e5, 8e4\n*SECTION POINTS\n";
  {
    DeckDir dir;
    auto r = dir.read(general + "0.15, 0.1, -0.15, 0.1, 0., 0.\n-0.15, -0.1,\n");
    ASSERT_TRUE(r.ok()) << r.report();
    const auto& points = r.model.mesh.beam_sections.at(0).section_points;
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[1], (std::array<double, 2>{-0.15, 0.1}));
    EXPECT_EQ(points[2], (std::array<double, 2>{-0.15, -0.1}));
  }
  DeckDir dir;
  auto r = dir.read(general + "0., 0.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.beam_sections.at(0).section_points.size(), 1u);
}

TEST(BeamSectionKeyword, DataThatContradictsTheMeshOrIsNotSupportedIsADeckError) {
  struct Case {
    std::string deck, message;
  };
  const std::string sec = "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=";
  for (const Case& c : std::vector<Case>{
           {kBeams + kMaterial + sec + "RECT\n0.3, -0.2\n", "the section dimensions must be positive"},
           {kBeams + kMaterial + sec + "L\n1., 1., .1, .1\n", "SECTION=L is not supported yet"},
           {kBeams + kMaterial + sec + "I\n.5, 1., .4, .4, .5, .5, .1\n", "the flanges t1 + t2 = 1 must be thinner"},
           {kBeams + kMaterial + sec + "I\n.5, 1., .4, .4, .1, .1, .5\n", "the web t3 = 0.5 must be no wider"},
           {kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=I, OFFSET2=0.5\n.5, 1., .4, .4, .1, .1, .1\n",
            "deck.inp:11:56: error: *BEAM SECTION: an I section places its nodes by its own l"},
           {kBeams + kMaterial + sec + "BOX\n1., 1., .5, .1, .5, .1\n", "must be thinner than"},
           {kBeams + kMaterial + sec + "PIPE\n0.1, 0.2\n", "the wall thickness 0.2 exceeds the outer radius 0.1"},
           {kBeams + kMaterial + sec + "CIRC\n0.1\n0., 0., 0.\n", "the n1 direction is the zero vector"},
           {kBeams + kMaterial, "deck.inp:6: error: *ELEMENT: element 1 has no section (assign one with *BEAM SECTION)"},
           {kBeams + kMaterial + "*SOLID SECTION, ELSET=B, MATERIAL=M\n", "element 1 is a beam element: its section is a "
                                                                        "*BEAM SECTION"},
           {kBeams + "*BEAM SECTION, ELSET=B, MATERIAL=X, SECTION=CIRC\n0.1\n", "material 'X' is not defined"},
           {kBeams + "*BEAM GENERAL SECTION, ELSET=B\n0.06, 2e-4, 1e-5, 4.5e-4, 3e-4\n", "I12 other than 0"},
           {kBeams + "*BEAM GENERAL SECTION, ELSET=B\n0.06, 2e-4, 0., 4.5e-4, 3e-4\n0., 1., 0.\n2e5, 8e4\n"
                     "*SECTION POINTS\n0.1, 0.2, 0.3\n",
            "deck.inp:13: error: *SECTION POINTS: expected x1, x2 pairs, at most four a line; found 3 values"},
           {kBeams + kMaterial + sec + "CIRC\n0.1\n*SECTION POINTS\n0.1, 0.\n",
            "*SECTION POINTS: must follow *BEAM GENERAL SECTION"},
       }) {
    DeckDir dir;
    auto r = dir.read(c.deck);
    EXPECT_FALSE(r.ok()) << c.deck;
    EXPECT_TRUE(has_diagnostic(r, c.message)) << r.report();
  }
}

// A *TRANSFORM over a beam node whose rotations the deck refers to: rotations have no local
// system yet, so a global one would be silently wrong; held at zero in all three, any axes do.
TEST(BeamSectionKeyword, RotationsOfATransformedBeamNodeAreADeckErrorUnlessHeldAtZero) {
  const std::string deck = kBeams + kMaterial + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.1\n"
                           "*NSET, NSET=END\n3\n*TRANSFORM, NSET=END\n0., 1., 0., -1., 0., 0.\n*BOUNDARY\n1, ENCASTRE\n";
  {
    DeckDir dir;
    auto r = dir.read(deck + "END, 5, 5, 0.01\n");
    EXPECT_TRUE(has_diagnostic(r, "deck.inp:15:1: error: *TRANSFORM: beam node 3 is in this system and a boundary "
                                  "condition, moment or equation refers to its rotations"))
        << r.report();
  }
  DeckDir dir;
  auto r = dir.read(deck + "END, 4, 6\n");
  EXPECT_TRUE(r.ok()) << r.report();
}
