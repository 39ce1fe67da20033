// What an analytical rigid surface must be before an analysis (solver/analytical_contact.hpp):
// each violation a deck error naming the line, raised by build_analysis_model (so by check as
// by run). The deck: decks/verification/rigid_punch_segments_cpe4.inp, edited.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "analysis_error_of.hpp"
#include "fixtures/deck_fixture.hpp"

namespace inpact::test {
namespace {

std::string punch_deck() {
  std::ifstream in(std::string(INPACT_SOURCE_DIR) + "/decks/verification/rigid_punch_segments_cpe4.inp");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The deck with `from` replaced by `to` (which must be there).
std::string edited(const std::string& from, const std::string& to) {
  std::string s = punch_deck();
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

TEST(AnalyticalContactChecks, TheDeckItselfPasses) { EXPECT_EQ(analysis_error(punch_deck()), ""); }

TEST(AnalyticalContactChecks, ABadProfileNamesItsSegmentLine) {
  const std::string e = analysis_error(edited("LINE, 0, 2", "CIRCL, 0, 2.2, 1, 2"));
  EXPECT_NE(e.find("deck.inp:95:1: error: *SURFACE: analytical surface 'PUNCH_BOTTOM': CIRCL: the end point is"),
            std::string::npos)
      << e;
}

TEST(AnalyticalContactChecks, AnAnalyticalSlaveAndAnUncarriedSurfaceAreRefused) {
  std::string e = analysis_error(edited("BLOCK_TOP, PUNCH_BOTTOM", "PUNCH_BOTTOM, BLOCK_TOP"));
  EXPECT_NE(e.find("the analytical surface PUNCH_BOTTOM can only be a master surface"), std::string::npos) << e;
  e = analysis_error(edited("*RIGID BODY, REF NODE=REF, ANALYTICAL SURFACE=PUNCH_BOTTOM",
                            "*SURFACE, TYPE=SEGMENTS, NAME=LOOSE\nSTART, 0, 3\nLINE, 1, 3\n"
                            "*RIGID BODY, REF NODE=REF, ANALYTICAL SURFACE=PUNCH_BOTTOM"));
  EXPECT_NE(e.find("error: *SURFACE: analytical surface 'LOOSE' moves with nothing"), std::string::npos) << e;
}

}  // namespace
}  // namespace inpact::test
