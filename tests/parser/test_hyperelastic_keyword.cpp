// *HYPERELASTIC: Abaqus's data-line layouts per form, the default form, N, the D's, and the
// errors; and NLGEOM switched on for the steps of a model with a hyperelastic material.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

namespace inpact::parser {
namespace {

using test::DeckDir;
using test::has_diagnostic;
using Form = model::Hyperelastic::Form;

/// One C3D8 cube whose material is `material` (the keyword lines after *MATERIAL), one step.
std::string cube(const std::string& material, const std::string& step = "*STEP\n*STATIC\n*END STEP\n") {
  return R"(*NODE, NSET=ALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8H, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*SOLID SECTION, ELSET=CUBE, MATERIAL=RUBBER
*MATERIAL, NAME=RUBBER
)" + material + step;
}

const model::Hyperelastic& read_law(const DeckDir& dir, const std::string& material, ReadResult& r) {
  r = dir.read(cube(material));
  EXPECT_TRUE(r.ok()) << r.report();
  return *r.model.materials.at("RUBBER").hyperelastic;
}

TEST(HyperelasticKeyword, EachFormReadsItsCoefficientsAndDs) {
  DeckDir dir;
  ReadResult r;
  struct Case {
    std::string text;
    Form form;
    int n;
    std::vector<double> c, d;
  };
  const std::vector<Case> cases = {
      {"*HYPERELASTIC, NEO HOOKE\n1.5, 0.02\n", Form::ReducedPolynomial, 1, {1.5}, {0.02}},
      {"*HYPERELASTIC,NEOHOOKE\n1.5, 0.02, 20.\n", Form::ReducedPolynomial, 1, {1.5}, {0.02}},  // + temperature
      {"*HYPERELASTIC, MOONEY-RIVLIN\n1., 0.2, 0.01\n", Form::Polynomial, 1, {1, 0.2}, {0.01}},
      {"*HYPERELASTIC\n1., 0.2, 0.01\n", Form::Polynomial, 1, {1, 0.2}, {0.01}},  // POLYNOMIAL, N=1 by default
      {"*HYPERELASTIC, POLYNOMIAL, N=2\n1., 0.2, 0.3, 0.4, 0.5, 0.01, 0.02\n", Form::Polynomial, 2,
       {1, 0.2, 0.3, 0.4, 0.5}, {0.01, 0.02}},
      {"*HYPERELASTIC, REDUCED POLYNOMIAL, N=3\n1., 0.2, 0.3, 0.01, 0., 0.\n", Form::ReducedPolynomial, 3,
       {1, 0.2, 0.3}, {0.01, 0, 0}},
      {"*HYPERELASTIC, YEOH\n1., -0.2, 0.3, 0.01, 0.02, 0.03\n", Form::ReducedPolynomial, 3, {1, -0.2, 0.3},
       {0.01, 0.02, 0.03}},
      {"*HYPERELASTIC, ARRUDA-BOYCE\n2., 3., 0.01\n", Form::ArrudaBoyce, 1, {2, 3}, {0.01}},
      {"*HYPERELASTIC, OGDEN, N=1\n3.488, 2.163, 0.\n", Form::Ogden, 1, {3.488, 2.163}, {0}},
      {"*HYPERELASTIC, OGDEN, N=3\n1., 2., 3., 4., 5., 6., 0.1, 0.2\n0.3\n", Form::Ogden, 3, {1, 2, 3, 4, 5, 6},
       {0.1, 0.2, 0.3}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const model::Hyperelastic& h = read_law(dir, c.text, r);
    EXPECT_EQ(h.form, c.form);
    EXPECT_EQ(h.order, c.n);
    EXPECT_EQ(h.coefficients, c.c);
    EXPECT_EQ(h.d, c.d);
  }
}

TEST(HyperelasticKeyword, NlgeomIsSwitchedOnForAHyperelasticModel) {
  DeckDir dir;
  auto r = dir.read(cube("*HYPERELASTIC, NEO HOOKE\n1.5, 0.02\n",
                         "*STEP\n*STATIC\n*END STEP\n*STEP, NLGEOM\n*STATIC\n*END STEP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.steps.size(), 2u);
  EXPECT_TRUE(r.model.steps[0].nlgeom);
  EXPECT_TRUE(r.model.steps[0].nlgeom_switched_on);
  EXPECT_TRUE(r.model.steps[1].nlgeom);
  EXPECT_FALSE(r.model.steps[1].nlgeom_switched_on);
}

TEST(HyperelasticKeyword, AnElasticModelKeepsItsSmallStrainSteps) {
  DeckDir dir;
  auto r = dir.read(cube("*ELASTIC\n100., 0.3\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_FALSE(r.model.steps[0].nlgeom);
}

TEST(HyperelasticKeyword, BadDefinitionsAreDeckErrors) {
  DeckDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"*HYPERELASTIC, NEO HOOKE\n1.5\n", "expected 2 coefficients"},
      {"*HYPERELASTIC, POLYNOMIAL, N=3\n1., 0.2, 0.01\n", "N=3 is not supported for POLYNOMIAL"},
      {"*HYPERELASTIC, NEO HOOKE, N=2\n1., 0.01\n", "NEO HOOKE takes no N"},
      {"*HYPERELASTIC, NEO HOOKE, OGDEN\n1., 0.01\n", "two strain-energy forms"},
      {"*HYPERELASTIC, NEO HOOKE\n1., -0.01\n", "must not be negative"},
      {"*HYPERELASTIC, NEO HOOKE\n1., 0.01, 20.\n1.1, 0.01, 40.\n", "temperature-dependent data"},
      {"*HYPERELASTIC, MARLOW\n1., 0.01\n", "MARLOW is not supported yet"},
      {"*HYPERELASTIC, NEO HOOKE\n1., 0.01\n*ELASTIC\n100., 0.3\n", "has both *ELASTIC and *HYPERELASTIC"},
      {"*HYPERELASTIC, NEO HOOKE\n1., 0.01\n*EXPANSION\n1e-5\n", "thermal expansion of a hyperelastic material"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    auto r = dir.read(cube(text));
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_diagnostic(r, message)) << r.report();
  }
}

}  // namespace
}  // namespace inpact::parser
