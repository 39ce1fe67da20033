// The shells' nodal normals (solver/shell_normals.hpp): averaged across elements that meet at a
// node within 20°, as Abaqus does without *NORMAL, kept apart across a sharper fold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "fixtures/deck_fixture.hpp"
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

}  // namespace
}  // namespace inpact::test
