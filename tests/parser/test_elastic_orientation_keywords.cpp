// *ELASTIC with TYPE=ENGINEERING CONSTANTS | ORTHOTROPIC | ANISOTROPIC | LAMINA (the constants
// over several lines, the temperature column, Abaqus's stability checks as deck errors) and
// *ORIENTATION with *SOLID SECTION, ORIENTATION=.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

/// One C3D8 cube; `section_params` end the *SOLID SECTION line (line 12), `elastic` starts at line 14,
/// `extra` follows it.
std::string cube(const std::string& elastic, const std::string& section_params = "", const std::string& extra = "") {
  return "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n"
         "8, 0, 1, 1\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*SOLID SECTION, ELSET=CUBE, MATERIAL=M" + section_params + "\n*MATERIAL, NAME=M\n" + elastic + extra;
}

const char* kEngineering = "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n140000., 10000., 9000., 0.3, 0.28, 0.45, 5000., 4500.,\n3500., 20.\n";

}  // namespace

TEST(ElasticKeyword, EngineeringConstantsOverTwoLinesWithTemperature) {
  DeckDir dir;
  const auto r = dir.read(cube(kEngineering));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& e = *r.model.materials.at("M").elastic;
  EXPECT_EQ(e.type, model::Elastic::Type::EngineeringConstants);
  ASSERT_EQ(e.constants.size(), 9u);
  EXPECT_EQ(e.constants[0], 140000.);
  EXPECT_EQ(e.constants[8], 3500.);
}

TEST(ElasticKeyword, CalculixSpellingsAndTheAnisotropicLayout) {
  DeckDir dir;
  const auto ortho = dir.read(cube("*ELASTIC,TYPE=ORTHO\n500000.,157200.,400000.,157200.,157200.,300000.,126200.,126200.,\n"
                                   "126200.,294.\n"));
  ASSERT_TRUE(ortho.ok()) << ortho.report();
  EXPECT_EQ(ortho.model.materials.at("M").elastic->type, model::Elastic::Type::Orthotropic);
  const auto aniso = dir.read(cube("*ELASTIC,TYPE=ANISO\n300000.,110000.,320000.,130000.,140000.,350000.,160000.,170000.,\n"
                                   "180000.,390000.,200000.,210000.,220000.,230000.,440000.,250000.,\n"
                                   "260000.,270000.,280000.,290000.,500000.\n"));
  ASSERT_TRUE(aniso.ok()) << aniso.report();
  const auto& c = aniso.model.materials.at("M").elastic->constants;
  ASSERT_EQ(c.size(), 21u);
  EXPECT_EQ(c[20], 500000.);
  // An empty field is a zero stiffness, as in Abaqus.
  const auto zeros = dir.read(cube("*ELASTIC,TYPE=ORTHO\n500.,,400.,,,300.,100.,100.,\n100.\n"));
  ASSERT_TRUE(zeros.ok()) << zeros.report();
  EXPECT_EQ(zeros.model.materials.at("M").elastic->constants[1], 0.0);
}

TEST(ElasticKeyword, UnstableConstantsAreDeckErrorsAtTheirField) {
  DeckDir dir;
  // |ν12| < √(E1/E2) = √(10000/140000) = 0.267 for the constants given the other way round.
  EXPECT_TRUE(has_diagnostic(
      dir.read(cube("*ELASTIC, TYPE=ENGINEERING CONSTANTS\n10000., 140000., 9000., 0.3, 0.28, 0.45, 5000., 4500.,\n3500.\n")),
      "deck.inp:15:25: error: *ELASTIC: unstable material: |nu12| < sqrt(E1/E2) is required, found 0.3"));
  EXPECT_TRUE(has_diagnostic(
      dir.read(cube("*ELASTIC, TYPE=ENGINEERING CONSTANTS\n140000., -10., 9000., 0.3, 0.28, 0.45, 5000., 4500.,\n3500.\n")),
      "deck.inp:15:10: error: *ELASTIC: E2 must be positive, found -10"));
  // ν12 = ν13 = ν23 = 0.6 with equal moduli: each bound holds (< 1), the determinant does not.
  EXPECT_TRUE(has_diagnostic(
      dir.read(cube("*ELASTIC, TYPE=ENGINEERING CONSTANTS\n1., 1., 1., 0.6, 0.6, 0.6, 1., 1.,\n1.\n")),
      "*ELASTIC: unstable material: 1 - nu12 nu21 - nu23 nu32 - nu31 nu13 - 2 nu21 nu32 nu13 must be positive"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC,TYPE=ORTHO\n500.,600.,400.,1.,1.,300.,100.,100.,\n100.\n")),
                             "deck.inp:15:6: error: *ELASTIC: unstable material: |D1122| < sqrt(D1111 D2222) is required"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC,TYPE=ANISO\n1.,2.,1.,0.,0.,1.,0.,0.,\n0.,1.,0.,0.,0.,0.,1.,0.,\n"
                                           "0.,0.,0.,0.,1.\n")),
                             "deck.inp:15:1: error: *ELASTIC: unstable material: the stiffness D is not positive definite"));
}

TEST(ElasticKeyword, CountsAndTemperaturesThatCannotBeRead) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC, TYPE=ORTHOTROPIC\n500.,157.,400.,157.,157.,300.,126.,126.\n")),
                             "deck.inp:15:36: error: *ELASTIC: expected 9 constants"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(std::string(kEngineering) + "140000., 10000., 9000., 0.3, 0.28, 0.45, 5000., 4500.,\n"
                                           "3500., 100.\n")),
                             "deck.inp:17:1: error: *ELASTIC: temperature-dependent data (more than one set of constants) is "
                             "not supported yet"));
}

TEST(OrientationKeyword, RectangularAndCylindricalWithTheAdditionalRotation) {
  DeckDir dir;
  const auto r = dir.read(cube(kEngineering, ", ORIENTATION=OR",
                               "*ORIENTATION, NAME=OR\n1., 1., 0., -1., 1., 0.\n3, 15.\n"
                               "*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& o = r.model.orientations.at("OR");
  EXPECT_EQ(o.system, model::Orientation::System::Rectangular);
  EXPECT_EQ(o.a[0], 1.0);
  EXPECT_EQ(o.b[0], -1.0);
  EXPECT_EQ(o.axis, 3);
  EXPECT_EQ(o.angle, 15.0);
  EXPECT_EQ(r.model.orientations.at("CYL").system, model::Orientation::System::Cylindrical);
  EXPECT_EQ(r.model.mesh.sections[0].orientation, "OR");
}

TEST(OrientationKeyword, ErrorsSayWhatIsWrong) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, ", ORIENTATION=ORX", "*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n")),
                             "deck.inp:12:1: error: *SOLID SECTION: orientation 'ORX' is not defined"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=OR\n1., 0., 0., 2., 0., 0.\n")),
                             "deck.inp:18:1: error: *ORIENTATION: the points a and b do not span a plane"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n4, 30.\n")),
                             "deck.inp:19:1: error: *ORIENTATION: the local axis of the additional rotation must be 1, 2 or 3"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=OR\nDIST\n")),
                             "deck.inp:18:1: error: *ORIENTATION: orientation data from a distribution ('DIST', *DISTRIBUTION) "
                             "is not supported yet"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=OR, SYSTEM=SPHERICAL\n1., 0., 0., 0., 1., 0.\n")),
                             "*ORIENTATION: SYSTEM=SPHERICAL is not supported yet (RECTANGULAR or CYLINDRICAL)"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=OR, DEFINITION=NODES\n1, 2, 3\n")),
                             "*ORIENTATION: DEFINITION=NODES is not supported yet (only COORDINATES)"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube(kEngineering, "", "*ORIENTATION, NAME=C, SYSTEM=CYLINDRICAL\n1., 0., 0., 1., 0., 0.\n")),
                             "deck.inp:18:13: error: *ORIENTATION: the two points a and b of the cylinder axis coincide"));
}
