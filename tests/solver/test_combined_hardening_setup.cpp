// The Chaboche law's parameters from *PLASTIC and *CYCLIC HARDENING
// (solver/combined_hardening_setup.hpp): one set at every temperature any datum is given at,
// each datum interpolated between its own temperatures; half-cycle rows fitted per temperature
// against the size of the yield surface there; KINEMATIC rows per temperature as C = Δσ/Δε̄ᵖ.
#include <cmath>

#include <gtest/gtest.h>

#include "solver/analysis_error.hpp"
#include "solver/combined_hardening_setup.hpp"

namespace inpact::solver {
namespace {

using Point = model::Plastic::Point;

model::Material combined(std::vector<Point> rows, model::Plastic::CombinedData data) {
  model::Material mat;
  mat.name = "M";
  mat.plastic.emplace();
  mat.plastic->hardening = model::Plastic::Hardening::Combined;
  mat.plastic->combined_data = data;
  mat.plastic->table = std::move(rows);
  return mat;
}

/// Rows on σ⁰(ε̄ᵖ) + C/γ (1 − e^{−γ ε̄ᵖ}) at `temperature`, σ⁰ given as a function.
template <class Surface>
void add_half_cycle(std::vector<Point>& rows, Surface s0, double C, double g, double temperature) {
  for (double e : {0.0, 0.001, 0.003, 0.01, 0.03}) rows.push_back({s0(e) + C / g * (1 - std::exp(-g * e)), e, temperature});
}

TEST(CombinedHardeningSetup, HalfCycleDataAreFittedAgainstTheCyclicSurfaceAtTheirTemperature) {
  // σ⁰ from *CYCLIC HARDENING, PARAMETERS at 0 and 200 (σ|0 240 → 200, Q∞ 50 → 30, b 20);
  // half-cycle rows at T = 100 whose first row is above σ|0 there (α_1 ≠ 0).
  auto s0_100 = [](double e) { return 220.0 + 40.0 * (1 - std::exp(-20.0 * e)); };
  std::vector<Point> rows;
  add_half_cycle(rows, [&](double e) { return s0_100(e) + 0.0; }, 30000.0, 300.0, 100.0);
  for (auto& r : rows) r.yield_stress += 12.0 * std::exp(-300.0 * r.plastic_strain);  // α_1 = 12
  model::Material mat = combined(rows, model::Plastic::CombinedData::HalfCycle);
  mat.cyclic_hardening.emplace();
  mat.cyclic_hardening->parameters = {{240.0, 50.0, 20.0, 0.0}, {200.0, 30.0, 20.0, 200.0}};
  const CombinedLawData d = combined_law_data(model::Model{}, mat);
  ASSERT_EQ(d.temperatures, (std::vector<double>{0.0, 100.0, 200.0}));
  for (const auto& set : d.sets) {  // one backstress block: the same C, γ at every temperature
    ASSERT_EQ(set.backstresses.size(), 1u);
    EXPECT_NEAR(set.backstresses[0].modulus, 30000.0, 1e-6 * 30000.0);
    EXPECT_NEAR(set.backstresses[0].recovery, 300.0, 1e-6 * 300.0);
  }
  EXPECT_NEAR(d.sets[1].initial, 220.0, 1e-12);
  EXPECT_NEAR(d.sets[1].saturation, 40.0, 1e-12);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("fitted to the half-cycle data"), std::string::npos) << d.notes[0];
}

TEST(CombinedHardeningSetup, ParametersPerTemperatureAndTheFirstRowsAsTheSurface) {
  model::Material mat = combined({{250.0, 0.0, 20.0}, {150.0, 0.0, 420.0}}, model::Plastic::CombinedData::Parameters);
  mat.plastic->backstresses = {{40000.0, 400.0}, {20000.0, 200.0}};
  const CombinedLawData d = combined_law_data(model::Model{}, mat);
  ASSERT_EQ(d.temperatures, (std::vector<double>{20.0, 420.0}));
  EXPECT_EQ(d.sets[1].backstresses[0].modulus, 20000.0);
  EXPECT_EQ(d.sets[1].table_stress, (std::vector<double>{150.0}));  // σ⁰ = σ|0(T), constant in ε̄ᵖ
  EXPECT_TRUE(d.notes.empty());
}

TEST(CombinedHardeningSetup, KinematicRowsGiveTheSlopePerTemperature) {
  model::Material mat = combined({{250.0, 0.0, 20.0}, {450.0, 0.01, 20.0}, {150.0, 0.0, 420.0}, {250.0, 0.01, 420.0}},
                                 model::Plastic::CombinedData::HalfCycle);
  mat.plastic->hardening = model::Plastic::Hardening::Kinematic;
  const CombinedLawData d = combined_law_data(model::Model{}, mat);
  ASSERT_EQ(d.sets.size(), 2u);
  EXPECT_NEAR(d.sets[0].backstresses[0].modulus, 20000.0, 1e-9);
  EXPECT_NEAR(d.sets[1].backstresses[0].modulus, 10000.0, 1e-9);
  EXPECT_EQ(d.sets[1].backstresses[0].recovery, 0.0);
  EXPECT_EQ(d.sets[0].table_stress, (std::vector<double>{250.0}));
}

TEST(CombinedHardeningSetup, SofteningHalfCycleDataAreRefused) {
  const model::Material mat =
      combined({{250.0, 0.0}, {240.0, 0.01}, {230.0, 0.02}}, model::Plastic::CombinedData::HalfCycle);
  try {
    combined_law_data(model::Model{}, mat);
    FAIL() << "no error";
  } catch (const AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("do not harden"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace inpact::solver
