// Element kernels, every type in model/element_types.cpp: rigid motion, patch test with hand
// values, finite-difference tangent, symmetry, zero-energy modes, uniaxial stress, thermal
// expansion, and the same checks with NLGEOM. Tolerances are stated at each check.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "solver/elements/element_kernel.hpp"
#include "solver/elements/face_loads.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::distorted_coords;
using inpact::test::nodal_field;
using inpact::test::reference_coords;
using model::ElementFamily;
using model::Integration;

namespace {

constexpr double kE = 1000.0, kNu = 0.3, kAlpha = 1e-3;
const ElasticConstants kMat{kE, kNu, kAlpha};
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
const double kMu = kE / (2 * (1 + kNu));

ElementSystem run(const model::ElementTypeInfo& t, const std::vector<Vec3>& x, const std::vector<double>& u,
                  bool nlgeom = false, std::span<const double> dT = {}, SectionData sec = {0.7, 0.005}) {
  ElementRequest req;
  req.point_output = true;
  req.nlgeom = nlgeom;
  return compute_element(t, x, u, kMat, sec, req, dT);
}

Eigen::MatrixXd stiffness(const ElementSystem& s) {
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      s.stiffness.data(), s.n_dof, s.n_dof);
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Hand value of σ = λ tr(ε) I + 2μ ε for the family (plane stress: the condensed law, σ33 = 0).
// ε in Abaqus order with engineering shear.
Voigt6 hand_stress(ElementFamily fam, const Voigt6& e) {
  if (fam == ElementFamily::PlaneStress) {
    const double c = kE / (1 - kNu * kNu);
    return {c * (e[0] + kNu * e[1]), c * (e[1] + kNu * e[0]), 0, kMu * e[3], 0, 0};
  }
  const double tr = e[0] + e[1] + e[2];
  return {kLambda * tr + 2 * kMu * e[0], kLambda * tr + 2 * kMu * e[1], kLambda * tr + 2 * kMu * e[2],
          kMu * e[3], kMu * e[4], kMu * e[5]};
}

int expected_zero_modes(const model::ElementTypeInfo& t) {
  const int rigid = t.dim == 3 ? 6 : t.family == ElementFamily::Axisymmetric ? 1 : 3;
  const std::string name(t.name);
  // Abaqus gives its second-order reduced elements no hourglass control: a single C3D20R has
  // six spurious modes and a single CPE8R/CPS8R one (not communicable in a mesh). The CAX8R
  // hourglass mode is stiffened by the hoop strain.
  if (name == "C3D20R") return rigid + 6;
  if (name == "CPE8R" || name == "CPS8R" || name == "CPE8RH") return rigid + 1;
  // C3D20RH: the 2×2×2 points constrain the volume change through the four linear pressure
  // functions only, not at each of the eight points: four more single-element modes than
  // C3D20R (the mixed element with that quadrature and pressure space has them too).
  if (name == "C3D20RH") return rigid + 10;
  // Abaqus's 2-point rule for C3D6 (triangle centroid × 2 through the thickness) leaves one
  // twist mode: u = θ r (h − 1/3, −(g − 1/3), 0) is strain-free on the centroid line. Shared
  // quadrilateral faces restrain it in a mesh.
  if (name == "C3D6") return rigid + 1;
  // One-point axisymmetric elements: the r–z rotation about the integration point,
  // u_r = s (z − z₀), u_z = −s r, has zero strain there (its hoop strain s(z − z₀)/r vanishes at
  // z₀). It is linear, so hourglass control (orthogonal to linear fields) cannot see it; a mesh
  // restrains it because neighbouring elements have different z₀.
  if (name == "CAX3" || name == "CAX4R") return rigid + 1;
  return rigid;
}

// Rigid body motion small enough for small strain: translation + infinitesimal rotation
// (exactly strain-free in the linear theory). CAX admits only the axial translation.
std::vector<double> small_rigid_motion(const model::ElementTypeInfo& t, const std::vector<Vec3>& x) {
  return nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    if (t.family == ElementFamily::Axisymmetric) return {0, 0.3, 0};
    if (t.dim == 2) return {0.1 - 0.2 * p[1], 0.3 + 0.2 * p[0], 0};
    const double w[3] = {0.2, -0.1, 0.15};  // u = c + ω × X
    return {0.1 + w[1] * p[2] - w[2] * p[1], 0.3 + w[2] * p[0] - w[0] * p[2], -0.2 + w[0] * p[1] - w[1] * p[0]};
  });
}

// The linear patch field and the strain it produces (engineering shear). CAX: u_r = a r,
// u_z = c r + d z + e (u_r ∝ z or u_r = const would give a non-constant hoop strain).
struct PatchField {
  std::vector<double> u;
  Voigt6 strain;
};

PatchField patch_field(const model::ElementTypeInfo& t, const std::vector<Vec3>& x) {
  const double A[3][3] = {{1.1e-3, 0.4e-3, -0.7e-3}, {-0.3e-3, -0.6e-3, 0.5e-3}, {0.9e-3, 0.2e-3, 0.8e-3}};
  PatchField pf;
  if (t.family == ElementFamily::Axisymmetric) {
    const double a = 1.1e-3, c = 0.4e-3, d = -0.6e-3;
    pf.u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 { return {a * p[0], c * p[0] + d * p[1] + 0.2, 0}; });
    pf.strain = {a, d, a, c, 0, 0};
    return pf;
  }
  const int dim = t.dim;
  pf.u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    Vec3 v{0.05, -0.02, 0.01};
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) v[i] += A[i][j] * p[j];
    return v;
  });
  pf.strain = {A[0][0], A[1][1], dim == 3 ? A[2][2] : 0, A[0][1] + A[1][0], dim == 3 ? A[0][2] + A[2][0] : 0,
               dim == 3 ? A[1][2] + A[2][1] : 0};
  if (t.family == ElementFamily::PlaneStress) pf.strain[2] = -kNu / (1 - kNu) * (A[0][0] + A[1][1]);
  return pf;
}

// Central-difference tangent: K_fd(:, j) = (f(u + h e_j) − f(u − h e_j)) / 2h.
Eigen::MatrixXd fd_tangent(const model::ElementTypeInfo& t, const std::vector<Vec3>& x, const std::vector<double>& u,
                           bool nlgeom, std::span<const double> dT, double h) {
  const int n = static_cast<int>(u.size());
  Eigen::MatrixXd K(n, n);
  for (int j = 0; j < n; ++j) {
    auto up = u, um = u;
    up[j] += h;
    um[j] -= h;
    const auto fp = run(t, x, up, nlgeom, dT).internal_force, fm = run(t, x, um, nlgeom, dT).internal_force;
    for (int i = 0; i < n; ++i) K(i, j) = (fp[i] - fm[i]) / (2 * h);
  }
  return K;
}

class EachElementType : public ::testing::TestWithParam<std::string> {
 protected:
  const model::ElementTypeInfo& type() const { return *model::find_element_type(GetParam()); }
};

std::vector<std::string> all_type_names() {
  std::vector<std::string> names;
  for (const auto& t : model::element_types())
    if (model::is_continuum(t)) names.emplace_back(t.name);  // trusses, springs: test_line_elements.cpp
  return names;
}

}  // namespace

TEST_P(EachElementType, RigidMotionGivesZeroStrainStressAndResidual) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const auto s = run(t, x, small_rigid_motion(t, x));
  ASSERT_GT(s.min_jacobian, 0.0);
  EXPECT_LT(max_abs(s.internal_force), 1e-12 * kE);
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(p.strain[k], 0.0, 1e-14) << k;
      EXPECT_NEAR(p.stress[k], 0.0, 1e-12 * kE) << k;
    }
}

TEST_P(EachElementType, PatchTestReproducesTheHandStressOnADistortedElement) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const PatchField pf = patch_field(t, x);
  const auto s = run(t, x, pf.u);
  const Voigt6 sig = hand_stress(t.family, pf.strain);
  ASSERT_FALSE(s.points.empty());
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(p.strain[k], pf.strain[k], 1e-10 * 1e-3) << "component " << k;  // 1e-10 relative to |ε| ~ 1e-3
      EXPECT_NEAR(p.stress[k], sig[k], 1e-10 * kE * 1e-3) << "component " << k;
    }
  // The nodal forces of a constant stress balance (no body force).
  std::array<double, 3> sum{};
  for (int a = 0; a < t.n_nodes; ++a)
    for (int i = 0; i < t.dim; ++i) sum[i] += s.internal_force[a * t.dim + i];
  if (t.family != ElementFamily::Axisymmetric) {  // CAX: the hoop stress balances the radial sum
    for (int i = 0; i < t.dim; ++i) EXPECT_NEAR(sum[i], 0.0, 1e-12);
  } else {
    EXPECT_NEAR(sum[1], 0.0, 1e-12);
  }
}

TEST_P(EachElementType, StiffnessEqualsCentralDifferenceOfInternalForce) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  std::vector<double> u(static_cast<std::size_t>(t.n_nodes) * t.dim);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = 0.01 * std::sin(1.3 * k + 0.2);
  std::vector<double> dT(t.n_nodes);
  for (int a = 0; a < t.n_nodes; ++a) dT[a] = 10.0 + 3 * a;
  const Eigen::MatrixXd K = stiffness(run(t, x, u, false, dT));
  const Eigen::MatrixXd Kfd = fd_tangent(t, x, u, false, dT, 1e-6);
  EXPECT_LT((K - Kfd).norm() / K.norm(), 1e-6);
}

TEST_P(EachElementType, StiffnessIsSymmetric) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const Eigen::MatrixXd K = stiffness(run(t, x, std::vector<double>(t.n_nodes * t.dim, 0.0)));
  EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-13);
}

TEST_P(EachElementType, ZeroEnergyModesAreExactlyTheRigidOnes) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const Eigen::MatrixXd K = stiffness(run(t, x, std::vector<double>(t.n_nodes * t.dim, 0.0)));
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  int zeros = 0;
  for (int i = 0; i < ev.size(); ++i) zeros += std::abs(ev(i)) < 1e-9 * ev.maxCoeff();
  EXPECT_EQ(zeros, expected_zero_modes(t)) << "eigenvalues from " << ev(0) << " to " << ev(ev.size() - 1);
  EXPECT_GT(ev.minCoeff(), -1e-9 * ev.maxCoeff());  // positive semi-definite
}

TEST_P(EachElementType, UniaxialStressByHand) {
  // σ11 = E ε with free lateral contraction (CAX: axial stress σzz = E ε with u_r = −ν ε r).
  const auto& t = type();
  const auto x = reference_coords(t);
  const double eps = 2e-3;
  const bool axi = t.family == ElementFamily::Axisymmetric;
  const double nu_eff = t.family == ElementFamily::PlaneStrain ? kNu / (1 - kNu) : kNu;
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    if (axi) return {-kNu * eps * p[0], eps * p[1], 0};
    return {eps * p[0], -nu_eff * eps * p[1], -nu_eff * eps * p[2]};
  });
  const auto s = run(t, x, u);
  const int axis = axi ? 1 : 0;
  // Plane strain: ε33 = 0 needs σ11 = E ε/(1−ν²) and σ33 = ν σ11 for σ22 = 0.
  const double s11 = t.family == ElementFamily::PlaneStrain ? kE * eps / (1 - kNu * kNu) : kE * eps;
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) {
      double expect = k == axis ? s11 : 0.0;
      if (t.family == ElementFamily::PlaneStrain && k == 2) expect = kNu * s11;
      EXPECT_NEAR(p.stress[k], expect, 1e-10 * kE * eps) << "component " << k;
    }
}

TEST_P(EachElementType, InternalForceOfUniformStressEqualsTheConsistentFaceTractions) {
  // For a constant stress σ, f_int = ∫ Bᵀσ dV = Σ_faces ∫ Nᵀ σ n dA. With σ = σ11 e1⊗e1 on the
  // reference element only the faces normal to x carry traction σ11 n_x: the pressure −σ11 n_x.
  const auto& t = type();
  if (t.family == ElementFamily::Axisymmetric) {
    GTEST_SKIP() << "hoop stress also loads the radial faces";
  }
  const auto x = reference_coords(t);
  const double eps = 1e-3;
  const double nu_eff = t.family == ElementFamily::PlaneStrain ? kNu / (1 - kNu) : kNu;
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    return {eps * p[0], -nu_eff * eps * p[1], -nu_eff * eps * p[2]};
  });
  const SectionData sec{0.7, 0.005};
  const auto s = run(t, x, u, false, {}, sec);
  const double s11 = s.points.front().stress[0];
  std::vector<double> traction(s.internal_force.size(), 0.0);
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    // Only the x components: a slanted face also carries n_y, n_z in the pressure load.
    const auto lf = pressure_load(t, x, static_cast<int>(f), -s11, sec);
    for (std::size_t k = 0; k < traction.size(); k += t.dim) traction[k] += lf[k];
  }
  for (std::size_t k = 0; k < traction.size(); k += t.dim)
    EXPECT_NEAR(s.internal_force[k], traction[k], 1e-10 * std::abs(s11)) << "dof " << k;
}

TEST_P(EachElementType, FreeThermalExpansionIsStressFree) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  const double dT = 40.0, e = kAlpha * dT;
  std::vector<double> temps(t.n_nodes, dT);
  // Plane strain cannot expand out of plane: in-plane (1+ν)αΔT leaves σ11 = σ22 = 0, σ33 = −EαΔT.
  const double e_in = t.family == ElementFamily::PlaneStrain ? (1 + kNu) * e : e;
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 { return {e_in * p[0], e_in * p[1], e_in * p[2]}; });
  const auto s = run(t, x, u, false, temps);
  EXPECT_LT(max_abs(s.internal_force), 1e-12 * kE);
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) {
      const double expect = (t.family == ElementFamily::PlaneStrain && k == 2) ? -kE * e : 0.0;
      EXPECT_NEAR(p.stress[k], expect, 1e-10 * kE * e) << "component " << k;
    }
  // Fully restrained: σ = −E αΔT / (1 − 2ν) on the diagonal (3D, plane strain, CAX).
  if (t.family != ElementFamily::PlaneStress) {
    const auto r = run(t, x, std::vector<double>(t.n_nodes * t.dim, 0.0), false, temps);
    for (const auto& p : r.points) EXPECT_NEAR(p.stress[0], -kE * e / (1 - 2 * kNu), 1e-10 * kE * e);
  }
}

TEST_P(EachElementType, NlgeomRigidRotationOf90DegreesIsStressFree) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  // 3D: 90° about the axis (1, 2, 2)/3; 2D: 90° in the plane; CAX: only axial translation is rigid.
  const double c = 0.0, sn = 1.0;
  const Eigen::Vector3d ax = Eigen::Vector3d(1, 2, 2).normalized();
  Eigen::Matrix3d R;
  if (t.dim == 3) {
    Eigen::Matrix3d W;
    W << 0, -ax(2), ax(1), ax(2), 0, -ax(0), -ax(1), ax(0), 0;
    R = Eigen::Matrix3d::Identity() * c + sn * W + (1 - c) * ax * ax.transpose();
  } else {
    R << c, -sn, 0, sn, c, 0, 0, 0, 1;
  }
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    if (t.family == ElementFamily::Axisymmetric) return {0, 0.4, 0};
    const Eigen::Vector3d X(p[0], p[1], p[2]);
    const Eigen::Vector3d d = R * X - X + Eigen::Vector3d(0.3, -0.2, 0.1);
    return {d(0), d(1), d(2)};
  });
  const auto s = run(t, x, u, true);
  EXPECT_LT(max_abs(s.internal_force), 1e-12 * kE);
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(p.stress[k], 0.0, 1e-12 * kE) << k;
      EXPECT_NEAR(p.strain[k], 0.0, 1e-13) << k;
    }
}

TEST_P(EachElementType, NlgeomTangentEqualsCentralDifferenceAtLargeDeformation) {
  const auto& t = type();
  const auto x = distorted_coords(t);
  std::vector<double> u(static_cast<std::size_t>(t.n_nodes) * t.dim);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = 0.08 * std::sin(1.3 * k + 0.2);
  std::vector<double> dT(t.n_nodes);
  for (int a = 0; a < t.n_nodes; ++a) dT[a] = 10.0 + 3 * a;
  const auto s = run(t, x, u, true, dT);
  const Eigen::MatrixXd K = stiffness(s);
  const Eigen::MatrixXd Kfd = fd_tangent(t, x, u, true, dT, 1e-6);
  EXPECT_LT((K - Kfd).norm() / K.norm(), 1e-6);
  EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-12);
}

TEST_P(EachElementType, NlgeomUniaxialStretchMatchesStVenantKirchhoffByHand) {
  // u = (λ−1) X e1 with the lateral directions held: E11 = ½(λ²−1), S11 = (λ_L + 2μ) E11,
  // Cauchy σ11 = λ S11 (J = λ; plane stress J = λ F33). CAX: stretch along z.
  const auto& t = type();
  const auto x = distorted_coords(t);
  const double stretch = 1.3, E11 = 0.5 * (stretch * stretch - 1);
  const bool axi = t.family == ElementFamily::Axisymmetric;
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 {
    if (axi) return {0, (stretch - 1) * p[1], 0};
    return {(stretch - 1) * p[0], 0, 0};
  });
  const auto s = run(t, x, u, true);
  const double c11 = t.family == ElementFamily::PlaneStress ? kE / (1 - kNu * kNu) : kLambda + 2 * kMu;
  const double s11 = c11 * E11;
  // Plane stress: the thickness stretch F33 = √(1 + 2E33), E33 = −ν/(1−ν) E11, enters J.
  const double f33 = t.family == ElementFamily::PlaneStress ? std::sqrt(1 - 2 * kNu / (1 - kNu) * E11) : 1.0;
  const int axis = axi ? 1 : 0;
  for (const auto& p : s.points) {
    EXPECT_NEAR(p.stress[axis], stretch * s11 / f33, 1e-10 * kE) << t.name;
    EXPECT_NEAR(p.strain[axis], std::log(stretch), 1e-12);
    EXPECT_NEAR(p.stress[3], 0.0, 1e-10 * kE);
  }
}

TEST_P(EachElementType, NlgeomFreeThermalExpansionIsStressFree) {
  // With S = D(E − αΔT I), the stress-free stretch is √(1 + 2αΔT).
  const auto& t = type();
  if (t.family == ElementFamily::PlaneStrain) {
    GTEST_SKIP() << "plane strain restrains the expansion";
  }
  const auto x = distorted_coords(t);
  const double dT = 40.0, g = std::sqrt(1 + 2 * kAlpha * dT) - 1;
  std::vector<double> temps(t.n_nodes, dT);
  const auto u = nodal_field(t, x, [&](const Vec3& p) -> Vec3 { return {g * p[0], g * p[1], g * p[2]}; });
  const auto s = run(t, x, u, true, temps);
  EXPECT_LT(max_abs(s.internal_force), 1e-11 * kE);
  for (const auto& p : s.points)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(p.stress[k], 0.0, 1e-11 * kE) << k;
}

INSTANTIATE_TEST_SUITE_P(AllTypes, EachElementType, ::testing::ValuesIn(all_type_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

TEST(ElementKernel, AxisymmetricVolumeIsTheFullRing) {
  // A CAX4 square [2,3]×[0,1]: the ring volume π(3² − 2²)·1 is the sum of the point volumes.
  const auto& t = *model::find_element_type("CAX4");
  const auto s = run(t, reference_coords(t), std::vector<double>(8, 0.0));
  double v = 0;
  for (const auto& p : s.points) v += p.volume;
  EXPECT_NEAR(v, std::numbers::pi * (9 - 4), 1e-12);
}

TEST(ElementKernel, PlaneElementsScaleWithThickness) {
  const auto& t = *model::find_element_type("CPS4");
  const auto x = reference_coords(t);
  const auto u = nodal_field(t, x, [](const Vec3& p) -> Vec3 { return {1e-3 * p[0], 0, 0}; });
  const auto a = run(t, x, u, false, {}, {1.0, 0.005});
  const auto b = run(t, x, u, false, {}, {2.5, 0.005});
  for (std::size_t k = 0; k < a.internal_force.size(); ++k) EXPECT_NEAR(b.internal_force[k], 2.5 * a.internal_force[k], 1e-14);
}

TEST(ElementKernel, InvertedElementReportsNonPositiveJacobian) {
  const auto& t = *model::find_element_type("C3D8");
  auto x = reference_coords(t);
  std::swap(x[0], x[1]);
  std::swap(x[4], x[5]);  // mirrored: det J < 0
  const auto s = run(t, x, std::vector<double>(24, 0.0));
  EXPECT_LE(s.min_jacobian, 0.0);
  EXPECT_TRUE(s.stiffness.empty());
}

// Mirrored through x = 0 by its displacement (u1 = −2 x1, F = diag(−1, 1, 1)), an element has
// Green strain ½(FᵀF − I) = 0: a St. Venant–Kirchhoff point feels nothing, so only det F = −1
// tells that the state is no body's (CalculiX's hinge.inp converged to such a fold before the
// solver checked it). The C3D8 kernel and the generic one (C3D20R) report it alike; a rigid
// rotation keeps det F = 1.
TEST(ElementKernel, NlgeomReportsAnElementTurnedInsideOutByItsDisplacement) {
  for (const char* name : {"C3D8", "C3D20R", "CPE4"}) {
    const auto& t = *model::find_element_type(name);
    const auto x = reference_coords(t);
    const auto mirrored = nodal_field(t, x, [](const Vec3& p) -> Vec3 { return {-2 * p[0], 0, 0}; });
    const auto s = run(t, x, mirrored, true);
    EXPECT_GT(s.min_jacobian, 0.0) << name;  // the reference geometry is fine
    EXPECT_NEAR(s.min_volume_ratio, -1.0, 1e-12) << name;
    EXPECT_LE(max_abs(s.internal_force), 1e-12) << name;  // no strain: no force either
    const double c = std::cos(1.2), sn = std::sin(1.2);
    const auto turned =
        nodal_field(t, x, [&](const Vec3& p) -> Vec3 { return {c * p[0] - sn * p[1] - p[0], sn * p[0] + c * p[1] - p[1], 0}; });
    EXPECT_NEAR(run(t, x, turned, true).min_volume_ratio, 1.0, 1e-12) << name;
    EXPECT_EQ(run(t, x, mirrored, false).min_volume_ratio, 1.0) << name;  // small strain: not measured
  }
}

TEST(ElementKernel, IncompatibleModesMakeTheQuadExactInPureBending) {
  // Pure bending of a rectangle a × b: u = κ x y, v = −κ x²/2 − ν' κ y²/2 is exact for CPS4I on
  // a rectangle (the modes 1 − ξ², 1 − η² capture it); CPS4 locks in shear. σ11 = E κ y.
  const auto& ti = *model::find_element_type("CPS4I");
  const auto& tf = *model::find_element_type("CPS4");
  const std::vector<Vec3> x = {{0, -0.5, 0}, {4, -0.5, 0}, {4, 0.5, 0}, {0, 0.5, 0}};
  const double kappa = 1e-3;
  // Apply the nodal values of the exact field and let the modes relax.
  const auto u = nodal_field(ti, x, [&](const Vec3& p) -> Vec3 {
    return {kappa * (p[0] - 2) * p[1], -kappa * (p[0] - 2) * (p[0] - 2) / 2 - kNu * kappa * p[1] * p[1] / 2, 0};
  });
  const auto si = run(ti, x, u), sf = run(tf, x, u);
  for (const auto& p : si.points) {
    EXPECT_NEAR(p.stress[0], kE * kappa * p.coords[1], 1e-9 * kE * kappa);
    EXPECT_NEAR(p.stress[3], 0.0, 1e-9 * kE * kappa);
  }
  double shear_full = 0;
  for (const auto& p : sf.points) shear_full = std::max(shear_full, std::abs(p.stress[3]));
  EXPECT_GT(shear_full, 0.1 * kE * kappa);  // the parasitic shear that incompatible modes remove
}

TEST(ElementKernel, WithoutHourglassControlReducedElementsShowTheirHourglassModes) {
  // hourglass_scale = 0 exposes the spurious modes of one-point integration: 12 in C3D8R
  // (4 hourglass vectors × 3 components), 2 in CPE4R/CPS4R (1 × 2), 2 in CAX4R.
  const std::pair<const char*, int> cases[] = {{"C3D8R", 6 + 12}, {"CPE4R", 3 + 2}, {"CPS4R", 3 + 2}, {"CAX4R", 2 + 2}};
  for (const auto& [name, expected] : cases) {
    const auto& t = *model::find_element_type(name);
    const auto x = distorted_coords(t);
    for (double scale : {0.0, 0.005}) {
      const auto s = run(t, x, std::vector<double>(t.n_nodes * t.dim, 0.0), false, {}, {0.7, scale});
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(stiffness(s)).eigenvalues();
      int zeros = 0;
      for (int i = 0; i < ev.size(); ++i) zeros += std::abs(ev(i)) < 1e-9 * ev.maxCoeff();
      EXPECT_EQ(zeros, scale == 0.0 ? expected : expected_zero_modes(t)) << name << " scale " << scale;
    }
  }
}

TEST(ElementKernel, HourglassForceIsLinearInTheScale) {
  // f_int = ∫Bᵀσ + K_hg u with K_hg ∝ s: doubling s doubles the hourglass part only.
  const auto& t = *model::find_element_type("C3D8R");
  const auto x = distorted_coords(t);
  std::vector<double> u(24);
  for (int k = 0; k < 24; ++k) u[k] = 1e-3 * std::cos(0.9 * k);
  const auto f0 = run(t, x, u, false, {}, {1.0, 0.0}).internal_force;
  const auto f1 = run(t, x, u, false, {}, {1.0, 0.01}).internal_force;
  const auto f2 = run(t, x, u, false, {}, {1.0, 0.02}).internal_force;
  double hg = 0;
  for (int k = 0; k < 24; ++k) {
    EXPECT_NEAR(f2[k] - f0[k], 2 * (f1[k] - f0[k]), 1e-12);
    hg = std::max(hg, std::abs(f1[k] - f0[k]));
  }
  EXPECT_GT(hg, 0.0);
}

TEST(ElementKernel, NlgeomIncompatibleModesConvergeLocally) {
  const auto& t = *model::find_element_type("C3D8I");
  const auto x = distorted_coords(t);
  std::vector<double> u(24);
  for (int k = 0; k < 24; ++k) u[k] = 0.1 * std::sin(1.1 * k);
  const auto s = run(t, x, u, true);
  EXPECT_GE(s.local_iterations, 2);
  EXPECT_LT(s.local_iterations, 30);  // quadratic convergence: a handful of iterations
}
