// What *MODEL CHANGE, TYPE=ELEMENT cannot remove or reactivate yet (solver/element_activity.hpp):
// each a deck error naming the *MODEL CHANGE line, raised by build_analysis_model (check and run).
#include <gtest/gtest.h>

#include <string>

#include "analysis_error_of.hpp"
#include "fixtures/deck_fixture.hpp"

namespace inpact::test {
namespace {

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
