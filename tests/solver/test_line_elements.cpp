// Truss and spring kernels (solver/elements/line_elements.hpp): the tangent against central
// finite differences of the internal force, rigid translations without force, closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "model/element_types.hpp"
#include "solver/elements/element_kernel.hpp"
#include "solver/elements/line_elements.hpp"

namespace inpact::solver::elements {
namespace {

const model::ElementTypeInfo& type(const char* name) { return *model::find_element_type(name); }

ElementSystem run(const char* name, const std::vector<Vec3>& x, const std::vector<double>& u, bool nlgeom,
                  const SectionData& section) {
  ElementRequest req;
  req.nlgeom = nlgeom;
  req.point_output = true;
  ElementSystem sys;
  compute_line_element(type(name), x, u, {1000.0, 0.3, 0.0}, section, req, {}, sys);
  return sys;
}

/// max |K − ∂f/∂u (central differences, h = 1e-6)| / max |K|.
double tangent_error(const char* name, const std::vector<Vec3>& x, std::vector<double> u, bool nlgeom,
                     const SectionData& section) {
  const ElementSystem sys = run(name, x, u, nlgeom, section);
  double worst = 0.0, scale = 0.0;
  for (double k : sys.stiffness) scale = std::max(scale, std::abs(k));
  const double h = 1e-6;
  for (int j = 0; j < sys.n_dof; ++j) {
    auto up = u, um = u;
    up[j] += h, um[j] -= h;
    const auto fp = run(name, x, up, nlgeom, section).internal_force;
    const auto fm = run(name, x, um, nlgeom, section).internal_force;
    for (int i = 0; i < sys.n_dof; ++i) worst = std::max(worst, std::abs((fp[i] - fm[i]) / (2 * h) - sys.k(i, j)));
  }
  return worst / scale;
}

// Central differences of a smooth force: error O(h²) ≈ 1e-12 relative, plus round-off 1e-16/h.
TEST(LineElements, NlgeomTrussAndSpringTangentsMatchFiniteDifferences) {
  SectionData truss;
  truss.area = 0.3;
  const std::vector<Vec3> curved = {{0, 0, 0}, {1.0, 0.2, -0.1}, {2.0, 0.1, 0.3}};  // T3D3: end, middle, end
  EXPECT_LT(tangent_error("T3D3", curved, {0, 0, 0, 0.1, -0.05, 0.2, 0.3, 0.4, -0.2}, true, truss), 1e-7);
  EXPECT_LT(tangent_error("T3D2", {{0, 0, 0}, {1, 2, 2}}, {0.1, 0, 0, -0.3, 0.5, 0.2}, true, truss), 1e-7);
  EXPECT_LT(tangent_error("T2D2", {{0, 0, 0}, {3, 4, 0}}, {0, 0, 0.5, -1.0}, true, truss), 1e-7);
  EXPECT_LT(tangent_error("T3D3", curved, {0, 0, 0, 0.1, -0.05, 0.2, 0.3, 0.4, -0.2}, false, truss), 1e-7);
  SpringBehavior linear;
  linear.stiffness = 50.0;
  SectionData spring;
  spring.spring = &linear;
  EXPECT_LT(tangent_error("SPRINGA", {{0, 0, 0}, {1, 1, 0}}, {0.1, 0, 0.2, -0.3, 0.5, 0.1}, true, spring), 1e-7);
}

// A rigid translation strains nothing: no force, in either formulation.
TEST(LineElements, RigidTranslationGivesNoForce) {
  SectionData truss;
  truss.area = 2.0;
  for (bool nlgeom : {false, true}) {
    const auto sys = run("T3D3", {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, {0.3, -0.2, 0.7, 0.3, -0.2, 0.7, 0.3, -0.2, 0.7},
                         nlgeom, truss);
    for (double f : sys.internal_force) EXPECT_NEAR(f, 0.0, 1e-12);
  }
}

// SPRINGA along (3, 4)/5 stretched by 0.5 along its axis: F = k δ = 50 · 0.5, split ∓ on the nodes.
TEST(LineElements, AxialSpringActsAlongItsNodes) {
  SpringBehavior linear;
  linear.stiffness = 50.0;
  SectionData spring;
  spring.spring = &linear;
  const auto sys = run("SPRINGA", {{0, 0, 0}, {3, 4, 0}}, {0, 0, 0.3, 0.4}, false, spring);
  EXPECT_NEAR(sys.points.at(0).stress[0], 25.0, 1e-12);
  EXPECT_NEAR(sys.points.at(0).strain[0], 0.5, 1e-15);
  EXPECT_NEAR(sys.internal_force[2], 25.0 * 0.6, 1e-12);
  EXPECT_NEAR(sys.internal_force[3], 25.0 * 0.8, 1e-12);
  EXPECT_NEAR(sys.internal_force[0], -25.0 * 0.6, 1e-12);
}

TEST(LineElements, NonlinearTableIsConstantBeyondItsEnds) {
  SpringBehavior s;
  s.table = {{0.0, 0.0}, {10.0, 1.0}, {30.0, 2.0}};
  EXPECT_EQ(s.force(-1.0), std::make_pair(0.0, 0.0));
  EXPECT_EQ(s.force(0.0), std::make_pair(0.0, 10.0));  // the end segment's slope on its end point
  EXPECT_EQ(s.force(1.5), std::make_pair(20.0, 20.0));
  EXPECT_EQ(s.force(2.0), std::make_pair(30.0, 20.0));
  EXPECT_EQ(s.force(5.0), std::make_pair(30.0, 0.0));
}

}  // namespace
}  // namespace inpact::solver::elements
