// The directional elastic law (anisotropic_elastic.hpp) and the material axes
// (material_orientation.hpp): engineering constants against their compliance, isotropic
// constants through every directional path against the isotropic matrix, the rotated stiffness
// against the closed-form rotated compliance, the axes of rectangular and cylindrical
// orientations, and the plane-stress condensation and thickness strain.
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "model/elastic_stiffness.hpp"
#include "solver/elements/anisotropic_elastic.hpp"
#include "solver/elements/material_orientation.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using model::ElementFamily;

namespace {

// A transversely isotropic-like carbon/epoxy set (units MPa): E1, E2, E3, ν12, ν13, ν23, G12, G13, G23.
const std::vector<double> kOrtho = {140000., 10000., 9000., 0.3, 0.28, 0.45, 5000., 4500., 3500.};

model::Elastic elastic(model::Elastic::Type type, std::vector<double> c) {
  model::Elastic e;
  e.type = type;
  e.constants = std::move(c);
  return e;
}

Mat6 to_mat(const model::Stiffness& d) { return Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(d.data()); }

Mat6 stiffness(const model::Elastic& e) { return to_mat(model::material_stiffness(e)); }

double rel(const Mat6& a, const Mat6& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

model::Orientation rectangular(double degrees_about_z) {
  const double t = degrees_about_z * std::numbers::pi / 180;
  model::Orientation o;
  o.a[0] = std::cos(t);
  o.a[1] = std::sin(t);
  o.b[0] = -std::sin(t);
  o.b[1] = std::cos(t);
  return o;
}

}  // namespace

TEST(ElasticStiffness, EngineeringConstantsInvertTheirCompliance) {
  const Mat6 d = stiffness(elastic(model::Elastic::Type::EngineeringConstants, kOrtho));
  const Mat6 s = d.inverse();
  const double e1 = kOrtho[0], e2 = kOrtho[1], e3 = kOrtho[2];
  Mat6 expected = Mat6::Zero();
  expected(0, 0) = 1 / e1, expected(1, 1) = 1 / e2, expected(2, 2) = 1 / e3;
  expected(0, 1) = expected(1, 0) = -kOrtho[3] / e1;
  expected(0, 2) = expected(2, 0) = -kOrtho[4] / e1;
  expected(1, 2) = expected(2, 1) = -kOrtho[5] / e2;
  expected(3, 3) = 1 / kOrtho[6], expected(4, 4) = 1 / kOrtho[7], expected(5, 5) = 1 / kOrtho[8];
  EXPECT_LT(rel(s, expected), 1e-14);
}

TEST(ElasticStiffness, IsotropicConstantsGiveTheIsotropicMatrixThroughEveryType) {
  const double E = 210000., nu = 0.3, G = E / (2 * (1 + nu)), l = E * nu / ((1 + nu) * (1 - 2 * nu));
  model::Elastic iso;
  iso.youngs_modulus = E;
  iso.poissons_ratio = nu;
  const Mat6 d_iso = stiffness(iso);
  EXPECT_EQ(d_iso, elasticity_matrix(ElementFamily::Solid3D, {E, nu, 0.0}));
  const Mat6 ec = stiffness(elastic(model::Elastic::Type::EngineeringConstants, {E, E, E, nu, nu, nu, G, G, G}));
  EXPECT_LT(rel(ec, d_iso), 1e-14);
  const Mat6 ortho = stiffness(elastic(model::Elastic::Type::Orthotropic, {l + 2 * G, l, l + 2 * G, l, l, l + 2 * G, G, G, G}));
  EXPECT_LT(rel(ortho, d_iso), 1e-15);
  std::vector<double> aniso;  // the upper triangle column by column
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i <= j; ++i) aniso.push_back(d_iso(i, j));
  EXPECT_EQ(stiffness(elastic(model::Elastic::Type::Anisotropic, aniso)), d_iso);
}

TEST(ElasticStiffness, AnisotropicOrderIsAbaqusUpperTriangleByColumns) {
  std::vector<double> c(21);
  for (int k = 0; k < 21; ++k) c[k] = k + 1;
  const Mat6 d = stiffness(elastic(model::Elastic::Type::Anisotropic, c));
  EXPECT_EQ(d(1, 1), 3);   // D2222 third
  EXPECT_EQ(d(0, 3), 7);   // D1112 seventh
  EXPECT_EQ(d(3, 3), 10);  // D1212
  EXPECT_EQ(d(3, 4), 14);  // D1213
  EXPECT_EQ(d(4, 4), 15);  // D1313
  EXPECT_EQ(d(2, 5), 18);  // D3323
  EXPECT_EQ(d(5, 5), 21);  // D2323
  EXPECT_EQ(d(5, 2), 18);
}

TEST(MaterialOrientation, RectangularCylindricalAndAdditionalRotation) {
  const Eigen::Matrix3d q30 = MaterialOrientation(rectangular(30)).axes_at({0, 0, 0});
  model::Orientation turned = rectangular(0);
  turned.axis = 3;
  turned.angle = 30;
  EXPECT_LT((MaterialOrientation(turned).axes_at({0, 0, 0}) - q30).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(q30(0, 0), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(q30(1, 0), -0.5, 1e-15);  // axis 2 = (−sin, cos, 0)

  model::Orientation cyl;  // axis along z through (1, 0, 0)
  cyl.system = model::Orientation::System::Cylindrical;
  cyl.a[0] = 1;
  cyl.b[0] = 1, cyl.b[2] = 2;
  const Eigen::Matrix3d q = MaterialOrientation(cyl).axes_at({1, 3, 7});
  Eigen::Matrix3d expected;
  expected << 0, 1, 0,  // radial
      -1, 0, 0,         // tangential = z × radial
      0, 0, 1;
  EXPECT_LT((q - expected).cwiseAbs().maxCoeff(), 1e-15);
  cyl.axis = 1;  // turning about the radial axis by 90° takes the tangential axis to the cylinder axis
  cyl.angle = 90;
  const Eigen::Matrix3d qr = MaterialOrientation(cyl).axes_at({1, 3, 7});
  EXPECT_LT((qr.row(1) - Eigen::RowVector3d(0, 0, 1)).cwiseAbs().maxCoeff(), 1e-15);
}

// Uniaxial stress σ along material axis 1 turned by 30° about z: the global strain D(x)⁻¹ σ_g,
// taken back into the material axes, is the first column of the compliance times σ.
TEST(AnisotropicElastic, RotatedStiffnessIsObjective) {
  const model::Elastic ec = elastic(model::Elastic::Type::EngineeringConstants, kOrtho);
  const model::Orientation o = rectangular(30);
  const AnisotropicElastic law(ElementFamily::Solid3D, stiffness(ec), 0.0, MaterialOrientation(o));
  const Eigen::Matrix3d q = MaterialOrientation(o).axes_at({0, 0, 0});
  const double sigma = 100.0;
  Eigen::Matrix3d s_local = Eigen::Matrix3d::Zero();
  s_local(0, 0) = sigma;
  const Eigen::Matrix3d s_global = q.transpose() * s_local * q;
  Vec6 s_voigt;
  s_voigt << s_global(0, 0), s_global(1, 1), s_global(2, 2), s_global(0, 1), s_global(0, 2), s_global(1, 2);
  const Vec6 e_global = law.stiffness_at({0, 0, 0}).ldlt().solve(s_voigt);
  const Vec6 e_local = strain_rotation(q) * e_global;
  Vec6 expected = Vec6::Zero();
  expected(0) = sigma / kOrtho[0];
  expected(1) = -kOrtho[3] * sigma / kOrtho[0];
  expected(2) = -kOrtho[4] * sigma / kOrtho[0];
  EXPECT_LT((e_local - expected).cwiseAbs().maxCoeff(), 1e-14 * expected(0));
  // The stress the law returns for that strain is the applied one.
  Vec6 stress;
  Mat6 scratch;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  law.update({F, e_global, 0.0}, {}, stress, scratch);
  EXPECT_LT((stress - s_voigt).cwiseAbs().maxCoeff(), 1e-12 * sigma);
}

// A cylindrical law at a point of angle φ about z has the rectangular law turned by φ.
TEST(AnisotropicElastic, CylindricalAxesFollowThePoint) {
  const Mat6 d = stiffness(elastic(model::Elastic::Type::EngineeringConstants, kOrtho));
  model::Orientation cyl;
  cyl.system = model::Orientation::System::Cylindrical;
  cyl.b[2] = 1;
  const AnisotropicElastic law(ElementFamily::Solid3D, d, 0.0, MaterialOrientation(cyl));
  const double phi = 0.7;
  const AnisotropicElastic turned(ElementFamily::Solid3D, d, 0.0, MaterialOrientation(rectangular(phi * 180 / std::numbers::pi)));
  const Vec3 x{2 * std::cos(phi), 2 * std::sin(phi), 0.3};
  EXPECT_LT(rel(law.stiffness_at(x), turned.stiffness_at({0, 0, 0})), 1e-14);
  Vec6 strain, stress;
  strain << 1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4;
  Mat6 scratch;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  const Mat6& tangent = law.update({F, strain, 0.0, &x}, {}, stress, scratch);
  EXPECT_LT(rel(tangent, law.stiffness_at(x)), 1e-15);
  EXPECT_THROW(law.update({F, strain, 0.0}, {}, stress, scratch), std::logic_error);
}

// Plane stress: isotropic engineering constants condense to elasticity_matrix's plane-stress
// matrix, and the thickness strain is −ν/(1−ν)(ε11 + ε22 − 2ε_th) + ε_th.
TEST(AnisotropicElastic, PlaneStressCondensationAndThicknessStrain) {
  const double E = 1000., nu = 0.25, G = E / (2 * (1 + nu)), alpha = 1e-5;
  const Mat6 d = stiffness(elastic(model::Elastic::Type::EngineeringConstants, {E, E, E, nu, nu, nu, G, G, G}));
  const AnisotropicElastic law(ElementFamily::PlaneStress, d, alpha, MaterialOrientation(rectangular(20)));
  EXPECT_LT(rel(law.stiffness_at({0, 0, 0}), elasticity_matrix(ElementFamily::PlaneStress, {E, nu, 0.0})), 1e-14);
  Vec6 strain, stress;
  strain << 1e-3, -4e-4, 0, 6e-4, 0, 0;
  const double eth = 2e-4;
  Mat6 scratch;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  law.update({F, strain, eth}, {}, stress, scratch);
  const double expected = -nu / (1 - nu) * (strain(0) + strain(1) - 2 * eth) + eth;
  EXPECT_NEAR(law.plane_stress_thickness_strain({0, 0, 0}, strain, stress, eth, 0.0, {}), expected, 1e-15);
  // The isotropic stand-ins of elastic() are E and ν themselves.
  EXPECT_NEAR(law.elastic().youngs_modulus, E, 1e-12 * E);
  EXPECT_NEAR(law.elastic().poissons_ratio, nu, 1e-14);
  EXPECT_EQ(law.elastic().expansion, alpha);
}

// A lamina: Q11 = E1/(1 − ν12ν21), Q12 = ν12 E2/(1 − ν12ν21), Q22 = E2/(1 − ν12ν21), Q66 = G12.
TEST(AnisotropicElastic, LaminaIsItsPlaneStressMatrix) {
  const double e1 = 140000, e2 = 10000, n12 = 0.3, g12 = 5000;
  const Mat6 d = stiffness(elastic(model::Elastic::Type::Lamina, {e1, e2, n12, g12, 4000, 3000}));
  const AnisotropicElastic law(ElementFamily::PlaneStress, d, 0.0, std::nullopt, true);
  const Mat6 q = law.stiffness_at({0, 0, 0});
  const double den = 1 - n12 * n12 * e2 / e1;
  EXPECT_NEAR(q(0, 0), e1 / den, 1e-10 * e1);
  EXPECT_NEAR(q(0, 1), n12 * e2 / den, 1e-10 * e1);
  EXPECT_NEAR(q(1, 1), e2 / den, 1e-10 * e1);
  EXPECT_EQ(q(3, 3), g12);
  EXPECT_EQ(q(2, 2), 0.0);
  EXPECT_THROW(AnisotropicElastic(ElementFamily::Solid3D, d, 0.0, std::nullopt, true), std::invalid_argument);
}

TEST(ElasticStiffness, PositiveDefinite) {
  EXPECT_TRUE(model::positive_definite(model::material_stiffness(elastic(model::Elastic::Type::EngineeringConstants, kOrtho))));
  model::Stiffness d{};
  for (int i = 0; i < 6; ++i) d[static_cast<std::size_t>(7 * i)] = 1.0;
  d[1] = d[6] = 1.0;  // D1122 = √(D1111 D2222): singular
  EXPECT_FALSE(model::positive_definite(d));
}
