// The shells' nodal normals (solver/shell_normals.hpp): averaged across elements that meet at a
// node within 20°, as Abaqus does without *NORMAL, kept apart across a sharper fold; given by
// *NORMAL or on *NODE.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

/// Two unit S4 plates sharing the edge x = 0, the second folded down by `degrees` about it.
std::string fold(double degrees) {
  const double a = degrees * M_PI / 180;
  return fmt::format("*NODE\n1, 0., 0., 0.\n2, 0., 1., 0.\n3, -1., 0., 0.\n4, -1., 1., 0.\n5, {0}, 0., {1}\n"
                     "6, {0}, 1., {1}\n*ELEMENT, TYPE=S4, ELSET=PLATE\n1, 3, 1, 2, 4\n2, 1, 5, 6, 2\n"
                     "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.1\n",
                     std::cos(a), -std::sin(a));
}

// At 10° the shared nodes of both plates take the bisector of their normals, (sin 5°, 0, cos 5°)
// for the fold down by 10°; the nodes they do not share keep their own. At 30° nothing changes.
TEST(ShellNormals, AShallowFoldIsSmoothedAndASharpOneIsKept) {
  const DeckDir dir;
  const auto shallow = dir.read(fold(10.0));
  ASSERT_TRUE(shallow.ok()) << shallow.report();
  const auto am = solver::build_analysis_model(shallow.model);
  const double half = 5.0 * M_PI / 180;
  for (std::size_t e : {0u, 1u}) {
    const auto& directors = am.elements[e].section.shell_directors;
    ASSERT_EQ(directors.size(), 4u) << e;
    const auto nodes = shallow.model.mesh.elements.nodes_of(e);
    for (std::size_t a = 0; a < 4; ++a) {
      const std::int64_t label = shallow.model.mesh.nodes.labels[static_cast<std::size_t>(nodes[a])];
      if (label != 1 && label != 2) continue;  // the shared edge
      EXPECT_NEAR(directors[a][0], std::sin(half), 1e-12) << e << " " << label;
      EXPECT_NEAR(directors[a][1], 0.0, 1e-12);
      EXPECT_NEAR(directors[a][2], std::cos(half), 1e-12);
    }
  }
  const auto sharp = dir.read(fold(30.0));
  ASSERT_TRUE(sharp.ok()) << sharp.report();
  const auto kept = solver::build_analysis_model(sharp.model);
  EXPECT_TRUE(kept.elements[0].section.shell_directors.empty());
  EXPECT_TRUE(kept.elements[1].section.shell_directors.empty());
}

// *NORMAL replaces the averaged director at its element's node: at 10° the first plate given its
// own normal (0, 0, 1) at node 1 keeps it there while the second still takes the bisector; one
// given reversed (more than 160° off) is taken with the element's sense; one 25° off is used as
// given, with a warning (Abaqus).
TEST(ShellNormals, AGivenNormalReplacesTheAveragedOne) {
  const DeckDir dir;
  const auto r = dir.read(fold(10.0) + "*NORMAL\n1, 1, 0., 0., 2.\n1, 2, 0., 0., -1.\n2, 1, 0.573576436351, 0., 0.819152044289\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  const auto& first = am.elements[0].section.shell_directors;
  const auto& second = am.elements[1].section.shell_directors;
  ASSERT_EQ(first.size(), 4u);
  ASSERT_EQ(second.size(), 4u);
  // Element 1 is 3, 1, 2, 4: node 1 is its second, node 2 its third.
  for (std::size_t a : {1u, 2u}) {
    EXPECT_NEAR(first[a][0], 0.0, 1e-12) << a;
    EXPECT_NEAR(first[a][2], 1.0, 1e-12) << a;
  }
  // Element 2 is 1, 5, 6, 2: at node 1 the given 35° tilt, 25° from its own 10°; at node 2 the
  // bisector.
  EXPECT_NEAR(second[0][0], std::sin(35.0 * M_PI / 180), 1e-12);
  EXPECT_NEAR(second[3][0], std::sin(5.0 * M_PI / 180), 1e-12);
  ASSERT_EQ(am.warnings.size(), 1u);
  EXPECT_EQ(am.warnings[0].rfind("*NORMAL at ", 0), 0u) << am.warnings[0];
  EXPECT_NE(am.warnings[0].find("deck.inp:19: the normal of element 2 at node 1 lies 25.0° from the element's own normal"),
            std::string::npos)
      << am.warnings[0];
}

// A normal on *NODE (fields 5–7) is the director of every shell at the node, *NORMAL taking
// precedence; on a beam node it is refused (a beam's n2 from it is not read yet).
TEST(ShellNormals, ANodeNormalIsTheDirectorOfEveryShellThere) {
  std::string deck = fold(10.0);
  deck.replace(deck.find("1, 0., 0., 0.\n"), 14, "1, 0., 0., 0., 0., 0., 3.\n");
  const DeckDir dir;
  const auto r = dir.read(deck + "*NORMAL\n2, 1, 0.1736481777, 0., 0.984807753\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto am = solver::build_analysis_model(r.model);
  EXPECT_NEAR(am.elements[0].section.shell_directors[1][2], 1.0, 1e-12);  // element 1's node 1: *NODE's
  EXPECT_NEAR(am.elements[1].section.shell_directors[0][0], std::sin(10.0 * M_PI / 180), 1e-9);  // *NORMAL's
  EXPECT_TRUE(am.warnings.empty());

  // Elements before their nodes (inpact resolves the nodes when *NORMAL needs them).
  std::string late = fold(10.0);
  const auto nodes_end = late.find("*ELEMENT");
  const auto elements_end = late.find("*MATERIAL");
  late = late.substr(nodes_end, elements_end - nodes_end) + late.substr(0, nodes_end) + late.substr(elements_end);
  const auto reordered = dir.read(late + "*NORMAL\n1, 1, 0., 0., 1.\n");
  ASSERT_TRUE(reordered.ok()) << reordered.report();
  EXPECT_EQ(reordered.model.mesh.normals.at(0).local, 1);

  // Sets: each element of PLATE takes the normal at those nodes of EDGE that are its own.
  const auto sets = dir.read(fold(10.0) + "*NSET, NSET=EDGE\n1, 2, 3\n*NORMAL\nPLATE, EDGE, 0., 0., 1.\n");
  ASSERT_TRUE(sets.ok()) << sets.report();
  EXPECT_EQ(sets.model.mesh.normals.size(), 5u);  // element 1: nodes 3, 1, 2; element 2: 1, 2

  const auto beam = dir.read("*NODE\n1, 0., 0., 0., 0., 0., 1.\n2, 1., 0., 0.\n*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
                             "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*BEAM SECTION, ELSET=B, MATERIAL=M, "
                             "SECTION=CIRC\n0.1\n");
  ASSERT_TRUE(beam.ok()) << beam.report();
  try {
    (void)solver::build_analysis_model(beam.model);
    ADD_FAILURE() << "a normal on a beam node should be refused";
  } catch (const solver::AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:2: error: *NODE: node 1 of beam element 1 is given a normal"),
              std::string::npos)
        << e.what();
  }
}

// *NORMAL's deck errors: a node not on the element, a beam element, the zero vector, TYPE=CONTACT
// SURFACE.
TEST(ShellNormals, GivenNormalsThatDoNotFitAreDeckErrors) {
  const std::pair<std::string, std::string> cases[] = {
      {"*NORMAL\n1, 5, 0., 0., 1.\n", "deck.inp:17:4: error: *NORMAL: node 5 is not a node of element 1"},
      {"*NSET, NSET=FAR\n5, 6\n*NORMAL\n1, FAR, 0., 0., 1.\n",
       "deck.inp:19:4: error: *NORMAL: no node of the node set is a node of an element of the element set"},
      {"*NORMAL\n1, 1, 0., 0., 0.\n", "deck.inp:17:7: error: *NORMAL: the normal is the zero vector"},
      {"*NORMAL, TYPE=CONTACT SURFACE\nS, 1, 0., 0., 1.\n", "TYPE=CONTACT SURFACE is not supported yet"},
      {"*NORMAL\n1, 1, 0., 0.\n", "deck.inp:17:11: error: *NORMAL: data line has 4 fields, expected 5"},
  };
  for (const auto& [lines, message] : cases) {
    const DeckDir dir;
    const auto r = dir.read(fold(10.0) + lines);
    EXPECT_FALSE(r.ok()) << lines;
    EXPECT_TRUE(has_diagnostic(r, message)) << r.report();
  }
}

}  // namespace
}  // namespace inpact::test
