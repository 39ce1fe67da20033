// A surface-to-surface point keeps its closest master facet without a search while no other facet
// can have come within the search's tolerance (SurfaceToSurfacePair::reproject). Run with
// contact::projection_self_check, every kept projection is compared with the search's own, to
// the bit, and a difference throws: on decks that move the master as a body (the default job's
// pin), slide with friction, smooth, and touch themselves (self contact), in 2D and 3D.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "contact/initial_adjustment.hpp"
#include "contact/surface_to_surface.hpp"
#include "parser/read_deck.hpp"
#include "solver/analysis.hpp"
#include "verification/verification_fixture.hpp"

namespace inpact {
namespace {

struct SelfCheck {
  SelfCheck() { contact::projection_self_check = true; }
  ~SelfCheck() { contact::projection_self_check = false; }
};

void expect_kept_projections_are_the_searchs(const std::string& path, const std::map<std::string, std::string>& params) {
  const SelfCheck on;
  parser::ReadOptions options;
  options.parameters = params;
  auto deck = parser::read_deck(path, options);
  ASSERT_TRUE(deck.ok()) << deck.report();
  contact::apply_adjust(deck.model);
  verification::Capture capture;
  const auto outcome = solver::run_analysis(deck.model, capture, {});
  EXPECT_TRUE(outcome.completed) << outcome.message;  // (a differing projection stops the run)
}

std::string deck(const std::string& folder, const std::string& name) {
  return std::string(INPACT_SOURCE_DIR) + "/decks/" + folder + name + ".inp";
}

const std::map<std::string, std::string> kSurfaceToSurface{{"type", "SURFACE TO SURFACE"}};

TEST(KeptProjections, PinPushedIntoItsHoleSmoothedWithFriction) { expect_kept_projections_are_the_searchs(deck("", "pin_in_hole"), {}); }
TEST(KeptProjections, Sphere3d) {
  expect_kept_projections_are_the_searchs(deck("contact_verification/", "sphere_3d"), kSurfaceToSurface);
}
TEST(KeptProjections, Hertz2d) {
  expect_kept_projections_are_the_searchs(deck("contact_verification/", "hertz_2d"), kSurfaceToSurface);
}
TEST(KeptProjections, InterferenceSmoothed2d) {
  expect_kept_projections_are_the_searchs(deck("contact_verification/", "interference_2d_smoothed"), kSurfaceToSurface);
}
TEST(KeptProjections, FrictionSlide3d) { expect_kept_projections_are_the_searchs(deck("contact/", "friction_slide_3d_direct"), {}); }
TEST(KeptProjections, SelfContact2d) { expect_kept_projections_are_the_searchs(deck("contact/", "patch_2d_self_s2s"), {}); }

}  // namespace
}  // namespace inpact
