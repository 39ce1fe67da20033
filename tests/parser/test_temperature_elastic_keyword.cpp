// *ELASTIC (ISOTROPIC) and *EXPANSION with one data line per temperature: the tables, the
// temperatures strictly increasing and required once there are several lines; *DENSITY
// repeated per temperature (CalculiX decks) is one density.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;

namespace {

/// One C3D8 cube whose material M holds `material` from line 14 on.
std::string cube(const std::string& material) {
  return "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n"
         "8, 0, 1, 1\n*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n*MATERIAL, NAME=M\n" + material;
}

}  // namespace

TEST(TemperatureElastic, IsotropicRowsAreKeptWithTheFirstAsTheConstants) {
  DeckDir dir;
  const auto r = dir.read(cube("*ELASTIC\n210000., 0.3, 0.\n100000., 0.32, 1000.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const model::Elastic& e = *r.model.materials.at("M").elastic;
  EXPECT_EQ(e.youngs_modulus, 210000.);
  EXPECT_EQ(e.poissons_ratio, 0.3);
  ASSERT_EQ(e.temperature_table.size(), 2u);
  EXPECT_EQ(e.temperature_table[1].youngs_modulus, 100000.);
  EXPECT_EQ(e.temperature_table[1].poissons_ratio, 0.32);
  EXPECT_EQ(e.temperature_table[1].temperature, 1000.);
  EXPECT_TRUE(e.temperature_dependent());
  EXPECT_EQ(e.loc.line, 14);  // the *ELASTIC line
}

TEST(TemperatureElastic, OneLineOrEqualRowsDoNotDependOnTemperature) {
  DeckDir dir;
  const auto one = dir.read(cube("*ELASTIC\n210000., 0.3\n"));
  ASSERT_TRUE(one.ok()) << one.report();
  const model::Elastic& e = *one.model.materials.at("M").elastic;
  ASSERT_EQ(e.temperature_table.size(), 1u);
  EXPECT_EQ(e.temperature_table[0].temperature, 0.);
  EXPECT_FALSE(e.temperature_dependent());
  // CalculiX's beamnlt writes its constants twice, at 0 and 2000.
  const auto equal = dir.read(cube("*ELASTIC\n210000., .3, 0.\n210000., .3, 2000.\n*EXPANSION\n12.E-6, 0.\n"
                                   "12.E-6, 2000.\n*DENSITY\n7.8E-9, 0.\n7.8E-9, 2000.\n"));
  ASSERT_TRUE(equal.ok()) << equal.report();
  const model::Material& m = equal.model.materials.at("M");
  EXPECT_FALSE(m.elastic->temperature_dependent());
  EXPECT_FALSE(m.expansion->temperature_dependent());
  EXPECT_EQ(m.density, 7.8e-9);
}

TEST(TemperatureElastic, ExpansionRowsWithTheReferenceTemperature) {
  DeckDir dir;
  const auto r = dir.read(cube("*ELASTIC\n210000., 0.3\n*EXPANSION, ZERO=20.\n12.E-6, 0.\n24.E-6, 1000.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const model::Expansion& x = *r.model.materials.at("M").expansion;
  EXPECT_EQ(x.alpha, 12e-6);
  EXPECT_EQ(x.zero, 20.);
  ASSERT_EQ(x.temperature_table.size(), 2u);
  EXPECT_EQ(x.temperature_table[1].alpha, 24e-6);
  EXPECT_EQ(x.temperature_table[1].temperature, 1000.);
  EXPECT_TRUE(x.temperature_dependent());
  EXPECT_EQ(x.loc.line, 16);
}

TEST(TemperatureElastic, TemperaturesMustIncreaseAndBeGivenOnEveryLine) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3, 100.\n200000., 0.3, 100.\n")),
                             "deck.inp:16:15: error: *ELASTIC: the temperatures must increase strictly from line to "
                             "line, found 100 after 100"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3, 100.\n200000., 0.3, 20.\n")),
                             "deck.inp:16:15: error: *ELASTIC: the temperatures must increase strictly from line to "
                             "line, found 20 after 100"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3\n200000., 0.3, 20.\n")),
                             "deck.inp:15:10: error: *ELASTIC: field 3 (the temperature) is required on every data line "
                             "when there are several"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3\n*EXPANSION\n1e-5, 400.\n2e-5, 300.\n")),
                             "deck.inp:18:7: error: *EXPANSION: the temperatures must increase strictly from line to "
                             "line, found 300 after 400"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3\n*EXPANSION\n1e-5, 400.\n2e-5,\n")),
                             "deck.inp:18:1: error: *EXPANSION: field 2 (the temperature) is required on every data "
                             "line when there are several"));
}

TEST(TemperatureElastic, EachRowIsCheckedAsTheOneLineWas) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3, 0.\n-5., 0.3, 100.\n")),
                             "deck.inp:16:1: error: *ELASTIC: Young's modulus must be positive, found -5"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3, 0.\n200000., 0.5, 100.\n")),
                             "deck.inp:16:10: error: *ELASTIC: Poisson's ratio must lie in (-1, 0.5), found 0.5"));
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3, 0.\n200000., 0.3, hot\n")),
                             "deck.inp:16:15: error: *ELASTIC: field 3: expected a number, found 'hot'"));
}

TEST(TemperatureElastic, WhatStaysUnsupportedSaysSo) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(cube("*ELASTIC\n210000., 0.3\n*DENSITY\n7.8e-9, 0.\n7.7e-9, 500.\n")),
                             "deck.inp:18:1: error: *DENSITY: a temperature-dependent density (here 7.7e-09 after "
                             "7.8e-09) is not supported yet"));
}
