// *PLASTIC, HARDENING=COMBINED (DATATYPE=PARAMETERS) and *CYCLIC HARDENING as the reader takes
// them, and the errors for what inpact does not do (HALF CYCLE data, a set per temperature).
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
  EXPECT_EQ(m.cyclic_hardening->saturation, 80.0);
}

TEST(CombinedHardeningKeyword, CyclicHardeningTable) {
  const auto r = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250., 40000., 400.\n"
                               "*CYCLIC HARDENING\n250., 0.\n300., 0.1\n");
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.materials.at("STEEL").cyclic_hardening->table.size(), 2u);
}

TEST(CombinedHardeningKeyword, WhatIsNotSupportedSaysSo) {
  const auto half = read_material("*PLASTIC, HARDENING=COMBINED\n250., 0.\n300., 0.01\n");
  ASSERT_FALSE(half.ok());
  EXPECT_NE(half.report().find("DATATYPE=HALF CYCLE (the default) is not supported yet"), std::string::npos) << half.report();
  EXPECT_NE(half.report().find(":16:"), std::string::npos) << half.report();
  const auto two = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n250., 40000., 400., 20.\n240., 30000., 300., 100.\n");
  ASSERT_FALSE(two.ok());
  EXPECT_NE(two.report().find("more than one set"), std::string::npos) << two.report();
  const auto few = read_material("*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n250., 40000., 400.\n");
  ASSERT_FALSE(few.ok());
  EXPECT_NE(few.report().find("expected 5 values"), std::string::npos) << few.report();
}

}  // namespace
}  // namespace inpact::parser
