// Parts, assembly and instances: the form every Abaqus/CAE deck takes.
#include <cmath>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {
const char* kPart = R"(*PART, NAME=Block
*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=ALL
1, 1, 2, 3, 4
*NSET, NSET=LEFT
1, 4
*SURFACE, NAME=TOPS
ALL, S3
*SOLID SECTION, ELSET=ALL, MATERIAL=M
1.
*END PART
)";
const char* kMaterial = "*MATERIAL, NAME=M\n*ELASTIC\n100., 0.3\n";
}  // namespace

TEST(Assembly, TwoInstancesOfOnePartWithTranslationAndRotation) {
  DeckDir dir;
  auto r = dir.read(std::string(kPart) +
                    "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=B1, PART=Block\n*END INSTANCE\n"
                    "*INSTANCE, NAME=B2, PART=Block\n10., 0., 0.\n10., 0., 0., 10., 0., 1., 90.\n*END INSTANCE\n"
                    "*NSET, NSET=BOTH\nB1.LEFT, B2.3\n*END ASSEMBLY\n" + kMaterial);
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model;
  ASSERT_EQ(m.instances.size(), 3u);
  EXPECT_EQ(m.instances[2], "B2");
  EXPECT_EQ(m.mesh.nodes.size(), 8u);
  EXPECT_EQ(m.mesh.elements.size(), 2u);
  // B2 node 2 at (1,0) → translated (11,0) → rotated 90° about z through (10,0): (10,1).
  auto row = m.mesh.nodes.index.find(2, 2);
  ASSERT_TRUE(row);
  EXPECT_NEAR(m.mesh.nodes.coords[*row][0], 10.0, 1e-12);
  EXPECT_NEAR(m.mesh.nodes.coords[*row][1], 1.0, 1e-12);
  EXPECT_EQ(m.mesh.nodes.labels[*row], 2);
  EXPECT_EQ(m.mesh.nodes.instance[*row], 2);
  // Instance sets and surfaces carry the instance prefix; sections follow their elsets.
  EXPECT_EQ(m.mesh.nsets.at("B2.LEFT").rows.size(), 2u);
  EXPECT_EQ(m.mesh.nsets.at("BOTH").rows.size(), 3u);
  EXPECT_EQ(m.mesh.surfaces.at("B1.TOPS").faces.size(), 1u);
  ASSERT_EQ(m.mesh.sections.size(), 2u);
  EXPECT_EQ(m.mesh.sections[1].elset, "B2.ALL");
  // Element connectivity points at the instance's own nodes.
  auto conn = m.mesh.elements.nodes_of(1);
  EXPECT_EQ(m.mesh.nodes.instance[conn[0]], 2);
}

TEST(Assembly, IndependentInstanceHoldsItsOwnMesh) {
  DeckDir dir;
  auto r = dir.read(std::string("*PART, NAME=P\n*END PART\n*ASSEMBLY, NAME=A\n*INSTANCE, NAME=P-1, PART=P\n"
                                "*NODE\n1,0,0\n2,1,0\n3,0,1\n*ELEMENT, TYPE=CPS3, ELSET=E\n1,1,2,3\n"
                                "*SOLID SECTION, ELSET=E, MATERIAL=M\n*END INSTANCE\n*END ASSEMBLY\n") + kMaterial);
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.elements.size(), 1u);
  EXPECT_EQ(r.model.mesh.sections[0].elset, "P-1.E");
}

TEST(Assembly, InstanceSetByInstanceParameterAndLabel) {
  DeckDir dir;
  auto r = dir.read(std::string(kPart) + "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=B1, PART=Block\n*END INSTANCE\n"
                    "*NSET, NSET=N, INSTANCE=B1\n2, 3\n*END ASSEMBLY\n" + kMaterial);
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.mesh.nsets.at("N").rows.size(), 2u);
}

TEST(Assembly, UndefinedPartAndKeywordsInTheWrongPlace) {
  DeckDir dir;
  auto r = dir.read(std::string(kPart) + "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=X, PART=Blok\n*END INSTANCE\n"
                    "*END ASSEMBLY\n*END STEP\n" + kMaterial);
  EXPECT_TRUE(has_diagnostic(r, "*INSTANCE: part 'BLOK' is not defined")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*END STEP: not allowed in the model data; it belongs in *STEP")) << r.report();
  auto r2 = dir.read(std::string(kPart) + "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*PART, NAME=Q\n*MATERIAL, NAME=N\n");
  EXPECT_TRUE(has_diagnostic(r2, "*MATERIAL: not allowed inside *PART")) << r2.report();
  EXPECT_TRUE(has_diagnostic(r2, "*PART: missing *END PART")) << r2.report();
}

// An *ORIENTATION does not turn with an instance: an oriented section in a rotated instance is
// refused (its material axes would silently stay the part's), an unrotated one is read.
TEST(Assembly, AnOrientedSectionInARotatedInstanceIsRefused) {
  DeckDir dir;
  std::string part = kPart;
  part.replace(part.find("MATERIAL=M\n"), 11, "MATERIAL=M, ORIENTATION=OR\n");
  const std::string orientation = "*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n";
  auto turned = dir.read(orientation + part + "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=B2, PART=Block\n0., 0., 0.\n"
                                              "0., 0., 0., 0., 0., 1., 90.\n*END INSTANCE\n*END ASSEMBLY\n" + kMaterial);
  EXPECT_TRUE(has_diagnostic(turned, "instance 'B2' is rotated and a section in it uses the orientation 'OR'"))
      << turned.report();
  auto placed = dir.read(orientation + part + "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=B1, PART=Block\n5., 0., 0.\n"
                                              "*END INSTANCE\n*END ASSEMBLY\n" + kMaterial);
  EXPECT_TRUE(placed.ok()) << placed.report();
  // A cylindrical orientation's axis runs through fixed points: a translation moves it too.
  const std::string cylinder = "*ORIENTATION, NAME=OR, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n";
  auto shifted = dir.read(cylinder + part + "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=B1, PART=Block\n5., 0., 0.\n"
                                            "*END INSTANCE\n*END ASSEMBLY\n" + kMaterial);
  EXPECT_TRUE(has_diagnostic(shifted, "instance 'B1' is translated and a section in it uses the cylindrical "
                                      "orientation 'OR'"))
      << shifted.report();
}
