// Finite rotations of beams and shells (solver/elements/corotation.hpp): the rotation map and
// its inverse, rigid motions by finite rotations that cost nothing, the tangent against central
// differences of the internal force, and the small-rotation limit, which is the linear kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <string_view>
#include <vector>

#include "model/element_types.hpp"
#include "solver/elements/beam_elements.hpp"
#include "solver/elements/corotation.hpp"
#include "solver/elements/mises_plasticity.hpp"
#include "solver/elements/shell_elements.hpp"
#include "solver/elements/shell_section.hpp"

namespace inpact::solver::elements {
namespace {

using Matrix3 = std::array<Vec3, 3>;

Vec3 times(const Matrix3& r, const Vec3& v) {
  Vec3 out{};
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
  return out;
}

TEST(Corotation, TheRotationVectorOfExpIsTheVectorItCameFrom) {
  for (const Vec3& psi : {Vec3{0.0, 0.0, 0.0}, Vec3{1e-9, -2e-9, 3e-9}, Vec3{4e-4, 1e-4, -2e-4},
                          Vec3{0.3, -0.2, 0.5}, Vec3{1.5, 1.0, -2.0}, Vec3{0.0, 0.0, 3.0}}) {
    const Matrix3 r = rotation_exp(psi);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double rrt = r[i][0] * r[j][0] + r[i][1] * r[j][1] + r[i][2] * r[j][2];
        EXPECT_NEAR(rrt, i == j ? 1.0 : 0.0, 1e-15);
      }
    const Vec3 back = rotation_log(r);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], psi[i], 1e-12 * (1 + std::abs(psi[i])));
  }
  // A quarter turn about z takes x to y.
  const Vec3 y = times(rotation_exp({0, 0, M_PI / 2}), {1, 0, 0});
  EXPECT_NEAR(y[0], 0.0, 1e-15);
  EXPECT_NEAR(y[1], 1.0, 1e-15);
}

struct Element {
  std::string_view type;
  std::vector<Vec3> coords;
  bool offset = false;  ///< a beam whose section's centroid lies off its nodes
};

const std::vector<Element>& elements() {
  static const std::vector<Element> all{
      {"B31", {{0, 0, 0}, {1.0, 0.2, -0.1}}},
      {"B33", {{0, 0, 0}, {1.0, 0.2, -0.1}}},
      {"B32", {{0, 0, 0}, {0.52, 0.08, -0.04}, {1.0, 0.2, -0.1}}},
      {"S3", {{0, 0, 0}, {2, 0, 0.1}, {0.3, 1.5, 0}}},
      {"S4", {{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0.1}, {0, 1.4, 0}}},
      {"S4R", {{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0.1}, {0, 1.4, 0}}},
      {"S8R", {{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0.1}, {0, 1.4, 0},
               {1, 0, 0}, {2.1, 0.75, 0.05}, {1.1, 1.45, 0.05}, {0, 0.7, 0}}},
      {"S8", {{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0.1}, {0, 1.4, 0},
              {1, 0, 0}, {2.1, 0.75, 0.05}, {1.1, 1.45, 0.05}, {0, 0.7, 0}}},
      {"B31", {{0, 0, 0}, {1.0, 0.2, -0.1}}, true},  // its centroid off the node line
      {"B32", {{0, 0, 0}, {0.52, 0.08, -0.04}, {1.0, 0.2, -0.1}}, true},
  };
  return all;
}

BeamProperties beam() {
  model::BeamSection s;
  s.dims = {0.3, 0.2};
  BeamProperties p = beam_properties(s, 2e5, 0.3);
  p.n1 = {0, 1, 0};
  return p;
}

ShellProperties shell() {
  model::ShellSection s;
  s.thickness = 0.1;
  s.section_points = 5;
  return shell_properties(s, 2e5, 0.3, 0.0);
}

BeamProperties offset_beam() {
  BeamProperties p = beam();
  p.centroid = {0.04, -0.07};
  return p;
}

ElementSystem evaluate(const Element& el, const std::vector<double>& q, bool nlgeom) {
  static const BeamProperties plain = beam(), offset = offset_beam();
  const BeamProperties& b = el.offset ? offset : plain;
  static const ShellProperties s = shell();
  const auto& type = *model::find_element_type(el.type);
  ElementRequest req{.stiffness = true, .internal_force = true, .point_output = true, .nlgeom = nlgeom};
  ElementSystem out;
  if (model::is_beam(type))
    compute_beam(type, el.coords, q, b, req, out);
  else
    compute_shell(type, el.coords, q, s, 0.1, req, {}, {}, out);
  return out;
}

/// The element's unknowns after the rigid motion x → R(psi) x + c: u = (R − I) X + c, ψ_a = psi.
std::vector<double> rigid(const Element& el, const Vec3& psi, const Vec3& c) {
  const std::size_t n = el.coords.size();
  std::vector<double> q(6 * n);
  const Matrix3 r = rotation_exp(psi);
  for (std::size_t a = 0; a < n; ++a) {
    const Vec3 x = times(r, el.coords[a]);
    for (int i = 0; i < 3; ++i) {
      q[3 * a + i] = x[i] - el.coords[a][i] + c[i];
      q[3 * (n + a) + i] = psi[i];
    }
  }
  return q;
}

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Turned by 2 rad about a skew axis and moved, every element is free of force and stress; the
// small-strain kernel alone would strain it by the rotation's second order (1 − cos 2 ≈ 1.4).
TEST(Corotation, AFiniteRigidMotionCostsNothing) {
  for (const Element& el : elements()) {
    const std::vector<double> q = rigid(el, {1.2, -0.8, 1.4}, {0.5, -1.0, 2.0});
    const ElementSystem sys = evaluate(el, q, true);
    const double scale = largest(sys.stiffness);
    EXPECT_LT(largest(sys.internal_force), 1e-11 * scale) << el.type;
    for (const PointResult& p : sys.points) {
      EXPECT_LT(largest({p.stress.begin(), p.stress.end()}), 1e-6) << el.type;
      EXPECT_LT(largest({p.section.begin(), p.section.end()}), 1e-6) << el.type;
    }
    const ElementSystem small = evaluate(el, q, false);
    EXPECT_GT(largest(small.internal_force), 1e-2 * scale) << el.type;
  }
}

// Deformed on top of a finite rotation, the tangent is the derivative of the internal force:
// central differences with step 1e-6 agree to 1e-6 of the largest stiffness term, and the
// tangent is symmetric (it is the energy's Hessian).
TEST(Corotation, TheTangentIsTheDerivativeOfTheInternalForce) {
  for (const Element& el : elements()) {
    std::vector<double> q = rigid(el, {0.7, 0.4, -1.1}, {0.1, 0.2, 0.3});
    for (std::size_t j = 0; j < q.size(); ++j) q[j] += 0.01 * std::sin(3.0 * static_cast<double>(j) + 1.0);
    const ElementSystem sys = evaluate(el, q, true);
    const double scale = largest(sys.stiffness), h = 1e-6;
    double worst = 0.0, skew = 0.0;
    for (int j = 0; j < sys.n_dof; ++j) {
      std::vector<double> plus = q, minus = q;
      plus[j] += h, minus[j] -= h;
      const ElementSystem fp = evaluate(el, plus, true), fm = evaluate(el, minus, true);
      for (int i = 0; i < sys.n_dof; ++i) {
        worst = std::max(worst, std::abs((fp.internal_force[i] - fm.internal_force[i]) / (2 * h) - sys.k(i, j)));
        skew = std::max(skew, std::abs(sys.k(i, j) - sys.k(j, i)));
      }
    }
    EXPECT_LT(worst, 1e-6 * scale) << el.type;
    EXPECT_LT(skew, 1e-9 * scale) << el.type;
  }
}

// A shell of an elastic-perfectly plastic metal (Mises in plane stress at every section point),
// turned by a finite rotation and bent into the plastic range from a virgin committed state: the
// tangent is the derivative of the internal force (its consistent tangent through the frame),
// 1e-5 of the largest term (the yield surface's kink is farther than the step).
TEST(Corotation, APlasticShellsTangentIsTheDerivativeOfItsForce) {
  const Element& el = elements()[4];  // S4
  ElasticConstants c;
  c.youngs_modulus = 2e5;
  c.poissons_ratio = 0.3;
  MisesHardening h;
  h.plastic_strain = {0.0, 1.0};
  h.yield_stress = {200.0, 400.0};
  const MisesPlasticity law(c, h, model::ElementFamily::PlaneStress);
  static const ShellProperties s = shell();
  const auto& type = *model::find_element_type(el.type);
  const std::size_t points = shell_material_points(type, s) * law.state_size();
  std::vector<double> committed(points), trial(points);
  for (std::size_t p = 0; p < points; p += law.state_size())
    law.initial_state(std::span(committed).subspan(p, law.state_size()));
  const ShellMaterial material{&law, ElementHistory{committed, trial, law.state_size()}};
  const auto run = [&](const std::vector<double>& q) {
    ElementSystem out;
    compute_shell(type, el.coords, q, s, 0.1, ElementRequest{.nlgeom = true}, {}, material, out);
    return out;
  };
  for (double bend : {1e-4, 0.05}) {  // elastic, then plastic
    std::vector<double> q = rigid(el, {0.7, 0.4, -1.1}, {0.1, 0.2, 0.3});
    for (std::size_t a = 0; a < 4; ++a) q[3 * (4 + a) + 1] += bend * (el.coords[a][0] - 1.0);  // bend about y
    const ElementSystem sys = run(q);
    const double scale = largest(sys.stiffness), h_step = 1e-7;
    double worst = 0.0;
    for (int j = 0; j < sys.n_dof; ++j) {
      std::vector<double> plus = q, minus = q;
      plus[j] += h_step, minus[j] -= h_step;
      const ElementSystem fp = run(plus), fm = run(minus);
      for (int i = 0; i < sys.n_dof; ++i)
        worst = std::max(worst, std::abs((fp.internal_force[i] - fm.internal_force[i]) / (2 * h_step) - sys.k(i, j)));
    }
    EXPECT_LT(worst, 1e-5 * scale) << "bend " << bend;
  }
}

// At small displacements and rotations the element is the linear kernel: the same stiffness at
// zero, and internal forces that differ by the square of the motion (1e-5 here).
TEST(Corotation, SmallRotationsGiveTheLinearElement) {
  for (const Element& el : elements()) {
    std::vector<double> q(6 * el.coords.size());
    for (std::size_t j = 0; j < q.size(); ++j) q[j] = 1e-5 * std::cos(2.0 * static_cast<double>(j));
    const ElementSystem corotated = evaluate(el, q, true), linear = evaluate(el, q, false);
    const double scale = largest(linear.stiffness);
    const std::vector<double> zero(q.size(), 0.0);
    const ElementSystem k0 = evaluate(el, zero, true), k0_linear = evaluate(el, zero, false);
    for (std::size_t i = 0; i < k0.stiffness.size(); ++i)
      EXPECT_NEAR(k0.stiffness[i], k0_linear.stiffness[i], 1e-9 * scale) << el.type;
    const double force = largest(linear.internal_force);
    for (int i = 0; i < linear.n_dof; ++i)
      EXPECT_NEAR(corotated.internal_force[i], linear.internal_force[i], 1e-3 * force) << el.type;
  }
}

// A node turned half round against its element has no unique relative rotation: the element
// says so as an element turned inside out does, and the increment is cut back. Nothing is NaN.
TEST(Corotation, ANodeTurnedHalfRoundAgainstItsElementIsReported) {
  const Element& el = elements()[4];  // S4
  std::vector<double> q(24, 0.0);
  q[12] = M_PI;  // node 1 turned by π about x
  EXPECT_EQ(evaluate(el, q, true).min_volume_ratio, 0.0);
  // A beam whose second node is twisted by π about the chord has no frame: its end sections'
  // n1 point against each other.
  const Element& b31 = elements().front();
  std::vector<double> twist(12, 0.0);
  const Vec3& chord = b31.coords[1];
  const double length = std::sqrt(chord[0] * chord[0] + chord[1] * chord[1] + chord[2] * chord[2]);
  for (int i = 0; i < 3; ++i) twist[9 + i] = M_PI * chord[i] / length;
  EXPECT_EQ(evaluate(b31, twist, true).min_volume_ratio, 0.0);
}

// Beams and shells turn with finite rotations; solids and trusses need none.
TEST(Corotation, TheTypesThatTakeFiniteRotations) {
  for (const char* yes : {"B31", "B32", "B32R", "B33", "S3", "S3R", "S4", "S4R", "S8R", "S8"})
    EXPECT_TRUE(takes_finite_rotations(*model::find_element_type(yes))) << yes;
  for (const char* no : {"C3D8", "T3D2"})
    EXPECT_FALSE(takes_finite_rotations(*model::find_element_type(no))) << no;
}

}  // namespace
}  // namespace inpact::solver::elements
