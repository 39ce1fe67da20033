// *TRANSFORM (parser/kw_transform.cpp, parser/transforms.cpp): the system read, the local nodes
// added only where the deck refers to a node's DOFs, and the deck errors.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

/// The one-cube deck with its bottom and top node sets, then `body`.
std::string cube(const std::string& body) {
  return test::one_cube_deck("*NSET, NSET=BOTTOM\n1, 2, 3, 4\n*NSET, NSET=TOP\n5, 6, 7, 8\n" + body);
}

}  // namespace

TEST(TransformKeyword, OnlyNodesTheDeckRefersToGetALocalNode) {
  DeckDir dir;
  auto r = dir.read(cube("*TRANSFORM, NSET=ALL, TYPE=C\n0.5, 0.5, 0., 0.5, 0.5, 1.\n"
                         "*BOUNDARY\nBOTTOM, 1, 3\n*STEP\n*STATIC\n*CLOAD\n6, 2, 10.\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.transforms.size(), 1u);
  EXPECT_EQ(r.model.transforms[0].type, model::NodalTransform::Type::Cylindrical);
  EXPECT_EQ(r.model.transforms[0].b, (std::array<double, 3>{0.5, 0.5, 1.0}));
  // The bottom is held at zero in all three directions (any axes alike): node 6 alone.
  ASSERT_EQ(r.model.transformed_nodes.size(), 1u);
  const auto& t = r.model.transformed_nodes[0];
  EXPECT_EQ(r.model.mesh.nodes.labels[t.node], 6);
  EXPECT_EQ(r.model.mesh.nodes.labels[t.local], 9);
  EXPECT_EQ(r.model.mesh.nodes.coords[t.local], r.model.mesh.nodes.coords[t.node]);
}

TEST(TransformKeyword, DeckErrorsNameTheNodeAndTheLine) {
  DeckDir dir;
  // Node 5 on the axis of the cylindrical system, loaded in its (missing) radial direction.
  auto axis = dir.read(cube("*TRANSFORM, NSET=TOP, TYPE=C\n0., 0., 0., 0., 0., 1.\n"
                            "*STEP\n*STATIC\n*CLOAD\n5, 1, 10.\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(axis, "deck.inp:20:1: error: *TRANSFORM: node 5 lies on the cylindrical system's axis"))
      << axis.report();
  auto twice = dir.read(cube("*TRANSFORM, NSET=TOP\n1., 0., 0., 0., 1., 0.\n*TRANSFORM, NSET=ALL\n1., 0., 0., 0., 1., 0.\n"
                             "*STEP\n*STATIC\n*END STEP\n"));
  EXPECT_TRUE(has_diagnostic(twice, "deck.inp:22:1: error: *TRANSFORM: node 5 is in the *TRANSFORM at line 20 already"))
      << twice.report();
}
