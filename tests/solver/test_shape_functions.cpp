// Shape functions and integration rules: partition of unity, nodal interpolation (N_a(ξ_b) = δ_ab),
// derivatives equal to finite differences, and rules that integrate the reference volume.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "solver/elements/quadrature.hpp"
#include "solver/elements/shape_functions.hpp"

using namespace inpact::solver::elements;

namespace {

constexpr Shape kAll[] = {Shape::Line2, Shape::Line3, Shape::Tri3,   Shape::Tri6, Shape::Quad4, Shape::Quad8,
                          Shape::Tet4,  Shape::Tet10, Shape::Wedge6, Shape::Hex8, Shape::Hex20};

std::array<double, 3> interior_point(Shape s) {
  switch (s) {
    case Shape::Tri3:
    case Shape::Tri6: return {0.21, 0.33, 0};
    case Shape::Tet4:
    case Shape::Tet10: return {0.17, 0.23, 0.31};
    case Shape::Wedge6: return {0.21, 0.33, -0.37};
    default: return {0.31, -0.47, 0.23};
  }
}

}  // namespace

TEST(ShapeFunctions, PartitionOfUnityAndZeroDerivativeSum) {
  for (Shape s : kAll) {
    const ShapeValues v = evaluate_shape(s, interior_point(s));
    double sum = 0, dsum[3] = {0, 0, 0};
    for (int a = 0; a < v.n_nodes; ++a) {
      sum += v.N[a];
      for (int j = 0; j < 3; ++j) dsum[j] += v.dN[a][j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << static_cast<int>(s);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(dsum[j], 0.0, 1e-14) << static_cast<int>(s);
  }
}

TEST(ShapeFunctions, EachFunctionIsOneAtItsNodeAndZeroAtTheOthers) {
  for (Shape s : kAll) {
    const int n = n_nodes(s);
    for (int b = 0; b < n; ++b) {
      const ShapeValues v = evaluate_shape(s, node_parametric_coords(s, b));
      for (int a = 0; a < n; ++a) EXPECT_NEAR(v.N[a], a == b ? 1.0 : 0.0, 1e-14) << static_cast<int>(s) << " a=" << a << " b=" << b;
    }
  }
}

TEST(ShapeFunctions, DerivativesMatchCentralDifferences) {
  const double h = 1e-6;
  for (Shape s : kAll) {
    const auto xi = interior_point(s);
    const ShapeValues v = evaluate_shape(s, xi);
    for (int j = 0; j < parametric_dim(s); ++j) {
      auto xp = xi, xm = xi;
      xp[j] += h;
      xm[j] -= h;
      const ShapeValues vp = evaluate_shape(s, xp), vm = evaluate_shape(s, xm);
      for (int a = 0; a < v.n_nodes; ++a)
        EXPECT_NEAR(v.dN[a][j], (vp.N[a] - vm.N[a]) / (2 * h), 1e-8) << static_cast<int>(s) << " a=" << a << " j=" << j;
    }
  }
}

TEST(Quadrature, AbaqusPointCountsPerElementType) {
  const std::pair<const char*, std::size_t> expected[] = {
      {"C3D8", 8},  {"C3D8R", 1}, {"C3D8I", 8}, {"C3D20", 27}, {"C3D20R", 8}, {"C3D4", 1},  {"C3D10", 4},
      {"C3D6", 2},  {"CPE4", 4},  {"CPE4R", 1}, {"CPE4I", 4},  {"CPE8", 9},   {"CPE8R", 4}, {"CPE3", 1},
      {"CPE6", 3},  {"CPS4", 4},  {"CPS4R", 1}, {"CPS8R", 4},  {"CAX4", 4},   {"CAX4R", 1}, {"CAX8", 9},
      {"CAX8R", 4}, {"CAX3", 1},  {"CAX6", 3}};
  for (const auto& [name, n] : expected) EXPECT_EQ(element_rule(*inpact::model::find_element_type(name)).size(), n) << name;
}

TEST(Quadrature, WeightsSumToTheReferenceMeasure) {
  for (const auto& t : inpact::model::element_types()) {
    if (!inpact::model::is_continuum(t)) continue;  // tests/solver/test_line_elements.cpp
    double w = 0;
    for (const auto& q : element_rule(t)) w += q.weight;
    const Shape s = element_shape(t);
    const double expected = s == Shape::Tet4 || s == Shape::Tet10 ? 1.0 / 6
                            : s == Shape::Tri3 || s == Shape::Tri6 ? 0.5
                            : s == Shape::Wedge6                    ? 1.0
                            : t.dim == 3                            ? 8.0
                                                                    : 4.0;
    EXPECT_NEAR(w, expected, 1e-14) << t.name;
  }
}

TEST(Quadrature, FaceRulesAreExactForTheirDegree) {
  // ∫ g^p h^q over the unit triangle = p! q! / (p + q + 2)!
  auto tri_exact = [](int p, int q) { return std::tgamma(p + 1) * std::tgamma(q + 1) / std::tgamma(p + q + 3); };
  for (int order = 1; order <= 4; ++order) {
    const auto rule = face_rule(Shape::Tri3, order);
    for (int p = 0; p <= order; ++p)
      for (int q = 0; p + q <= order; ++q) {
        double s = 0;
        for (const auto& pt : rule) s += pt.weight * std::pow(pt.xi[0], p) * std::pow(pt.xi[1], q);
        EXPECT_NEAR(s, tri_exact(p, q), 1e-12) << "order " << order << " g^" << p << " h^" << q;
      }
    const auto line = face_rule(Shape::Line2, order);
    for (int p = 0; p <= order; ++p) {
      double s = 0;
      for (const auto& pt : line) s += pt.weight * std::pow(pt.xi[0], p);
      EXPECT_NEAR(s, p % 2 ? 0.0 : 2.0 / (p + 1), 1e-14) << "line order " << order << " s^" << p;
    }
  }
}
