// What build_analysis_model() says about a model before it is analysed.
#include <gtest/gtest.h>

#include <string>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"

namespace inpact::test {
namespace {

/// The one-cube deck with element type `type` and Poisson's ratio `nu`.
std::string cube(const std::string& type, const std::string& nu) {
  std::string s = one_cube_deck();
  s.replace(s.find("TYPE=C3D8,"), 10, "TYPE=" + type + ",");
  s.replace(s.find("210000., 0.3"), 12, "210000., " + nu);
  return s;
}

// bench/contact_extremes found Hertz on CPE4 at ν = 0.4999 110 % off without a word. Fully
// integrated solids lock there; a warning now says so and names the remedy.
TEST(AnalysisModelWarnings, NearIncompressibleFullIntegrationIsWarnedAbout) {
  const DeckDir dir;
  const auto locked = dir.read(cube("C3D8", "0.4999"));
  ASSERT_TRUE(locked.ok()) << locked.report();
  const auto am = solver::build_analysis_model(locked.model);
  ASSERT_EQ(am.warnings.size(), 1u);
  EXPECT_NE(am.warnings[0].find("fully integrated C3D8 elements with Poisson's ratio 0.4999 lock"), std::string::npos);
  for (const auto& [type, nu] : {std::pair<std::string, std::string>{"C3D8R", "0.4999"}, {"C3D8I", "0.4999"}, {"C3D8", "0.495"}}) {
    const auto r = dir.read(cube(type, nu));
    ASSERT_TRUE(r.ok()) << r.report();
    EXPECT_TRUE(solver::build_analysis_model(r.model).warnings.empty()) << type << " " << nu;
  }
}

}  // namespace
}  // namespace inpact::test
