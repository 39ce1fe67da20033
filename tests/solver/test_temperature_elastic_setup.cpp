// The laws a temperature-dependent isotropic *ELASTIC or *EXPANSION gets (solver/elastic_law.hpp):
// continuum elements take the tabulated IsotropicElastic; *PLASTIC, a directional *ELASTIC,
// trusses, beams and shells stop with "not supported yet" at the table, naming the material;
// tables of equal rows are today's constant material and go everywhere.
#include <string>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"
#include "solver/elements/material.hpp"

using namespace inpact;
using inpact::test::DeckDir;

namespace {

const char* kNodes = "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n"
                     "7, 1, 1, 1\n8, 0, 1, 1\n";

/// One C3D8 cube whose material M holds `material` from line 14 on.
std::string cube(const std::string& material) {
  return std::string(kNodes) + "*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n*MATERIAL, NAME=M\n" + material;
}

const std::string kTable = "*ELASTIC\n210000., 0.3, 0.\n100000., 0.3, 1000.\n";  // *ELASTIC on line 14

/// The message build_analysis_model stops with ("" when it does not).
std::string setup_error(const std::string& deck) {
  DeckDir dir;
  const auto r = dir.read(deck);
  if (!r.ok()) return "deck error: " + r.report();
  try {
    solver::build_analysis_model(r.model);
  } catch (const solver::AnalysisError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TemperatureElasticSetup, ContinuumElementsTakeTheTabulatedElasticLaw) {
  DeckDir dir;
  const auto r = dir.read(cube(kTable + "*EXPANSION\n1e-5, 0.\n2e-5, 1000.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const solver::AnalysisModel am = solver::build_analysis_model(r.model);
  const auto& law = *am.elements[0].material;
  EXPECT_TRUE(law.temperature_dependent());  // the assembler gathers the nodes' T for it
  ASSERT_NE(law.as_isotropic_elastic(), nullptr);
  EXPECT_EQ(law.elastic_at(500.0).youngs_modulus, 155000.0);
  EXPECT_EQ(law.elastic().youngs_modulus, 210000.0);
}

TEST(TemperatureElasticSetup, PlasticityWithTablesIsRefusedAtTheTable) {
  EXPECT_NE(setup_error(cube(kTable + "*PLASTIC\n250., 0.\n"))
                .find("deck.inp:14:1: error: *ELASTIC: temperature-dependent elastic constants (material 'M') together "
                      "with *PLASTIC is not supported yet"),
            std::string::npos)
      << setup_error(cube(kTable + "*PLASTIC\n250., 0.\n"));
  const std::string alpha = "*ELASTIC\n210000., 0.3\n*EXPANSION\n1e-5, 0.\n2e-5, 1000.\n*PLASTIC\n250., 0.\n";
  EXPECT_NE(setup_error(cube(alpha)).find("deck.inp:16:1: error: *EXPANSION: temperature-dependent expansion (material "
                                          "'M') together with *PLASTIC is not supported yet"),
            std::string::npos)
      << setup_error(cube(alpha));
  // Equal rows (CalculiX writes its constants per temperature) are no dependence at all.
  EXPECT_EQ(setup_error(cube("*ELASTIC\n210000., 0.3, 0.\n210000., 0.3, 1000.\n*PLASTIC\n250., 0.\n")), "");
}

TEST(TemperatureElasticSetup, DirectionalElasticityWithAnExpansionTableIsRefused) {
  const std::string deck = cube("*ELASTIC, TYPE=ENGINEERING CONSTANTS\n140000., 10000., 9000., 0.3, 0.28, 0.45, "
                                "5000., 4500.,\n3500., 20.\n*EXPANSION\n1e-5, 0.\n2e-5, 1000.\n");
  EXPECT_NE(setup_error(deck).find("*EXPANSION: temperature-dependent expansion (material 'M') together with a "
                                   "directional *ELASTIC is not supported yet"),
            std::string::npos)
      << setup_error(deck);
}

TEST(TemperatureElasticSetup, TrussesBeamsAndGeneralShellSectionsRefuseTables) {
  const std::string truss = std::string(kNodes) + "*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n"
                            "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n0.1\n*MATERIAL, NAME=M\n" + kTable;
  EXPECT_NE(setup_error(truss).find("together with T3D2 elements is not supported yet"), std::string::npos)
      << setup_error(truss);
  const std::string beam = std::string(kNodes) + "*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
                           "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.3, 0.2\n0., 1., 0.\n"
                           "*MATERIAL, NAME=M\n" + kTable;
  EXPECT_NE(setup_error(beam).find("together with beam elements is not supported yet"), std::string::npos)
      << setup_error(beam);
  // A shell of one isotropic material and a COMPOSITE's isotropic layers read their tables at
  // each section point (test_shell_temperature.cpp); a general section is integrated once from
  // constants.
  const std::string shell = std::string(kNodes) + "*ELEMENT, TYPE=S4, ELSET=S\n1, 1, 2, 3, 4\n"
                            "*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n*MATERIAL, NAME=M\n" + kTable;
  EXPECT_EQ(setup_error(shell), "");
  const std::string layered = std::string(kNodes) + "*ELEMENT, TYPE=S4, ELSET=S\n1, 1, 2, 3, 4\n"
                              "*SHELL SECTION, ELSET=S, COMPOSITE\n0.05, 3, M\n0.05, 3, M\n*MATERIAL, NAME=M\n" + kTable;
  EXPECT_EQ(setup_error(layered), "");
  const std::string general = std::string(kNodes) + "*ELEMENT, TYPE=S4, ELSET=S\n1, 1, 2, 3, 4\n"
                              "*SHELL GENERAL SECTION, ELSET=S, MATERIAL=M\n0.1\n*MATERIAL, NAME=M\n" + kTable;
  EXPECT_NE(setup_error(general).find("together with a general or directional shell section is not supported yet"),
            std::string::npos)
      << setup_error(general);
}
