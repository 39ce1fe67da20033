// Beam kernels B31, B32 and B33 (solver/elements/beam_elements.hpp) and their section properties
// (beam_section.hpp): rigid motions without force, symmetry, and one-element closed forms
// (axial, torsion, bending with shear) that the cantilever decks then check over a mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "element_fixtures.hpp"
#include "model/element_types.hpp"
#include "solver/elements/beam_elements.hpp"
#include "solver/elements/beam_section.hpp"

namespace inpact::solver::elements {
namespace {

BeamProperties rectangle(double a, double b) {
  model::BeamSection s;
  s.shape = model::BeamSection::Shape::Rect;
  s.dims = {a, b};
  s.n1 = {0.0, 0.0, 1.0};
  return beam_properties(s, 2.0e5, 0.3);
}

ElementSystem run(const char* name, const std::vector<Vec3>& x, const std::vector<double>& u, const BeamProperties& p) {
  ElementRequest req;
  req.point_output = true;
  ElementSystem sys;
  compute_beam(*model::find_element_type(name), x, u, p, req, sys);
  return sys;
}

// A rigid motion strains nothing, in any orientation, for every beam element; the stiffness is
// symmetric. Round-off: 1e-10 of the largest stiffness term times the motion.
TEST(BeamElements, RigidMotionsStrainNothingAndTheStiffnessIsSymmetric) {
  const BeamProperties p = rectangle(0.3, 0.2);
  const std::vector<std::vector<Vec3>> shapes = {{{0, 0, 0}, {1.0, 2.0, 0.5}}, {{0, 0, 0}, {0.5, 1.0, 0.25}, {1.0, 2.0, 0.5}}};
  for (const auto& [name, x] : {std::pair{"B31", shapes[0]}, std::pair{"B33", shapes[0]}, std::pair{"B32", shapes[1]}}) {
    const ElementSystem sys = run(name, x, test::rigid_motion_with_rotations(x, {0.1, -0.2, 0.3}, {0.01, 0.02, -0.03}), p);
    const test::RigidMotionResidual r = test::rigid_motion_residual(sys);
    EXPECT_LT(r.force, 1e-10 * r.scale * 0.1) << name;
    EXPECT_LT(r.skew, 1e-14 * r.scale) << name;
  }
}

// One element along x, node 1 held: stretched by δ, N = EA δ/L; twisted by φ, T = GJ φ/L.
TEST(BeamElements, AxialForceAndTorqueMatchTheClosedForms) {
  const BeamProperties p = rectangle(0.3, 0.2);
  const double L = 2.0;
  for (const char* name : {"B31", "B32"}) {
    const bool quadratic = std::string_view(name) == "B32";
    std::vector<Vec3> x = {{0, 0, 0}, {L, 0, 0}};
    if (quadratic) x = {{0, 0, 0}, {L / 2, 0, 0}, {L, 0, 0}};
    const std::size_t n = x.size();
    std::vector<double> u(6 * n, 0.0);
    for (std::size_t a = 0; a < n; ++a) {
      u[3 * a] = 1e-3 * x[a][0];                    // ε = 1e-3
      u[3 * (n + a)] = 2e-3 * x[a][0] / L;          // θ1 about the axis: κ3 = 2e-3 / L
    }
    const ElementSystem sys = run(name, x, u, p);
    ASSERT_FALSE(sys.points.empty());
    for (const PointResult& r : sys.points) {
      EXPECT_NEAR(r.section[0], p.youngs_modulus * p.area * 1e-3, 1e-9 * p.youngs_modulus * p.area * 1e-3) << name;
      EXPECT_NEAR(r.section[5], p.shear_modulus * p.torsion * 2e-3 / L, 1e-9 * p.shear_modulus * p.torsion) << name;
      for (int k : {1, 2, 3, 4}) EXPECT_NEAR(r.section[k], 0.0, 1e-9) << name << " component " << k;
    }
  }
}

// Section properties against hand values: RECT 0.3 × 0.2 (I11 = a b³/12, I22 = b a³/12, J from
// the series: β = 0.1958 for a/b = 1.5, Timoshenko & Goodier's table 0.196), CIRC, PIPE.
TEST(BeamElements, SectionPropertiesMatchHandValues) {
  const BeamProperties r = rectangle(0.3, 0.2);
  EXPECT_DOUBLE_EQ(r.area, 0.06);
  EXPECT_NEAR(r.i11, 0.3 * 0.008 / 12, 1e-18);
  EXPECT_NEAR(r.i22, 0.2 * 0.027 / 12, 1e-18);
  EXPECT_NEAR(r.torsion / (0.3 * 0.008), 0.1958, 2e-4);
  EXPECT_NEAR(r.k13, 0.85 * r.shear_modulus * r.area, 1e-9);
  model::BeamSection c;
  c.shape = model::BeamSection::Shape::Pipe;
  c.dims = {0.5, 0.1};
  const BeamProperties pipe = beam_properties(c, 1.0, 0.0);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(pipe.area, pi * (0.25 - 0.16), 1e-15);
  EXPECT_NEAR(pipe.torsion, pi / 2 * (std::pow(0.5, 4) - std::pow(0.4, 4)), 1e-15);
  c.shape = model::BeamSection::Shape::Circ;
  c.dims = {0.5};
  EXPECT_NEAR(beam_properties(c, 1.0, 0.0).i11, pi * std::pow(0.5, 4) / 4, 1e-15);
}

// BOX 0.3 × 0.2 with side walls (t1 = t3, at ±n1) 0.02 and top and bottom walls 0.03: the
// hollow rectangle's A and I by hand, Bredt's J on the midline (A_m = 0.28 × 0.17), k = 0.44.
TEST(BeamElements, BoxSectionPropertiesMatchHandValues) {
  model::BeamSection b;
  b.shape = model::BeamSection::Shape::Box;
  b.dims = {0.3, 0.2, 0.02, 0.03, 0.02, 0.03};
  const BeamProperties p = beam_properties(b, 2.0e5, 0.3);
  EXPECT_NEAR(p.area, 0.06 - 0.26 * 0.14, 1e-15);
  EXPECT_NEAR(p.i11, (0.3 * 0.008 - 0.26 * std::pow(0.14, 3)) / 12, 1e-15);
  EXPECT_NEAR(p.i22, (0.2 * 0.027 - 0.14 * std::pow(0.26, 3)) / 12, 1e-15);
  const double am = 0.28 * 0.17;
  EXPECT_NEAR(p.torsion, 4 * am * am / (2 * 0.28 / 0.03 + 2 * 0.17 / 0.02), 1e-15);
  EXPECT_NEAR(p.k13, 0.44 * p.shear_modulus * p.area, 1e-9);
}

// A BOX 0.3 × 0.2 whose walls all differ (t1 = 0.02 at +n1, t2 = 0.03 at +n2, t3 = 0.04 at
// −n1, t4 = 0.01 at −n2) against the sum of its four walls as rectangles: the centroid off the
// box's centre, A and I about it; CalculiX's OFFSET1 = 0.5 moves the centroid a further half
// width (0.15) to −n1.
TEST(BeamElements, AnUnevenBoxHasItsCentroidOffTheCentre) {
  model::BeamSection b;
  b.shape = model::BeamSection::Shape::Box;
  b.dims = {0.3, 0.2, 0.02, 0.03, 0.04, 0.01};
  struct Part {
    double w1, w2, c1, c2;  // widths along n1, n2 and centre
  };
  const double inner2 = 0.2 - 0.03 - 0.01, mid2 = (0.01 - 0.03) / 2;  // the side walls span the inside
  const Part parts[] = {{0.02, inner2, 0.15 - 0.01, mid2}, {0.04, inner2, -0.15 + 0.02, mid2},
                        {0.3, 0.03, 0.0, 0.1 - 0.015}, {0.3, 0.01, 0.0, -0.1 + 0.005}};
  double area = 0, s1 = 0, s2 = 0;
  for (const Part& q : parts) area += q.w1 * q.w2, s1 += q.w1 * q.w2 * q.c1, s2 += q.w1 * q.w2 * q.c2;
  const double x1 = s1 / area, x2 = s2 / area;
  double i11 = 0, i22 = 0;
  for (const Part& q : parts) {
    i11 += q.w1 * std::pow(q.w2, 3) / 12 + q.w1 * q.w2 * std::pow(q.c2 - x2, 2);
    i22 += q.w2 * std::pow(q.w1, 3) / 12 + q.w1 * q.w2 * std::pow(q.c1 - x1, 2);
  }
  const BeamProperties p = beam_properties(b, 2.0e5, 0.3);
  EXPECT_NEAR(p.area, area, 1e-15);
  EXPECT_NEAR(p.centroid[0], x1, 1e-15);
  EXPECT_NEAR(p.centroid[1], x2, 1e-15);
  EXPECT_NEAR(p.i11, i11, 1e-15);
  EXPECT_NEAR(p.i22, i22, 1e-15);
  b.offset = {0.5, 0.0};
  EXPECT_NEAR(beam_properties(b, 2.0e5, 0.3).centroid[0], x1 - 0.15, 1e-15);
}

// Abaqus's I with unequal flanges and its origin on the bottom edge (l = 0, h = 0.3, b1 = 0.2,
// b2 = 0.1, t1 = 0.02, t2 = 0.01, t3 = 0.01), by hand from its three rectangles: A, the
// centroid's height, I about it, J = Σ b t³/3; the web shears along n2 over the height between
// the flanges' midlines, the flanges along n1 with 5/6 of their area.
TEST(BeamElements, AnISectionsPropertiesMatchHandValues) {
  model::BeamSection b;
  b.shape = model::BeamSection::Shape::I;
  b.dims = {0.0, 0.3, 0.2, 0.1, 0.02, 0.01, 0.01};
  const BeamProperties p = beam_properties(b, 2.0e5, 0.3);
  const double a1 = 0.2 * 0.02, a2 = 0.1 * 0.01, aw = 0.27 * 0.01, area = a1 + a2 + aw;
  const double e = (a1 * 0.01 + a2 * 0.295 + aw * 0.155) / area;
  EXPECT_NEAR(p.area, area, 1e-15);
  EXPECT_NEAR(p.centroid[0], 0.0, 1e-15);
  EXPECT_NEAR(p.centroid[1], e, 1e-15);
  EXPECT_NEAR(p.i11, 0.2 * 8e-6 / 12 + a1 * (0.01 - e) * (0.01 - e) + 0.1 * 1e-6 / 12 + a2 * (0.295 - e) * (0.295 - e) +
                         0.01 * std::pow(0.27, 3) / 12 + aw * (0.155 - e) * (0.155 - e),
              1e-15);
  EXPECT_NEAR(p.i22, (0.02 * 0.008 + 0.01 * 0.001 + 0.27 * 1e-6) / 12, 1e-15);
  EXPECT_NEAR(p.torsion, (0.2 * 8e-6 + 0.1 * 1e-6 + 0.27 * 1e-6) / 3, 1e-15);
  EXPECT_NEAR(p.k23, p.shear_modulus * 0.01 * (0.3 - 0.015), 1e-9);
  EXPECT_NEAR(p.k13, 5.0 / 6 * p.shear_modulus * (a1 + a2), 1e-9);
}

// n1 along the beam leaves no plane to bend in; across it, the axes are right-handed.
TEST(BeamElements, LocalAxesAreRightHandedAndRefuseAnN1AlongTheBeam) {
  std::array<Vec3, 3> axes;
  EXPECT_FALSE(beam_axes({0, 0, 2}, {0, 0, -1}, axes));
  ASSERT_TRUE(beam_axes({0, 0, 2}, {1, 0, 0.5}, axes));
  const auto& [t, n1, n2] = axes;
  EXPECT_NEAR(n1[0], 1.0, 1e-15);  // n1 = ñ1 without its part along t
  EXPECT_NEAR(n2[1], 1.0, 1e-15);  // n2 = t × n1
  EXPECT_NEAR(t[2], 1.0, 1e-15);
}

}  // namespace
}  // namespace inpact::solver::elements
