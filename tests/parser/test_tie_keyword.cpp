// *TIE: parameters, defaults and data lines (parser/kw_tie.cpp).
#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"

using namespace inpact;
using inpact::test::DeckDir;
using inpact::test::has_diagnostic;
using inpact::test::one_cube_deck;

namespace {
std::string with_tie(const std::string& tie) {
  return one_cube_deck("*SURFACE, NAME=TOP\nCUBE, S2\n*SURFACE, NAME=BOTTOM\nCUBE, S1\n*NSET, NSET=TN\n1\n" + tie +
                       "*STEP\n*STATIC\n*END STEP\n");
}
}  // namespace

TEST(TieKeyword, DefaultsAreAbaqusStandards) {
  DeckDir dir;
  auto r = dir.read(with_tie("*TIE, NAME=Glue\nTOP, BOTTOM\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.ties.size(), 1u);
  const auto& t = r.model.ties[0];
  EXPECT_EQ(t.name, "GLUE");
  EXPECT_EQ(t.slave, "TOP");
  EXPECT_EQ(t.master, "BOTTOM");
  EXPECT_EQ(t.type, model::Tie::Type::SurfaceToSurface);
  EXPECT_TRUE(t.adjust);
  EXPECT_FALSE(t.position_tolerance);
  EXPECT_TRUE(t.tied_nset.empty());
  EXPECT_FALSE(t.no_rotation);
}

TEST(TieKeyword, ParametersAreRead) {
  DeckDir dir;
  auto r = dir.read(with_tie("*TIE, NAME=G, POSITION TOLERANCE=0.2, ADJUST=NO, TYPE=NODE TO SURFACE, NO ROTATION\nTOP, BOTTOM\n"
                             "*TIE, NAME=H, TIED NSET=TN\nBOTTOM, TOP\n"));
  ASSERT_TRUE(r.ok()) << r.report();
  ASSERT_EQ(r.model.ties.size(), 2u);
  const auto& g = r.model.ties[0];
  EXPECT_EQ(*g.position_tolerance, 0.2);
  EXPECT_FALSE(g.adjust);
  EXPECT_EQ(g.type, model::Tie::Type::NodeToSurface);
  EXPECT_TRUE(g.no_rotation);
  EXPECT_EQ(r.model.ties[1].tied_nset, "TN");
}

TEST(TieKeyword, BadInputIsReportedWithItsPlace) {
  DeckDir dir;
  auto r = dir.read(with_tie("*TIE, NAME=G, POSITION TOLERANCE=0.1, TIED NSET=TN\nTOP, BOTTOM\n"
                             "*TIE, NAME=C, CYCLIC SYMMETRY\nTOP, BOTTOM\n*TIE, NAME=S\nTOP, TOP\n*TIE, NAME=U\nTOP, NOPE\n"
                             "*TIE, NAME=D\nTOP, BOTTOM\n*TIE, NAME=D\nBOTTOM, TOP\n"));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(has_diagnostic(r, "*TIE: POSITION TOLERANCE and TIED NSET are mutually exclusive")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*TIE: CYCLIC SYMMETRY is not supported by inpact yet")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*TIE: the slave and the master surface of a tie must differ")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*TIE: surface 'NOPE' is not defined")) << r.report();
  EXPECT_TRUE(has_diagnostic(r, "*TIE: tie name 'D' is used already (line")) << r.report();
}
