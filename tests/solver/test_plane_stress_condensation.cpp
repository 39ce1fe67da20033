// Plane stress around a 3D law with state (solver/elements/plane_stress_condensation.hpp): the
// point lands on S33 = 0 with the 3D law's own answer there, the thickness strain is kept in the
// state, and the condensed tangent is the derivative of the plane-stress stress (central
// differences, 1e-6), at finite strain (the exponential-map Mises law) and small strain
// (combined hardening).
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "finite_strain_fixtures.hpp"
#include "solver/elements/combined_plasticity.hpp"
#include "solver/elements/finite_strain_mises.hpp"
#include "solver/elements/plane_stress_condensation.hpp"

namespace inpact::solver::elements {
namespace {

using test::finite_strain::Eval;
using test::finite_strain::initial;

const ElasticConstants kElastic{200000.0, 0.3, 0.0};

std::shared_ptr<const Material> mises_3d() {
  return std::make_shared<FiniteStrainMises>(kElastic, MisesHardening{false, {0.0, 1.0}, {250.0, 1250.0}});
}

/// The in-plane F of (E11, E22, E12): its stretch, F33 = 1 as the elements pass it.
Eigen::Matrix3d in_plane_F(const Vec6& e) {
  Vec6 full = e;
  full(2) = full(4) = full(5) = 0.0;
  return test::finite_strain::stretch_of(full);
}

Eval at(const Material& m, const std::vector<double>& committed, const Vec6& e, bool nlgeom) {
  Eval out;
  out.trial.assign(committed.size(), -1.0);
  const Eigen::Matrix3d F = in_plane_F(e);
  Mat6 scratch;
  out.tangent = m.update({F, e, 0.0, nullptr, nlgeom}, {committed, out.trial}, out.stress, scratch);
  return out;
}

void check(const Material& law_3d, const PlaneStressCondensation& m, bool nlgeom) {
  Vec6 e1, e2;
  e1 << 0.02, -0.004, 0, 0.01, 0, 0;
  e2 << 0.035, -0.006, 0, 0.02, 0, 0;
  if (!nlgeom) e1 *= 0.2, e2 *= 0.2;
  const std::vector<double> c = at(m, initial(m), e1, nlgeom).trial;
  const Eval base = at(m, c, e2, nlgeom);
  ASSERT_TRUE(base.stress.allFinite());
  // The 3D law at the converged thickness strain gives the same stress, with S33 = 0.
  Vec6 e3 = e2;
  e3(2) = base.trial.back();
  Eigen::Matrix3d F = in_plane_F(e2);
  if (nlgeom) F(2, 2) = std::sqrt(1 + 2 * e3(2));
  std::vector<double> inner(c.begin(), c.end() - 1), inner_trial(inner.size());
  Vec6 s3;
  Mat6 scratch;
  law_3d.update({F, e3, 0.0, nullptr, nlgeom}, {inner, inner_trial}, s3, scratch);
  const double scale = base.stress.cwiseAbs().maxCoeff();
  EXPECT_LT(std::abs(s3(2)), 1e-11 * scale);
  EXPECT_LT((s3 - base.stress).cwiseAbs().maxCoeff(), 1e-11 * scale);
  EXPECT_EQ(m.plane_stress_thickness_strain({}, e2, base.stress, 0.0, 0.0, base.trial), e3(2));
  // The condensed tangent against central differences in E11, E22, E12.
  const double h = 1e-8;
  for (int j : {0, 1, 3}) {
    const Vec6 d = (at(m, c, e2 + h * Vec6::Unit(j), nlgeom).stress - at(m, c, e2 - h * Vec6::Unit(j), nlgeom).stress) / (2 * h);
    for (int i : {0, 1, 3}) EXPECT_NEAR(base.tangent(i, j), d(i), 1e-6 * base.tangent.cwiseAbs().maxCoeff()) << i << j;
  }
}

TEST(PlaneStressCondensation, FiniteStrainMisesLandsOnZeroThicknessStressWithItsTangent) {
  const auto law = mises_3d();
  check(*law, PlaneStressCondensation(law), true);
}

TEST(PlaneStressCondensation, LinearKinematicCombinedHardeningAtSmallStrain) {
  CombinedHardening h;
  h.backstresses = {{20000.0, 0.0}};
  h.initial = 250.0;
  const auto law = std::make_shared<CombinedPlasticity>(kElastic, h);
  check(*law, PlaneStressCondensation(law), false);
}

}  // namespace
}  // namespace inpact::solver::elements
