#pragma once
/// Isoparametric shape functions in the Abaqus node order (Abaqus Theory Manual, "Solid
/// isoparametric quadrilaterals and hexahedra" and "Triangular, tetrahedral, and wedge
/// elements"). Plain arrays only: no Eigen here.
#include <array>
#include <cstdint>

#include "model/element_types.hpp"

namespace inpact::solver::elements {

/// The interpolation of an element or of one of its faces.
enum class Shape : std::uint8_t {
  Line2,   ///< face of quad4/tri3: nodes at s = -1, +1
  Line3,   ///< face of quad8/tri6: corners at s = -1, +1, then the midside node at s = 0
  Tri3,    ///< natural coordinates (g, h), g + h <= 1
  Tri6,
  Quad4,   ///< (ξ, η) ∈ [-1, 1]²
  Quad8,
  Tet4,    ///< (g, h, r), g + h + r <= 1
  Tet10,
  Wedge6,  ///< (g, h) on the triangle, r ∈ [-1, 1] through the thickness
  Hex8,    ///< (ξ, η, ζ) ∈ [-1, 1]³
  Hex20
};

inline constexpr int kMaxNodes = 20;

/// Shape function values and their derivatives with respect to the parametric coordinates.
struct ShapeValues {
  int n_nodes = 0;
  int dim = 0;  ///< number of parametric coordinates (1, 2 or 3)
  std::array<double, kMaxNodes> N{};
  std::array<std::array<double, 3>, kMaxNodes> dN{};  ///< dN[a][j] = ∂N_a/∂ξ_j
};

int n_nodes(Shape s);
int parametric_dim(Shape s);
/// The element interpolation for an Abaqus element type.
Shape element_shape(const model::ElementTypeInfo& type);
/// The interpolation of a face (3D) or edge (2D) with `n_nodes` nodes and `n_corners` corners.
Shape face_shape(int n_nodes, int n_corners);

/// N_a(ξ) and ∂N_a/∂ξ_j at the parametric point `xi` (unused coordinates ignored).
ShapeValues evaluate_shape(Shape s, const std::array<double, 3>& xi);

/// Parametric coordinates of node `a` (for tests and extrapolation).
std::array<double, 3> node_parametric_coords(Shape s, int a);

}  // namespace inpact::solver::elements
