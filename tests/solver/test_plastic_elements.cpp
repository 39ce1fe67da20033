// Every element type with the Mises material: the element stiffness is the central difference
// of the element internal force (the consistent tangent through the element, incompatible modes
// iterated to equilibrium, plane stress condensed, hourglass control), every point yielding.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "solver/elements/mises_plasticity.hpp"

using namespace inpact;
using namespace inpact::solver::elements;
using inpact::test::distorted_coords;
using inpact::test::nodal_field;

namespace {

class PlasticElement : public ::testing::TestWithParam<std::string> {
 protected:
  const model::ElementTypeInfo& type() const { return *model::find_element_type(GetParam()); }
};

std::vector<std::string> type_names() {
  std::vector<std::string> names;
  for (const auto& t : model::element_types())
    if (model::is_continuum(t)) names.emplace_back(t.name);  // trusses, springs: test_line_elements.cpp
  return names;
}

ElementSystem evaluate(const model::ElementTypeInfo& t, const std::vector<Vec3>& x, const std::vector<double>& u,
                       const Material& m) {
  ElementRequest req;
  req.point_output = true;
  ElementSystem sys;
  compute_element(t, x, u, m, {}, req, {}, {}, sys);  // no history: the initial (virgin) state
  return sys;
}

}  // namespace

TEST_P(PlasticElement, StiffnessIsTheCentralDifferenceOfTheInternalForce) {
  const auto& t = type();
  const MisesPlasticity m({200000.0, 0.3, 0.0}, {false, {0.0, 0.01, 0.05}, {250.0, 350.0, 400.0}}, t.family);
  const auto x = distorted_coords(t);
  // A strain of ~4e-3 (three times the yield strain) with a non-affine part, so that every point
  // flows, well away from the elastic–plastic switch the differences must not cross.
  auto u = nodal_field(t, x, [](const Vec3& p) -> Vec3 {
    return {4e-3 * p[0] + 1e-3 * p[1] + 3e-4 * p[1] * p[1], -2e-3 * p[1] + 5e-4 * p[0] * p[1], 1e-3 * p[2] - 6e-4 * p[0]};
  });
  const ElementSystem base = evaluate(t, x, u, m);
  ASSERT_GT(base.min_jacobian, 0.0);
  // Every point yielded (PEEQ > 0).
  for (const auto& p : base.points) ASSERT_GT(p.peeq, 1e-4) << t.name;
  const double h = 1e-8;
  double worst = 0, scale = 0;
  for (int j = 0; j < base.n_dof; ++j) {
    auto up = u, um = u;
    up[j] += h;
    um[j] -= h;
    const auto fp = evaluate(t, x, up, m).internal_force, fm = evaluate(t, x, um, m).internal_force;
    for (int i = 0; i < base.n_dof; ++i) {
      worst = std::max(worst, std::abs((fp[i] - fm[i]) / (2 * h) - base.k(i, j)));
      scale = std::max(scale, std::abs(base.k(i, j)));
    }
  }
  EXPECT_LE(worst, 1e-6 * scale) << t.name << ": worst " << worst / scale;
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PlasticElement, ::testing::ValuesIn(type_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });
