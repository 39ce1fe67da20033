// *PLASTIC, HARDENING=COMBINED (HALF CYCLE and PARAMETERS, a set per temperature) and *CYCLIC
// HARDENING as the reader takes them, and the errors for what inpact does not do.
#include <gtest/gtest.h>

#include <string>

#include "fixtures/deck_fixture.hpp"

namespace inpact::parser {
namespace {

/// The cube deck's material STEEL with `lines` after its *ELASTIC (they start at line 16).
ReadResult read_material(const std::string& lines) {
  static test::DeckDir dir;
  return dir.read(test::one_cube_deck(lines));
}

TEST(CombinedHardeningKeyword, ParametersGiveTheBackstressesAndTheSurface) {
  const auto r = read_material("*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n"
                               "250., 40000., 400., 5000.,\n20.\n*CYCLIC HARDENING, PARAMETERS\n250., 80., 10.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model.materials.at("STEEL");
  ASSERT_TRUE(m.plastic && m.cyclic_hardening);
  EXPECT_EQ(m.plastic->hardening, model::Plastic::Hardening::Combined);
  ASSERT_EQ(m.plastic->backstresses.size(), 2u);
  EXPECT_EQ(m.plastic->backstresses[1].modulus, 5000.0);
  EXPECT_EQ(m.plastic->backstresses[1].recovery, 20.0);
  EXPECT_EQ(m.plastic->table.front().yield_stress, 250.0);
  ASSERT_EQ(m.cyclic_hardening->parameters.size(), 1u);
  EXPECT_EQ(m.cyclic_hardening->parameters[0].saturation, 80.0);
}

TEST(CombinedHardeningKeyword, CyclicHardeningTable) {
  const auto r = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250., 40000., 400.\n"
                               "*CYCLIC HARDENING\n250., 0.\n300., 0.1\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.materials.at("STEEL").cyclic_hardening->table.size(), 2u);
}

TEST(CombinedHardeningKeyword, HalfCycleRowsAreTheTable) {
  const auto r = read_material("*PLASTIC, HARDENING=COMBINED\n250., 0.\n300., 0.01\n330., 0.02\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& p = *r.model.materials.at("STEEL").plastic;
  EXPECT_EQ(p.combined_data, model::Plastic::CombinedData::HalfCycle);
  ASSERT_EQ(p.table.size(), 3u);
  EXPECT_EQ(p.table[2].yield_stress, 330.0);
  EXPECT_TRUE(p.backstresses.empty());
}

TEST(CombinedHardeningKeyword, ASetPerTemperature) {
  const auto r = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250., 40000., 400., 20.\n"
                               "240., 30000., 300., 100.\n*CYCLIC HARDENING, PARAMETERS\n250., 80., 10., 20.\n"
                               "240., 60., 12., 100.\n");
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& m = r.model.materials.at("STEEL");
  ASSERT_EQ(m.plastic->table.size(), 2u);
  EXPECT_EQ(m.plastic->table[1].temperature, 100.0);
  EXPECT_EQ(m.plastic->table[1].yield_stress, 240.0);
  ASSERT_EQ(m.plastic->backstresses.size(), 2u);
  EXPECT_EQ(m.plastic->backstresses[1].modulus, 30000.0);
  ASSERT_EQ(m.cyclic_hardening->parameters.size(), 2u);
  EXPECT_EQ(m.cyclic_hardening->parameters[1].rate, 12.0);
  const auto down = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250., 40000., 400., 100.\n"
                                  "240., 30000., 300., 20.\n");
  ASSERT_FALSE(down.ok());
  EXPECT_NE(down.report().find(":18:21:"), std::string::npos) << down.report();
  EXPECT_NE(down.report().find("must increase"), std::string::npos) << down.report();
}

TEST(CombinedHardeningKeyword, WhatIsNotSupportedSaysSo) {
  const auto stabilized = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=STABILIZED\n250., 0.\n");
  ASSERT_FALSE(stabilized.ok());
  EXPECT_NE(stabilized.report().find("DATATYPE=STABILIZED"), std::string::npos) << stabilized.report();
  EXPECT_NE(stabilized.report().find(":16:"), std::string::npos) << stabilized.report();
  const auto two = read_material("*PLASTIC, HARDENING=COMBINED, NUMBER BACKSTRESSES=2\n250., 0.\n300., 0.01\n");
  ASSERT_FALSE(two.ok());
  EXPECT_NE(two.report().find("fits one backstress"), std::string::npos) << two.report();
  const auto few = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n250., 40000., 400.\n");
  ASSERT_FALSE(few.ok());
  EXPECT_NE(few.report().find("expected 5 values"), std::string::npos) << few.report();
}

}  // namespace
}  // namespace inpact::parser
