// What *MODEL CHANGE, TYPE=ELEMENT cannot remove or reactivate yet (solver/element_activity.hpp):
// each a deck error naming the *MODEL CHANGE line, raised by build_analysis_model (check and run).
#include <gtest/gtest.h>

#include <string>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

/// The AnalysisError message building the analysis model of `deck` raises ("" when none).
std::string analysis_error(const std::string& deck) {
  const DeckDir dir;
  const auto r = dir.read(deck);
  EXPECT_TRUE(r.ok()) << r.report();
  try {
    (void)solver::build_analysis_model(r.model);
  } catch (const solver::AnalysisError& e) {
    return e.what();
  }
  return "";
}

const std::string kRemoveCube = "*STEP\n*STATIC\n*MODEL CHANGE, REMOVE\n1\n*END STEP\n";

TEST(ElementChangeChecks, ASolidElementCanBeRemoved) { EXPECT_EQ(analysis_error(one_cube_deck(kRemoveCube)), ""); }

TEST(ElementChangeChecks, AnElementUnderAContactSurfaceIsRefused) {
  const std::string e = analysis_error(one_cube_deck(
      "*NODE\n11, 0, 0, 1\n12, 1, 0, 1\n13, 1, 1, 1\n14, 0, 1, 1\n*ELEMENT, TYPE=R3D4, ELSET=PLATE\n2, 11, 12, 13, 14\n"
      "*RIGID BODY, ELSET=PLATE, REF NODE=11\n*SURFACE, NAME=TOP\n1, S2\n*SURFACE, NAME=PLATE_S\nPLATE, SPOS\n"
      "*SURFACE INTERACTION, NAME=I\n*CONTACT PAIR, INTERACTION=I\nTOP, PLATE_S\n" + kRemoveCube));
  EXPECT_NE(e.find("error: *MODEL CHANGE: element 1 (C3D8) lies under a contact surface: removing or reactivating it "
                   "is not supported yet"),
            std::string::npos)
      << e;
}

}  // namespace
}  // namespace inpact::test
