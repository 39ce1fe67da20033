#pragma once
/// Integration rules as Abaqus uses them for each element type, in Abaqus's integration-point
/// order (first parametric direction fastest). Plain data, no Eigen.
#include <array>
#include <vector>

#include "model/element_types.hpp"
#include "shape_functions.hpp"

namespace inpact::solver::elements {

struct QuadraturePoint {
  std::array<double, 3> xi{};  ///< parametric coordinates
  double weight = 0.0;         ///< includes the parametric measure (1/6 for a tet, ½ for a triangle)
};

/// The stiffness integration rule of an element type:
///   C3D8, C3D8I 2×2×2 · C3D8R 1 · C3D20 3×3×3 · C3D20R 2×2×2 · C3D4 1 · C3D10 4 ·
///   C3D6 2 (triangle centroid × 2-point Gauss through r) ·
///   CPE4/CPS4/CAX4 and …4I 2×2 · …4R 1 · …8 3×3 · …8R 2×2 · …3 1 · …6 3 ·
///   T2D2, T3D2 1 · T3D3 2 (Gauss along the element) · springs 1 (the element) ·
///   shells in their plane: S4, S4R, S8R 2×2 · S8 3×3 · S3, S3R, S6 3.
std::vector<QuadraturePoint> element_rule(const model::ElementTypeInfo& type);

/// A rule for integrating over a face/edge shape; exact for the polynomial degree `order` for
/// lines, quads (tensor Gauss) and triangles (up to degree 4).
std::vector<QuadraturePoint> face_rule(Shape face, int order);

/// n-point Gauss–Legendre abscissae and weights on [-1, 1], n = 1..4.
std::vector<std::array<double, 2>> gauss_legendre(int n);

}  // namespace inpact::solver::elements
