// Temperature-dependent isotropic *ELASTIC and *EXPANSION (elements/temperature_tables.hpp):
// E, ν and α linear between the rows and held outside them; the secant thermal strain
// α(T)(T − T⁰) − α(Tᴵ)(Tᴵ − T⁰); IsotropicElastic with tables giving D(T) and its stress at a
// point's temperature; the element kernels with tables at a uniform temperature giving the
// constant law of E(T), ν(T) and the same thermal strain (hourglass control and plane stress
// thickness strain included).
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "solver/elements/material.hpp"
#include "solver/elements/temperature_tables.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::distorted_coords;
using inpact::test::nodal_field;
using model::ElementFamily;

namespace {

// E falls from 200000 to 120000 between 0 and 500 and to 60000 at 1000; ν rises.
const ElasticTable kElastic{{0.0, 500.0, 1000.0}, {200000.0, 120000.0, 60000.0}, {0.3, 0.32, 0.36}};
// α rises from 1e-5 to 2e-5 between 100 and 900; reference temperature T⁰ = 20.
const ExpansionTable kExpansion{{100.0, 900.0}, {1e-5, 2e-5}, 20.0};

/// The first rows as the constant constants elastic() reports.
ElasticConstants first_rows() { return {kElastic.youngs_modulus[0], kElastic.poissons_ratio[0], kExpansion.alpha[0]}; }

IsotropicElastic tabulated(ElementFamily family) {
  return IsotropicElastic(family, first_rows(), kElastic, kExpansion);
}

Vec6 stress_at(const Material& m, const Vec6& strain, double thermal_strain, double temperature) {
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Vec6 s;
  Mat6 scratch;
  m.update({F, strain, thermal_strain, nullptr, false, temperature}, {}, s, scratch);
  return s;
}

}  // namespace

TEST(TemperatureTables, ElasticConstantsAreLinearBetweenTheRowsAndHeldOutside) {
  const ElasticConstants base{1.0, 0.0, 7e-6};
  const ElasticConstants at_250 = elastic_constants_at(kElastic, 250.0, base);
  EXPECT_NEAR(at_250.youngs_modulus, 160000.0, 1e-10);
  EXPECT_NEAR(at_250.poissons_ratio, 0.31, 1e-15);
  EXPECT_EQ(at_250.expansion, 7e-6);  // α is not the elastic table's
  EXPECT_NEAR(elastic_constants_at(kElastic, 750.0, base).youngs_modulus, 90000.0, 1e-10);
  EXPECT_EQ(elastic_constants_at(kElastic, 500.0, base).youngs_modulus, 120000.0);  // a row exactly
  EXPECT_EQ(elastic_constants_at(kElastic, -40.0, base).youngs_modulus, 200000.0);  // below: the first row
  EXPECT_EQ(elastic_constants_at(kElastic, 1500.0, base).poissons_ratio, 0.36);     // above: the last row
  EXPECT_NEAR(expansion_at(kExpansion, 500.0), 1.5e-5, 1e-20);
  EXPECT_EQ(expansion_at(kExpansion, 0.0), 1e-5);
  EXPECT_EQ(expansion_at(kExpansion, 1000.0), 2e-5);
}

TEST(TemperatureTables, ThermalStrainIsTheSecantRuleLessItsValueAtTheInitialTemperature) {
  // T = 500 from Tᴵ = 300: α(500) = 1.5e-5, α(300) = 1.25e-5, T⁰ = 20:
  // ε_th = 1.5e-5 · 480 − 1.25e-5 · 280 = 7.2e-3 − 3.5e-3 = 3.7e-3.
  EXPECT_NEAR(thermal_strain(kExpansion, 500.0, 300.0), 3.7e-3, 1e-17);
  EXPECT_EQ(thermal_strain(kExpansion, 300.0, 300.0), 0.0);  // none at the initial temperature
  // Outside the table α is held: from 0 to 50, α = 1e-5 throughout: α (T − Tᴵ).
  EXPECT_NEAR(thermal_strain(kExpansion, 50.0, 0.0), 1e-5 * 50.0, 1e-18);
  // A constant α: α (T − Tᴵ) whatever T⁰.
  const ExpansionTable constant{{0.0, 1000.0}, {1.2e-5, 1.2e-5}, 300.0};
  EXPECT_NEAR(thermal_strain(constant, 700.0, 100.0), 1.2e-5 * 600.0, 1e-17);
}

TEST(IsotropicElasticWithTables, StressAndTangentAreThoseOfTheConstantsAtThePointsTemperature) {
  const Vec6 strain = (Vec6() << 1.2e-3, -0.4e-3, 0.7e-3, 2.0e-3, -1.1e-3, 0.3e-3).finished();
  const double eth = 3e-4, h = 1e-6;
  for (ElementFamily family :
       {ElementFamily::Solid3D, ElementFamily::PlaneStrain, ElementFamily::PlaneStress, ElementFamily::Axisymmetric}) {
    const IsotropicElastic law = tabulated(family);
    for (double T : {-50.0, 250.0, 500.0, 800.0, 2000.0}) {
      const Mat6 expected = elasticity_matrix(family, elastic_constants_at(kElastic, T, first_rows()));
      const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      Vec6 s;
      Mat6 scratch;
      const Mat6 D = law.update({F, strain, eth, nullptr, false, T}, {}, s, scratch);
      EXPECT_EQ(D, expected) << "T = " << T;  // the one rule, no other arithmetic
      Vec6 mechanical = strain;
      mechanical.head<3>().array() -= eth;
      EXPECT_LE((s - expected * mechanical).norm(), 1e-14 * s.norm()) << "T = " << T;
      // The tangent at fixed T is the central difference (σ linear in ε: round-off only).
      for (int j = 0; j < 6; ++j) {
        Vec6 plus = strain, minus = strain;
        plus(j) += h;
        minus(j) -= h;
        const Vec6 fd = (stress_at(law, plus, eth, T) - stress_at(law, minus, eth, T)) / (2 * h);
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(D(i, j), fd(i), 1e-8 * 200000.0) << "D" << i << j;
      }
    }
  }
}

TEST(IsotropicElasticWithTables, ReadsTheTemperatureAndGivesTheSecantThermalStrain) {
  const IsotropicElastic law = tabulated(ElementFamily::Solid3D);
  EXPECT_TRUE(law.temperature_dependent());
  EXPECT_NE(law.as_isotropic_elastic(), nullptr);  // still the kernels' elastic fast path
  // ΔT = T − Tᴵ: the point went from 300 to 500.
  EXPECT_EQ(law.thermal_strain(500.0, 200.0), thermal_strain(kExpansion, 500.0, 300.0));
  EXPECT_EQ(law.elastic_at(750.0).youngs_modulus, elastic_constants_at(kElastic, 750.0, {}).youngs_modulus);
  // Only α tabulated: E, ν constant, the tangent the constant D.
  const IsotropicElastic alpha_only(ElementFamily::Solid3D, first_rows(), std::nullopt, kExpansion);
  EXPECT_TRUE(alpha_only.temperature_dependent());
  Vec6 s;
  Mat6 scratch;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  EXPECT_EQ(&alpha_only.update({F, Vec6::Zero(), 0.0, nullptr, false, 800.0}, {}, s, scratch), &alpha_only.D());
  // Without tables: today's law, α ΔT, no temperature read.
  const IsotropicElastic constant(ElementFamily::Solid3D, first_rows());
  EXPECT_FALSE(constant.temperature_dependent());
  EXPECT_EQ(constant.thermal_strain(500.0, 200.0), 1e-5 * 200.0);
}

TEST(IsotropicElasticWithTables, PlaneStressThicknessStrainTakesPoissonsRatioAtTheTemperature) {
  const IsotropicElastic law = tabulated(ElementFamily::PlaneStress);
  const Vec6 strain = (Vec6() << 1e-3, 2e-3, 0, 0, 0, 0).finished();
  const double eth = 5e-4, T = 750.0, nu = 0.34;  // ν(750) halfway between 0.32 and 0.36
  const double expected = -nu / (1 - nu) * (strain(0) + strain(1) - 2 * eth) + eth;
  EXPECT_NEAR(law.plane_stress_thickness_strain({}, strain, Vec6::Zero(), eth, T, {}), expected, 1e-15);
}

// Every node at T = 640 from Tᴵ = 180: the tabulated law must give what the constant law of
// E(640), ν(640) and α with α ΔT = ε_th(640, 180) gives — stiffness, force and point output,
// on the fast C3D8 path, the generic one, reduced elements with hourglass control (G(T)),
// incompatible modes and plane stress (ε33 from ν(T)).
TEST(ElementsWithTables, MatchTheConstantLawOfTheConstantsAtAUniformTemperature) {
  const double T = 640.0, T_initial = 180.0;
  ElasticConstants at_T = elastic_constants_at(kElastic, T, first_rows());
  at_T.expansion = thermal_strain(kExpansion, T, T_initial) / (T - T_initial);
  for (const char* name : {"C3D8", "C3D8R", "C3D20R", "C3D8I", "CPS4R", "CPS8", "CPE4", "CAX8R"}) {
    const model::ElementTypeInfo& t = *model::find_element_type(name);
    const auto x = distorted_coords(t);
    const auto u = nodal_field(t, x, [](const Vec3& p) -> Vec3 {
      return {1e-3 * p[1] * p[1], -2e-3 * p[0] * p[1], 0.5e-3 * p[2] * p[0]};
    });
    const std::vector<double> dT(t.n_nodes, T - T_initial), temperature(t.n_nodes, T);
    ElementRequest req;
    req.point_output = true;
    ElementSystem expected;
    compute_element(t, x, u, IsotropicElastic(t.family, at_T), SectionData{}, req, dT, ElementHistory{}, expected);
    req.temperature = temperature;
    ElementSystem got;
    compute_element(t, x, u, tabulated(t.family), SectionData{}, req, dT, ElementHistory{}, got);
    const Eigen::Map<const Eigen::VectorXd> k_exp(expected.stiffness.data(), expected.stiffness.size());
    const Eigen::Map<const Eigen::VectorXd> k_got(got.stiffness.data(), got.stiffness.size());
    EXPECT_LE((k_got - k_exp).norm(), 1e-13 * k_exp.norm()) << name;
    const Eigen::Map<const Eigen::VectorXd> f_exp(expected.internal_force.data(), expected.internal_force.size());
    const Eigen::Map<const Eigen::VectorXd> f_got(got.internal_force.data(), got.internal_force.size());
    EXPECT_LE((f_got - f_exp).norm(), 1e-12 * f_exp.norm()) << name;
    ASSERT_EQ(got.points.size(), expected.points.size());
    for (std::size_t p = 0; p < got.points.size(); ++p)
      for (int k = 0; k < 6; ++k) {
        EXPECT_NEAR(got.points[p].stress[k], expected.points[p].stress[k], 1e-10) << name << " S" << k;
        EXPECT_NEAR(got.points[p].strain[k], expected.points[p].strain[k], 1e-16) << name << " E" << k;
      }
  }
}
