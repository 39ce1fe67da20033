// The material interface: the isotropic elastic law's tangent against central differences, the
// kernels' results through the interface bit for bit those of the elastic constants, a stateful
// law's history (element level), and the history store of an elastic model (zero bytes).
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "fixtures/deck_fixture.hpp"
#include "solver/analysis_model.hpp"
#include "solver/elements/material.hpp"
#include "solver/material_states.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::distorted_coords;
using inpact::test::nodal_field;
using model::ElementFamily;

namespace {

constexpr double kE = 1000.0, kNu = 0.3;
const ElasticConstants kMat{kE, kNu, 1e-3};

Vec6 stress_at(const Material& m, const Vec6& strain, double thermal_strain) {
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Vec6 s;
  Mat6 scratch;
  m.update({F, strain, thermal_strain}, {}, s, scratch);
  return s;
}

/// A law that keeps, per point, the number of evaluations' "commits" it was built on and the
/// strain ε11 it was last evaluated at: trial = (committed[0] + 1, ε11). Elastic stress.
class CountingMaterial final : public Material {
 public:
  explicit CountingMaterial(ElementFamily family) : elastic_(family, kMat) {}
  std::size_t state_size() const override { return 2; }
  const Mat6& update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                     Mat6& scratch) const override {
    point.trial[0] = point.committed[0] + 1;
    point.trial[1] = in.strain(0);
    return elastic_.update(in, {}, stress, scratch);
  }
  const ElasticConstants& elastic() const override { return elastic_.elastic(); }

 private:
  IsotropicElastic elastic_;
};

}  // namespace

TEST(IsotropicElastic, TangentIsTheCentralDifferenceOfTheStress) {
  // σ is linear in ε: the central difference is exact up to round-off, |σ| ε_machine / h
  // ≈ 1e-13 · E for h = 1e-6 — the tolerance 1e-8 E leaves a wide margin.
  const Vec6 strain = (Vec6() << 1.2e-3, -0.4e-3, 0.7e-3, 2.0e-3, -1.1e-3, 0.3e-3).finished();
  const double h = 1e-6;
  for (ElementFamily family :
       {ElementFamily::Solid3D, ElementFamily::PlaneStrain, ElementFamily::PlaneStress, ElementFamily::Axisymmetric}) {
    const IsotropicElastic law(family, kMat);
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    Vec6 s;
    Mat6 scratch;
    const Mat6& D = law.update({F, strain, 2e-4}, {}, s, scratch);
    for (int j = 0; j < 6; ++j) {
      Vec6 e_plus = strain, e_minus = strain;
      e_plus(j) += h;
      e_minus(j) -= h;
      const Vec6 fd = (stress_at(law, e_plus, 2e-4) - stress_at(law, e_minus, 2e-4)) / (2 * h);
      for (int i = 0; i < 6; ++i) EXPECT_NEAR(D(i, j), fd(i), 1e-8 * kE) << "family " << int(family) << " D" << i << j;
    }
  }
}

TEST(IsotropicElastic, StressIsHookesLawWithTheThermalStrainRemoved) {
  // Uniaxial-free thermal expansion: ε = α ΔT I on the diagonal gives no stress; then a pure
  // shear γ12 = 2e-3 gives σ12 = G γ12 (G = E / 2(1 + ν) = 384.615…).
  const IsotropicElastic law(ElementFamily::Solid3D, kMat);
  const Vec6 thermal = (Vec6() << 5e-4, 5e-4, 5e-4, 0, 0, 0).finished();
  EXPECT_LT(stress_at(law, thermal, 5e-4).norm(), 1e-15 * kE);
  const Vec6 shear = (Vec6() << 0, 0, 0, 2e-3, 0, 0).finished();
  EXPECT_NEAR(stress_at(law, shear, 0.0)(3), kE / (2 * (1 + kNu)) * 2e-3, 1e-15 * kE);
}

TEST(MaterialInterface, TheElasticLawGivesTheKernelsResultsBitForBit) {
  // The kernels through Material (the assembler's path) and through ElasticConstants (the
  // arithmetic of the version before the interface) on the fast C3D8 and the generic paths.
  for (const char* name : {"C3D8", "C3D20R", "C3D8I", "CPS4R", "CAX8", "CPE4"}) {
    const model::ElementTypeInfo& t = *model::find_element_type(name);
    const auto x = distorted_coords(t);
    const auto u = nodal_field(t, x, [](const Vec3& p) -> Vec3 {
      return {1e-2 * p[1] * p[1], -2e-2 * p[0] * p[1], 0.5e-2 * p[2] * p[0]};
    });
    const std::vector<double> dT(t.n_nodes, 3.0);
    for (bool nlgeom : {false, true}) {
      ElementRequest req;
      req.point_output = true;
      req.nlgeom = nlgeom;
      const ElementSystem a = compute_element(t, x, u, kMat, SectionData{}, req, dT);
      const IsotropicElastic law(t.family, kMat);
      ElementSystem b;
      compute_element(t, x, u, law, SectionData{}, req, dT, ElementHistory{}, b);
      EXPECT_EQ(a.stiffness, b.stiffness) << name;
      EXPECT_EQ(a.internal_force, b.internal_force) << name;
      ASSERT_EQ(a.points.size(), b.points.size());
      for (std::size_t p = 0; p < a.points.size(); ++p) EXPECT_EQ(a.points[p].stress, b.points[p].stress) << name;
    }
  }
}

TEST(MaterialInterface, AStatefulLawReadsTheCommittedAndWritesTheTrialStateOfEachPoint) {
  for (const char* name : {"C3D8", "CPE8"}) {
    const model::ElementTypeInfo& t = *model::find_element_type(name);
    const auto x = distorted_coords(t);
    const auto u = nodal_field(t, x, [](const Vec3& p) -> Vec3 { return {1e-3 * p[0], 0, 0}; });  // ε11 = 1e-3
    const CountingMaterial law(t.family);
    const std::size_t n_points = t.n_nodes == 8 && t.dim == 3 ? 8 : 9;  // 2×2×2, 3×3
    std::vector<double> committed(2 * n_points), trial(2 * n_points, -1.0);
    for (std::size_t p = 0; p < n_points; ++p) committed[2 * p] = 5.0;
    ElementSystem sys;
    compute_element(t, x, u, law, SectionData{}, ElementRequest{}, {}, ElementHistory{committed, trial, 2}, sys);
    for (std::size_t p = 0; p < n_points; ++p) {
      EXPECT_EQ(trial[2 * p], 6.0) << name << " point " << p;
      EXPECT_NEAR(trial[2 * p + 1], 1e-3, 1e-15) << name << " point " << p;
      EXPECT_EQ(committed[2 * p], 5.0);  // never written by an evaluation
    }
    // The elastic stress is the elastic law's: same force as the stateless kernel.
    ElementSystem elastic = compute_element(t, x, u, kMat, SectionData{}, ElementRequest{});
    EXPECT_EQ(sys.internal_force, elastic.internal_force) << name;
  }
}

TEST(MaterialStates, AnElasticModelHoldsNoHistoryAtAll) {
  test::DeckDir dir;
  const auto r = dir.read(test::one_cube_deck());
  ASSERT_TRUE(r.ok()) << r.report();
  const solver::AnalysisModel am = solver::build_analysis_model(r.model);
  const solver::MaterialStates states(am);
  EXPECT_TRUE(states.empty());
  EXPECT_EQ(states.bytes(), 0u);
  EXPECT_TRUE(states.committed(0).empty());
  ASSERT_NE(am.elements[0].material->as_isotropic_elastic(), nullptr);
  EXPECT_EQ(am.elements[0].material->state_size(), 0u);
}
