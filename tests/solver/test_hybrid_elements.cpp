// Hybrid elements (solver/elements/hybrid.hpp) against their standard forms, with isotropic
// linear elasticity (ν = 0.3) and with a hyperelastic material:
//  - a homogeneous deformation (affine u, in every element's space) gives the standard
//    element's internal force and stresses, small strain and NLGEOM (1e-10 relative);
//  - C3D4H and C3D10H are C3D4 and C3D10 for any displacement (their pressure projection is the
//    identity): the same f and K (1e-10);
//  - near incompressibility (ν = 0.4999) a bending field costs the hybrid element far less energy
//    than the standard one (the locking the hybrid form removes): ratio below 0.2 for
//    first-order elements;
//  - the hyperelastic tangent of every hybrid type is the central difference of its internal
//    force at a large deformation (1e-6 relative; the elastic case is in test_element_kernels).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "solver/elements/element_kernel.hpp"
#include "solver/elements/hyperelastic.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::distorted_coords;
using inpact::test::nodal_field;

namespace {

std::vector<std::string> hybrid_names() {
  std::vector<std::string> names;
  for (const auto& t : model::element_types())
    if (t.hybrid) names.emplace_back(t.name);
  return names;
}

/// The standard element of a hybrid one: the name without its H.
const model::ElementTypeInfo& standard_of(const model::ElementTypeInfo& hybrid) {
  std::string name(hybrid.name);
  name.pop_back();
  return *model::find_element_type(name);
}

ElementSystem evaluate(const model::ElementTypeInfo& t, const std::vector<double>& u, const Material& mat,
                       bool nlgeom) {
  ElementRequest req;
  req.point_output = true;
  req.nlgeom = nlgeom;
  ElementSystem sys;
  const auto x = distorted_coords(t);
  compute_element(t, x, u, mat, {}, req, {}, {}, sys);
  return sys;
}

Eigen::Map<const Eigen::VectorXd> vec(const std::vector<double>& v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}

class Hybrid : public ::testing::TestWithParam<std::string> {
 protected:
  const model::ElementTypeInfo& type() const { return *model::find_element_type(GetParam()); }
};

const IsotropicElastic& elastic(model::ElementFamily family, double nu) {
  static std::vector<std::unique_ptr<IsotropicElastic>> keep;
  return *keep.emplace_back(std::make_unique<IsotropicElastic>(family, ElasticConstants{1000.0, nu, 0.0}));
}

const Hyperelastic& rubber() {
  static const Hyperelastic mat(std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({0.5, 0.1}, 1, {0.02})));
  return mat;
}

}  // namespace

TEST_P(Hybrid, AHomogeneousDeformationGivesTheStandardElementsAnswer) {
  const auto& h = type();
  const auto& s = standard_of(h);
  const auto x = distorted_coords(h);
  // Axisymmetric: u_r = a r, u_z = b z + c (the hoop strain u_r/r constant too).
  const bool axi = h.family == model::ElementFamily::Axisymmetric;
  const auto u = nodal_field(h, x, [&](const Vec3& p) {
    if (axi) return Vec3{0.2 * p[0], 0.15 * p[1] - 0.02, 0.0};
    return Vec3{0.01 + 0.2 * p[0] - 0.1 * p[1] + 0.05 * p[2], -0.02 + 0.1 * p[0] + 0.15 * p[1] - 0.04 * p[2],
                h.dim == 3 ? 0.03 - 0.05 * p[0] + 0.08 * p[1] - 0.12 * p[2] : 0.0};
  });
  for (bool nlgeom : {false, true})
    for (const Material* mat : {static_cast<const Material*>(&elastic(h.family, 0.3)),
                                static_cast<const Material*>(&rubber())}) {
      if (!nlgeom && mat == &rubber()) continue;  // hyperelasticity is always NLGEOM
      SCOPED_TRACE(nlgeom ? "NLGEOM" : "small strain");
      const ElementSystem a = evaluate(h, u, *mat, nlgeom), b = evaluate(s, u, *mat, nlgeom);
      const double scale = vec(b.internal_force).cwiseAbs().maxCoeff();
      EXPECT_LE((vec(a.internal_force) - vec(b.internal_force)).cwiseAbs().maxCoeff(), 1e-10 * scale);
      ASSERT_EQ(a.points.size(), b.points.size());
      for (std::size_t p = 0; p < a.points.size(); ++p)
        for (int k = 0; k < 6; ++k)
          EXPECT_NEAR(a.points[p].stress[k], b.points[p].stress[k], 1e-10 * 1000.0) << "point " << p << " comp " << k;
    }
}

TEST(Hybrid, TetrahedraAreTheirStandardElements) {
  for (const char* name : {"C3D4H", "C3D10H"}) {
    SCOPED_TRACE(name);
    const auto& h = *model::find_element_type(name);
    const auto& s = standard_of(h);
    const auto x = distorted_coords(h);
    const auto u = nodal_field(h, x, [](const Vec3& p) {
      return Vec3{0.1 * p[1] * p[1] + 0.05 * p[2], -0.08 * p[0] * p[2], 0.06 * p[0] * p[1] - 0.1 * p[2] * p[2]};
    });
    for (bool nlgeom : {false, true}) {
      const ElementSystem a = evaluate(h, u, elastic(h.family, 0.45), nlgeom), b = evaluate(s, u, elastic(h.family, 0.45), nlgeom);
      EXPECT_LE((vec(a.internal_force) - vec(b.internal_force)).cwiseAbs().maxCoeff(),
                1e-10 * vec(b.internal_force).cwiseAbs().maxCoeff());
      EXPECT_LE((vec(a.stiffness) - vec(b.stiffness)).cwiseAbs().maxCoeff(), 1e-10 * vec(b.stiffness).cwiseAbs().maxCoeff());
    }
  }
}

TEST(Hybrid, NearIncompressibleBendingDoesNotLock) {
  for (const char* name : {"C3D8H", "CPE4H", "CAX4H"}) {
    SCOPED_TRACE(name);
    const auto& h = *model::find_element_type(name);
    const auto& s = standard_of(h);
    const auto x = distorted_coords(h);
    // Bending about the third axis: u1 = κ (x1 − x̄) (x2 − ȳ), u2 = −κ/2 (x1 − x̄)².
    const double xc = h.dim == 3 ? 0.5 : 2.5;
    const auto u = nodal_field(h, x, [&](const Vec3& p) {
      return Vec3{1e-3 * (p[0] - xc) * (p[1] - 0.5), -0.5e-3 * (p[0] - xc) * (p[0] - xc), 0.0};
    });
    const auto energy = [&](const model::ElementTypeInfo& t) {
      const ElementSystem sys = evaluate(t, u, elastic(t.family, 0.4999), false);
      return 0.5 * vec(sys.internal_force).dot(vec(u));
    };
    const double ratio = energy(h) / energy(s);
    EXPECT_LT(ratio, 0.2);
    std::printf("[hybrid] %s: bending energy hybrid / standard at nu = 0.4999: %.4f\n", name, ratio);
  }
}

TEST_P(Hybrid, HyperelasticTangentIsTheCentralDifferenceOfTheInternalForce) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const auto u = nodal_field(t, x, [&](const Vec3& p) {
    return Vec3{0.25 * p[0] - 0.2 * p[1] * p[1] + 0.1 * p[2], 0.15 * p[0] * p[1] - 0.1 * p[1],
                t.dim == 3 ? 0.1 * p[0] * p[2] - 0.2 * p[2] : 0.0};
  });
  const ElementSystem sys = evaluate(t, u, rubber(), true);
  const int n = sys.n_dof;
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> K(sys.stiffness.data(), n, n);
  Eigen::MatrixXd Kfd(n, n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    auto up = u, um = u;
    up[static_cast<std::size_t>(j)] += h;
    um[static_cast<std::size_t>(j)] -= h;
    Kfd.col(j) = (vec(evaluate(t, up, rubber(), true).internal_force) - vec(evaluate(t, um, rubber(), true).internal_force)) / (2 * h);
  }
  EXPECT_LT((K - Kfd).norm() / K.norm(), 1e-6);
  EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllHybrid, Hybrid, ::testing::ValuesIn(hybrid_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });
