// *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN on a unit cube (C3D8, E = 210000, ν = 0.3, σ_y = 250):
// an isochoric initial plastic strain εᵖ = (5e-4, −2.5e-4, −2.5e-4, 0, 0, 0) is
//  - stress free in a cube held just against rigid motion: the cube takes the strain εᵖ,
//    U(1, 1, 1) = (5e-4, −2.5e-4, −2.5e-4), S = 0;
//  - σ = −D εᵖ = −2G εᵖ (deviatoric) in a cube held at every node (q = 3G εᵖ11 = 121 < σ_y).
// PEEQ stays 0 (the hardening is TYPE=HARDENING's, not set here), PE is the given strain.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures/deck_fixture.hpp"
#include "solver/analysis.hpp"
#include "solver/analysis_error.hpp"
#include "solver/analysis_model.hpp"

using namespace inpact;
using namespace inpact::solver;

namespace {

struct Frames final : AnalysisObserver {
  void frame(const Frame& f) override { frames.push_back(f); }
  std::vector<Frame> frames;
};

const FieldData& field(const Frame& f, const std::string& key) {
  for (const auto& fd : f.fields)
    if (fd.key == key) return fd;
  throw std::runtime_error("no field " + key);
}

std::string deck(const std::string& supports, const std::string& initial = "CUBE, , 5e-4, -2.5e-4, -2.5e-4\n") {
  return test::one_cube_deck("*PLASTIC\n250., 0.\n*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN\n" + initial +
                             "*STEP\n*STATIC\n1., 1.\n*BOUNDARY\n" + supports +
                             "*OUTPUT, FIELD\n*NODE OUTPUT\nU\n*ELEMENT OUTPUT\nS, PE, PEEQ\n*END STEP\n");
}

Frame run(const std::string& text) {
  test::DeckDir dir;
  const auto r = dir.read(text);
  EXPECT_TRUE(r.ok()) << r.report();
  Frames obs;
  const AnalysisOutcome outcome = run_analysis(r.model, obs);
  EXPECT_TRUE(outcome.completed) << outcome.message;
  return obs.frames.back();
}

}  // namespace

TEST(InitialPlasticStrain, FreeCubeTakesThePlasticStrainStressFree) {
  const Frame f = run(deck("1, 1, 3\n2, 2, 3\n4, 3, 3\n4, 1, 1\n"));
  const auto& u = field(f, "U");
  EXPECT_NEAR(u.values[6 * 3 + 0], 5e-4, 1e-12);  // node 7 at (1, 1, 1)
  EXPECT_NEAR(u.values[6 * 3 + 1], -2.5e-4, 1e-12);
  EXPECT_NEAR(u.values[6 * 3 + 2], -2.5e-4, 1e-12);
  for (double s : field(f, "S").values) EXPECT_NEAR(s, 0.0, 1e-7);
  const auto& pe = field(f, "PE").values;
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_EQ(pe[6 * p], 5e-4);
    EXPECT_EQ(pe[6 * p + 1], -2.5e-4);
    EXPECT_EQ(field(f, "PEEQ").values[p], 0.0);
  }
}

TEST(InitialPlasticStrain, HeldCubeCarriesMinusTwoGTimesThePlasticStrain) {
  const Frame f = run(deck("ALL, 1, 3\n"));
  const double G = 210000.0 / 2.6;
  const auto& s = field(f, "S").values;
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_NEAR(s[6 * p], -2 * G * 5e-4, 1e-9);
    EXPECT_NEAR(s[6 * p + 1], 2 * G * 2.5e-4, 1e-9);
    EXPECT_NEAR(s[6 * p + 3], 0.0, 1e-9);
  }
}

TEST(InitialPlasticStrain, OnePointOnly) {
  const Frame f = run(deck("ALL, 1, 3\n", "1, 3, 5e-4, -2.5e-4, -2.5e-4\n"));
  const auto& pe = field(f, "PE").values;
  for (std::size_t p = 0; p < 8; ++p) EXPECT_EQ(pe[6 * p], p == 2 ? 5e-4 : 0.0) << p;
}

TEST(InitialPlasticStrain, ElasticMaterialOrAMissingPointIsADeckError) {
  test::DeckDir dir;
  auto text = deck("ALL, 1, 3\n", "1, 9, 1e-4\n");
  const auto r = dir.read(text);
  ASSERT_TRUE(r.ok()) << r.report();
  try {
    build_analysis_model(r.model);
    ADD_FAILURE() << "no error";
  } catch (const AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("element 1 (C3D8) has 8 integration points, not 9"), std::string::npos) << e.what();
  }
  text.erase(text.find("*PLASTIC\n250., 0.\n"), 18);
  const auto r2 = dir.read(text);
  ASSERT_TRUE(r2.ok()) << r2.report();
  try {
    build_analysis_model(r2.model);
    ADD_FAILURE() << "no error";
  } catch (const AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("TYPE=PLASTIC STRAIN on element 1, whose material has no *PLASTIC"),
              std::string::npos) << e.what();
  }
}
