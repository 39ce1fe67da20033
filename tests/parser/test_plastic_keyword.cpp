// *PLASTIC: the table, HARDENING=, the temperature column and the errors of a bad table.
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {

/// The cube's material STEEL with `plastic` after its *ELASTIC (the extra text starts at line 16).
std::string with_plastic(const std::string& plastic) { return one_cube_deck(plastic); }

}  // namespace

TEST(Plastic, IsotropicTableWithTemperatureColumnOfOneTemperature) {
  DeckDir dir;
  const auto r = dir.read(with_plastic("*PLASTIC\n250., 0., 20.\n300., 0.01, 20.\n320., 0.1, 20.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& p = r.model.materials.at("STEEL").plastic;
  ASSERT_TRUE(p);
  EXPECT_EQ(p->hardening, model::Plastic::Hardening::Isotropic);
  ASSERT_EQ(p->table.size(), 3u);
  EXPECT_EQ(p->table[1].yield_stress, 300.0);
  EXPECT_EQ(p->table[1].plastic_strain, 0.01);
  EXPECT_EQ(p->loc.line, 16);
}

TEST(Plastic, IsotropicTablesInBlocksOfOneTemperature) {
  DeckDir dir;
  const auto r = dir.read(with_plastic("*PLASTIC\n250., 0., 20.\n300., 0.1, 20.\n150., 0., 400.\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  const auto& table = r.model.materials.at("STEEL").plastic->table;
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[1].temperature, 20.0);
  EXPECT_EQ(table[2].temperature, 400.0);
  EXPECT_EQ(table[2].yield_stress, 150.0);
  EXPECT_EQ(table[2].plastic_strain, 0.0);
}

TEST(Plastic, KinematicAndPerfectlyPlasticOneLine) {
  DeckDir dir;
  const auto r = dir.read(with_plastic("*PLASTIC, HARDENING=KINEMATIC\n250., 0.\n300., 0.02\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  EXPECT_EQ(r.model.materials.at("STEEL").plastic->hardening, model::Plastic::Hardening::Kinematic);
  const auto r2 = dir.read(with_plastic("*PLASTIC\n250.\n"));  // the strain defaults to 0
  ASSERT_TRUE(r2.ok()) << r2.report();
  EXPECT_EQ(r2.model.materials.at("STEEL").plastic->table.size(), 1u);
}

TEST(Plastic, BadTablesSayWhatIsWrong) {
  DeckDir dir;
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., 0.001\n")),
                             "deck.inp:17:7: error: *PLASTIC: the first yield stress must be given at zero plastic "
                             "strain, found 0.001"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., 0.\n300., 0.02\n310., 0.01\n")),
                             "deck.inp:19:7: error: *PLASTIC: the plastic strains must increase, found 0.01 after 0.02"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n-250., 0.\n")),
                             "*PLASTIC: the yield stress must be positive, found -250"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., 0., 100.\n300., 0.1, 100.\n240., 0., 20.\n")),
                             "deck.inp:19:11: error: *PLASTIC: the temperatures must increase from block to block, "
                             "found 20 after 100"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., 0., 20.\n300., 0.1, 20.\n240., 0.01, 100.\n")),
                             "deck.inp:19:7: error: *PLASTIC: the first yield stress at temperature 100 must be given "
                             "at zero plastic strain, found 0.01"));
  EXPECT_TRUE(dir.read(with_plastic("*PLASTIC, HARDENING=KINEMATIC\n250., 0., 20.\n300., 0.1, 20.\n240., 0., 100.\n"))
                  .ok());  // kinematic hardening per temperature
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC, HARDENING=JOHNSON COOK\n250., 0.\n")),
                             "*PLASTIC: HARDENING=JOHNSONCOOK is not supported yet (ISOTROPIC, KINEMATIC or COMBINED)"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., 0.\n*PLASTIC\n260., 0.\n")),
                             "*PLASTIC: *PLASTIC is given twice in this material"));
  EXPECT_TRUE(has_diagnostic(dir.read(with_plastic("*PLASTIC\n250., abc\n")), "deck.inp:17:"));
}
