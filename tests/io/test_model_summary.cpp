// The model summary of `inpact check` for smoothing: each geometric-correction line with how far
// the correction moves the faceted surface (a cube inscribed in a sphere of radius √3: its face
// centres at distance 1, so 0.7321 against faces of size 2), or why it cannot be applied.
#include <sstream>

#include <gtest/gtest.h>

#include "contact/contact_test_util.hpp"
#include "io/model_summary.hpp"
#include "parser/read_deck.hpp"

using namespace inpact;

TEST(ModelSummary, SmoothingLinesShowTheLargestCorrection) {
  std::vector<contact::Vec3> x;
  for (const auto& s : std::vector<std::array<double, 3>>{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}})
    x.push_back(s);
  model::Model m = test::elements_model("C3D8", x, {{0, 1, 2, 3, 4, 5, 6, 7}}, {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}});
  m.general_contact.defined = true;
  model::GeometricCorrection sphere;
  sphere.kind = model::GeometricCorrection::Kind::Spherical;
  sphere.surface = "S";
  m.general_contact.geometric_corrections.push_back(sphere);
  model::GeometricCorrection axis = sphere;
  axis.kind = model::GeometricCorrection::Kind::Circumferential;
  axis.a = {1, 1, 0};
  axis.b = {1, 1, 1};
  model::SurfaceSmoothing sm;
  sm.name = "SM";
  sm.corrections.push_back(axis);
  m.surface_smoothings["SM"] = sm;

  std::ostringstream out;
  io::write_model_summary(out, m);
  const std::string s = out.str();
  EXPECT_NE(s.find("  smoothing assignments:\n    S SPHERICAL a=(0, 0, 0)\n"
                   "      faceted to idealised: largest distance 0.7321, characteristic length 2 (36.6%)\n"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("Surface smoothing SM\n    S CIRCUMFERENTIAL a=(1, 1, 0) b=(1, 1, 1)\n"
                   "      cannot be applied: CIRCUMFERENTIAL correction of surface S: node 3 lies on the axis of "
                   "revolution, where it has no radial direction\n"),
            std::string::npos)
      << s;
}

// `inpact check` on the pre-tension bar (decks/verification/pretension_bar.inp): the section's
// node, its normal (the average of the lower half's top faces), its area 10 × 10 and the cut.
TEST(ModelSummary, PretensionSectionLineShowsNodeNormalAreaAndCut) {
  const auto r = parser::read_deck(std::string(INPACT_SOURCE_DIR) + "/decks/verification/pretension_bar.inp");
  ASSERT_TRUE(r.ok()) << r.report();
  std::ostringstream out;
  io::write_model_summary(out, r.model);
  const std::string s = out.str();
  EXPECT_NE(s.find("Pre-tension sections    1\n  CUT: pre-tension node 9001, normal (0, 0, 1) (the surface's average), "
                   "area 100\n    9 section node(s) copied, 4 element(s) on the underlying side use the copies\n"),
            std::string::npos)
      << s;
}
