#include "quadrature.hpp"

#include <cmath>
#include <stdexcept>

namespace inpact::solver::elements {
namespace {

using model::Integration;

std::vector<QuadraturePoint> tensor(int n, int dim) {
  const auto g = gauss_legendre(n);
  std::vector<QuadraturePoint> pts;
  if (dim == 1) {
    for (const auto& a : g) pts.push_back({{a[0], 0, 0}, a[1]});
  } else if (dim == 2) {
    for (const auto& b : g)
      for (const auto& a : g) pts.push_back({{a[0], b[0], 0}, a[1] * b[1]});
  } else {
    for (const auto& c : g)
      for (const auto& b : g)
        for (const auto& a : g) pts.push_back({{a[0], b[0], c[0]}, a[1] * b[1] * c[1]});
  }
  return pts;
}

// Symmetric triangle rules on the unit triangle (area ½).
std::vector<QuadraturePoint> triangle(int order) {
  if (order <= 1) return {{{1.0 / 3, 1.0 / 3, 0}, 0.5}};
  if (order == 2) {
    // The 3-point interior rule Abaqus uses for the 6-node triangle: (1/6, 1/6), (2/3, 1/6), (1/6, 2/3).
    return {{{1.0 / 6, 1.0 / 6, 0}, 1.0 / 6}, {{2.0 / 3, 1.0 / 6, 0}, 1.0 / 6}, {{1.0 / 6, 2.0 / 3, 0}, 1.0 / 6}};
  }
  // Strang–Fix / Dunavant 6-point rule, degree 4.
  const double a1 = 0.445948490915965, w1 = 0.223381589678011 / 2;
  const double a2 = 0.091576213509771, w2 = 0.109951743655322 / 2;
  return {{{a1, a1, 0}, w1}, {{1 - 2 * a1, a1, 0}, w1}, {{a1, 1 - 2 * a1, 0}, w1},
          {{a2, a2, 0}, w2}, {{1 - 2 * a2, a2, 0}, w2}, {{a2, 1 - 2 * a2, 0}, w2}};
}

}  // namespace

std::vector<std::array<double, 2>> gauss_legendre(int n) {
  switch (n) {
    case 1: return {{0.0, 2.0}};
    case 2: {
      const double a = 1.0 / std::sqrt(3.0);
      return {{-a, 1.0}, {a, 1.0}};
    }
    case 3: {
      const double a = std::sqrt(0.6);
      return {{-a, 5.0 / 9}, {0.0, 8.0 / 9}, {a, 5.0 / 9}};
    }
    case 4: {
      const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5));
      const double b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
      const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
      return {{-b, wb}, {-a, wa}, {a, wa}, {b, wb}};
    }
    default: throw std::invalid_argument("gauss_legendre: n must be 1..4");
  }
}

std::vector<QuadraturePoint> element_rule(const model::ElementTypeInfo& type) {
  // Trusses: Gauss along the element, 1 point for two nodes, 2 for three (Abaqus's T3D3).
  // Springs: one output location, the element itself.
  // Beams likewise: B31 at one point, B32 at two (Abaqus's reduced integration of both); the
  // cubic B33 at two.
  if (type.family == model::ElementFamily::Beam && type.integration == Integration::Full) return tensor(2, 1);
  if (type.family == model::ElementFamily::Truss || type.family == model::ElementFamily::Beam)
    return tensor(type.n_nodes - 1, 1);
  if (type.family == model::ElementFamily::Spring) return {{{0, 0, 0}, 1.0}};
  // Shells: the in-plane points (shell_elements.hpp): S4 and S4R 2×2, S3, S3R and S6 3, S8R 2×2,
  // S8 3×3.
  if (model::is_shell(type)) {
    if (type.n_nodes == 3 || type.n_nodes == 6) return triangle(2);
    return tensor(type.n_nodes == 8 && type.integration == Integration::Full ? 3 : 2, 2);
  }
  const bool reduced = type.integration == Integration::Reduced;
  switch (element_shape(type)) {
    case Shape::Hex8: return tensor(reduced ? 1 : 2, 3);
    case Shape::Hex20: return tensor(reduced ? 2 : 3, 3);
    case Shape::Quad4: return tensor(reduced ? 1 : 2, 2);
    case Shape::Quad8: return tensor(reduced ? 2 : 3, 2);
    case Shape::Tri3: return triangle(1);
    case Shape::Tri6: return triangle(2);
    case Shape::Tet4: return {{{0.25, 0.25, 0.25}, 1.0 / 6}};
    case Shape::Tet10: {
      // 4-point rule, degree 2: a = (5-√5)/20, b = (5+3√5)/20, weight 1/24 each.
      const double a = (5 - std::sqrt(5.0)) / 20, b = (5 + 3 * std::sqrt(5.0)) / 20;
      return {{{a, a, a}, 1.0 / 24}, {{b, a, a}, 1.0 / 24}, {{a, b, a}, 1.0 / 24}, {{a, a, b}, 1.0 / 24}};
    }
    case Shape::Wedge6: {
      // Triangle centroid × 2-point Gauss in r: integration points 1 (r < 0) and 2 (r > 0).
      // The Abaqus manual page with the C3D6 point count was not in the reference corpus;
      // CalculiX, which follows Abaqus's element conventions, uses the same 2-point rule
      // (mint3d = 2 for C3D6, 9 for C3D15, 1 for C3D6R in its element stiffness routines).
      // It leaves one single-element twist mode (see tests/solver/test_element_kernels.cpp).
      const double a = 1.0 / std::sqrt(3.0);
      return {{{1.0 / 3, 1.0 / 3, -a}, 0.5}, {{1.0 / 3, 1.0 / 3, a}, 0.5}};
    }
    default: break;
  }
  throw std::invalid_argument("element_rule: unsupported element shape");
}

std::vector<QuadraturePoint> face_rule(Shape face, int order) {
  const int n_gauss = order / 2 + 1;  // n-point Gauss is exact to degree 2n-1
  switch (face) {
    case Shape::Line2:
    case Shape::Line3: return tensor(n_gauss, 1);
    case Shape::Quad4:
    case Shape::Quad8: return tensor(n_gauss, 2);
    case Shape::Tri3:
    case Shape::Tri6: return triangle(order);
    default: break;
  }
  throw std::invalid_argument("face_rule: not a face shape");
}

}  // namespace inpact::solver::elements
