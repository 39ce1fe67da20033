// Shell kernels S3, S3R, S4, S4R, S8R, S8 and S6 (solver/elements/shell_elements.hpp) and their
// sections (shell_section.hpp): rigid motions without force on flat, warped and curved
// elements, symmetry, and one-element closed forms — a membrane stretch, pure bending with the
// moment D·κ (Simpson's rule is exact for the cubic z² through the thickness), the offset's
// membrane–bending coupling and the transverse shear stiffness of *TRANSVERSE SHEAR STIFFNESS.
#include <gtest/gtest.h>

#include <cmath>
#include <string_view>
#include <vector>

#include "element_fixtures.hpp"
#include "model/element_types.hpp"
#include "solver/elements/shell_elements.hpp"
#include "solver/elements/shell_section.hpp"

namespace inpact::solver::elements {
namespace {

constexpr double kE = 2.0e5, kNu = 0.3, kT = 0.1;

ShellProperties section(double offset = 0.0, int points = 5) {
  model::ShellSection s;
  s.thickness = kT;
  s.section_points = points;
  s.offset = offset;
  return shell_properties(s, kE, kNu, 0.0);
}

ElementSystem run(std::string_view name, const std::vector<Vec3>& x, const std::vector<double>& u,
                  const ShellProperties& p) {
  ElementRequest req;
  req.point_output = true;
  ElementSystem sys;
  compute_shell(*model::find_element_type(name), x, u, p, kT, req, {}, {}, sys);
  return sys;
}

/// Unit-square-like elements in the x–y plane, Abaqus node order (corners, then midsides).
std::vector<Vec3> flat(std::string_view name, double a = 2.0, double b = 1.5) {
  if (name.starts_with("S3")) return {{0, 0, 0}, {a, 0, 0}, {0, b, 0}};
  if (name == "S6") return {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {a / 2, 0, 0}, {a / 2, b / 2, 0}, {0, b / 2, 0}};
  std::vector<Vec3> x = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
  if (name.starts_with("S8"))
    for (int k = 0; k < 4; ++k) {
      const Vec3 &p = x[k], &q = x[(k + 1) % 4];
      x.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    }
  return x;
}

/// Node positions bent onto a cylinder of radius R about the y axis (z = R − √(R² − x²)) and
/// turned, so that the directors differ from node to node and from the global axes.
std::vector<Vec3> curved(std::vector<Vec3> x, double R) {
  for (Vec3& p : x) {
    p[2] = R - std::sqrt(R * R - p[0] * p[0]) + 0.05 * p[1] * p[0];  // curved and warped
    const double c = std::cos(0.4), s = std::sin(0.4);
    p = {c * p[0] - s * p[2], p[1], s * p[0] + c * p[2]};
  }
  return x;
}

constexpr const char* kTypes[] = {"S3", "S3R", "S4", "S4R", "S8R", "S8", "S6"};

// A rigid motion strains nothing and costs nothing (drilling included), flat or curved and
// warped; the stiffness is symmetric. Round-off: 1e-10 of the largest stiffness term.
TEST(ShellElements, RigidMotionsCostNothingAndTheStiffnessIsSymmetric) {
  for (const char* name : kTypes)
    for (bool bent : {false, true}) {
      const std::vector<Vec3> x = bent ? curved(flat(name), 3.0) : flat(name);
      const ShellProperties p = section(bent ? 0.3 : 0.0);
      const ElementSystem sys = run(name, x, test::rigid_motion_with_rotations(x, {0.1, -0.2, 0.3}, {0.01, 0.02, -0.03}), p);
      const test::RigidMotionResidual r = test::rigid_motion_residual(sys);
      EXPECT_GT(sys.min_jacobian, 0.0) << name;
      EXPECT_LT(r.force, 1e-10 * r.scale) << name << (bent ? " curved" : " flat");
      EXPECT_LT(r.skew, 1e-12 * r.scale) << name;
    }
}

// ε11 = 1e-3 with ε22 = 0 (u1 = ε x): σ11 = E ε / (1 − ν²), σ22 = ν σ11 at both surfaces;
// N11 = σ11 t, no moment. Exact for every element (linear fields), to 1e-9 relative.
TEST(ShellElements, MembraneStretchGivesThePlaneStressAnswer) {
  const double eps = 1e-3, s11 = kE * eps / (1 - kNu * kNu);
  for (const char* name : kTypes) {
    const std::vector<Vec3> x = flat(name);
    std::vector<double> u(6 * x.size(), 0.0);
    for (std::size_t a = 0; a < x.size(); ++a) u[3 * a] = eps * x[a][0];
    const ElementSystem sys = run(name, x, u, section());
    ASSERT_FALSE(sys.points.empty()) << name;
    for (const PointResult& r : sys.points) {
      EXPECT_NEAR(r.stress[0], s11, 1e-9 * s11) << name;
      EXPECT_NEAR(r.stress[1], kNu * s11, 1e-9 * s11) << name;
      EXPECT_NEAR(r.strain[0], eps, 1e-12) << name;
      EXPECT_NEAR(r.section[0], s11 * kT, 1e-9 * s11 * kT) << name;
      EXPECT_NEAR(r.section[3], 0.0, 1e-9 * s11 * kT * kT) << name;
    }
  }
}

/// The pure-bending field w = −κx²/2, θ2 = κx (Kirchhoff: no transverse shear), κ = 1e-3.
std::vector<double> bending(const std::vector<Vec3>& x, double kappa) {
  std::vector<double> u(6 * x.size(), 0.0);
  for (std::size_t a = 0; a < x.size(); ++a) {
    u[3 * a + 2] = -kappa * x[a][0] * x[a][0] / 2;
    u[3 * (x.size() + a) + 1] = kappa * x[a][0];
  }
  return u;
}

// Pure bending: M11 = D κ, M22 = ν D κ, D = E t³ / (12 (1 − ν²)); at every section point, from
// SNEG up, σ11 = 12 M z / t³ (∓6M/t² at the surfaces), and the points' volumes sum to t·dA with
// Simpson's weights, so Σ ½σ:ε dV is the bending energy ½ M κ A exactly. S4, S8R, S8 are exact
// (their bilinear or quadratic w ties no shear), the triangles too; 1e-9 relative.
TEST(ShellElements, PureBendingGivesTheMomentDKappa) {
  const double kappa = 1e-3, D = kE * kT * kT * kT / (12 * (1 - kNu * kNu)), M = D * kappa;
  const ShellProperties props = section();
  const std::size_t n = props.zeta.size();
  for (const char* name : kTypes) {
    const std::vector<Vec3> x = flat(name);
    const ElementSystem sys = run(name, x, bending(x, kappa), props);
    ASSERT_EQ(sys.points.size() % n, 0u) << name;
    double volume = 0.0, energy = 0.0;
    for (std::size_t k = 0; k < sys.points.size(); ++k) {
      const PointResult& r = sys.points[k];
      EXPECT_NEAR(r.section[3], M, 1e-9 * M) << name;
      EXPECT_NEAR(r.section[4], kNu * M, 1e-9 * M) << name;
      EXPECT_NEAR(r.section[0], 0.0, 1e-9 * M / kT) << name;
      const double z = props.zeta[k % n] * kT / 2, expected = 12 * M * z / (kT * kT * kT);
      EXPECT_NEAR(r.stress[0], expected, 1e-9 * 6 * M / (kT * kT)) << name;
      volume += r.volume;
      for (int c = 0; c < 6; ++c) energy += 0.5 * r.stress[c] * r.strain[c] * r.volume;
    }
    const double area = volume / kT;
    EXPECT_NEAR(energy, 0.5 * M * kappa * area, 1e-9 * 0.5 * M * kappa * area) << name;
  }
}

// OFFSET = SPOS (0.5): the nodes lie on the top surface, the midsurface t/2 below them. The same
// nodal bending field strains the midsurface by −κ t/2, so N11 = −E t κ (t/2) / (1 − ν²) beside
// M11 = D κ about the midsurface. 1e-9 relative.
TEST(ShellElements, AnOffsetCouplesMembraneAndBending) {
  const double kappa = 1e-3, D = kE * kT * kT * kT / (12 * (1 - kNu * kNu));
  const double N = -kE * kT / (1 - kNu * kNu) * kappa * kT / 2;
  for (const char* name : {"S4", "S8R", "S3"}) {
    const std::vector<Vec3> x = flat(name);
    const ElementSystem sys = run(name, x, bending(x, kappa), section(0.5));
    for (const PointResult& r : sys.points) {
      EXPECT_NEAR(r.section[0], N, 1e-9 * std::abs(N)) << name;
      EXPECT_NEAR(r.section[3], D * kappa, 1e-9 * D * kappa) << name;
    }
  }
}

// A uniform transverse shear γ13 (w = γ x, no rotation) stores K11 γ² / 2 per area with
// K11 = 5/6 G t by default, or the K11 *TRANSVERSE SHEAR STIFFNESS gives: uᵀKu = K11 γ² A.
// S4 (MITC4) and S8R are exact for this linear field; 1e-9 relative (drilling: no rotation).
TEST(ShellElements, TransverseShearStiffnessIsFiveSixthsGtOrTheGivenK) {
  const double gamma = 1e-3, G = kE / (2 * (1 + kNu));
  for (const char* name : {"S4", "S8R", "S3"}) {
    const std::vector<Vec3> x = flat(name);
    const double area = std::string_view(name) == "S3" ? 1.5 : 3.0;
    std::vector<double> u(6 * x.size(), 0.0);
    for (std::size_t a = 0; a < x.size(); ++a) u[3 * a + 2] = gamma * x[a][0];
    for (const auto k11 : {5.0 / 6 * G * kT, 123.0}) {
      ShellProperties p = section();
      if (k11 == 123.0) p.transverse_shear = std::array<double, 2>{123.0, 456.0};
      const ElementSystem sys = run(name, x, u, p);
      double energy = 0.0;
      for (int i = 0; i < sys.n_dof; ++i) energy += u[i] * sys.internal_force[i];
      EXPECT_NEAR(energy, k11 * gamma * gamma * area, 1e-9 * k11 * gamma * gamma * area) << name;
    }
  }
}

// Simpson's rule: the points span [−1, 1] with weights h/3·(1, 4, 2, ..., 4, 1), summing to 2.
TEST(ShellSection, SimpsonPointsAndWeights) {
  std::vector<double> z, w;
  simpson_points(5, z, w);
  ASSERT_EQ(z.size(), 5u);
  const double expected_w[] = {1.0 / 6, 4.0 / 6, 2.0 / 6, 4.0 / 6, 1.0 / 6};
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(z[k], -1.0 + 0.5 * k);
    EXPECT_DOUBLE_EQ(w[k], expected_w[k]);
  }
  EXPECT_THROW(simpson_points(4, z, w), std::invalid_argument);
}

}  // namespace
}  // namespace inpact::solver::elements
