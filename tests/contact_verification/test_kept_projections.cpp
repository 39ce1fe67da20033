// A surface-to-surface point keeps its closest master facet without a search while no other facet
// can have come within the search's tolerance (SurfaceToSurfacePair::reproject). Run with
// contact::projection_self_check, every kept projection is compared with the search's own, to
// the bit, and a difference throws: on decks that move the master as a body (the default job's
// pin), slide with friction, smooth, and touch themselves (self contact), in 2D and 3D.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "contact/surface_to_surface.hpp"
#include "contact_verification/contact_verification.hpp"

namespace inpact::contact_verification {
namespace {

struct SelfCheck {
  SelfCheck() { contact::projection_self_check = true; }
  ~SelfCheck() { contact::projection_self_check = false; }
};

void expect_kept_projections_are_the_searchs(const std::string& path, const std::map<std::string, std::string>& params) {
  const SelfCheck on;
  const auto r = run(path, params);  // (a differing projection throws out of it)
  EXPECT_TRUE(r->outcome.completed) << r->outcome.message;
}

std::string contact_deck(const std::string& name) { return std::string(INPACT_SOURCE_DIR) + "/decks/contact/" + name + ".inp"; }

const std::map<std::string, std::string> kSurfaceToSurface{{"type", "SURFACE TO SURFACE"}};

TEST(KeptProjections, PinPushedIntoItsHoleSmoothedWithFriction) {
  expect_kept_projections_are_the_searchs(std::string(INPACT_SOURCE_DIR) + "/decks/pin_in_hole.inp", {});
}
TEST(KeptProjections, Sphere3d) { expect_kept_projections_are_the_searchs(deck_path("sphere_3d"), kSurfaceToSurface); }
TEST(KeptProjections, Hertz2d) { expect_kept_projections_are_the_searchs(deck_path("hertz_2d"), kSurfaceToSurface); }
TEST(KeptProjections, InterferenceSmoothed2d) {
  expect_kept_projections_are_the_searchs(deck_path("interference_2d_smoothed"), kSurfaceToSurface);
}
TEST(KeptProjections, FrictionSlide3d) { expect_kept_projections_are_the_searchs(contact_deck("friction_slide_3d_direct"), {}); }
TEST(KeptProjections, SelfContact2d) { expect_kept_projections_are_the_searchs(contact_deck("patch_2d_self_s2s"), {}); }

}  // namespace
}  // namespace inpact::contact_verification
