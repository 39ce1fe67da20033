#pragma once
// Reference and distorted element geometries for the element-kernel tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "model/element_types.hpp"
#include "solver/elements/element_kernel.hpp"
#include "solver/elements/shape_functions.hpp"

namespace inpact::test {

using solver::elements::Vec3;

/// Nodes of the reference element of `type` (unit cube/square/simplex, wedge of height 1),
/// scaled and shifted: 2D elements are placed at x ∈ [2, 3] so that CAX radii are positive.
inline std::vector<Vec3> reference_coords(const model::ElementTypeInfo& type) {
  using solver::elements::Shape;
  const Shape s = solver::elements::element_shape(type);
  std::vector<Vec3> x(type.n_nodes);
  for (int a = 0; a < type.n_nodes; ++a) {
    const auto xi = solver::elements::node_parametric_coords(s, a);
    switch (s) {
      case Shape::Hex8:
      case Shape::Hex20: x[a] = {(xi[0] + 1) / 2, (xi[1] + 1) / 2, (xi[2] + 1) / 2}; break;
      case Shape::Wedge6: x[a] = {xi[0], xi[1], (xi[2] + 1) / 2}; break;
      case Shape::Quad4:
      case Shape::Quad8: x[a] = {2 + (xi[0] + 1) / 2, (xi[1] + 1) / 2, 0}; break;
      case Shape::Tri3:
      case Shape::Tri6: x[a] = {2 + xi[0], xi[1], 0}; break;
      default: x[a] = xi;  // tets
    }
  }
  return x;
}

/// A deterministic, clearly non-affine distortion of the reference element (corners moved by
/// up to ~0.12, midside nodes moved off the chord), still with a positive Jacobian.
inline std::vector<Vec3> distorted_coords(const model::ElementTypeInfo& type) {
  std::vector<Vec3> x = reference_coords(type);
  for (int a = 0; a < type.n_nodes; ++a)
    for (int i = 0; i < type.dim; ++i) x[a][i] += 0.12 * std::sin(1.7 * a + 2.3 * i + 0.4) * (a % 3 == 1 ? 1 : 0.6);
  return x;
}

/// Node-major displacement vector of the field u(X) = c + A·X (A is dim × dim, row-major 3×3).
template <class Field>
std::vector<double> nodal_field(const model::ElementTypeInfo& type, const std::vector<Vec3>& x, Field&& field) {
  std::vector<double> u(static_cast<std::size_t>(type.n_nodes) * type.dim);
  for (int a = 0; a < type.n_nodes; ++a) {
    const Vec3 v = field(x[a]);
    for (int i = 0; i < type.dim; ++i) u[static_cast<std::size_t>(a) * type.dim + i] = v[i];
  }
  return u;
}

/// The DOFs of an element with rotations at its nodes (beams, shells: the translations of every
/// node, then the rotations in the same order) for the small rigid motion u = c + ω × x, θ = ω.
inline std::vector<double> rigid_motion_with_rotations(const std::vector<Vec3>& x, const Vec3& c, const Vec3& w) {
  std::vector<double> u(6 * x.size());
  for (std::size_t a = 0; a < x.size(); ++a) {
    const Vec3& p = x[a];
    const Vec3 wx{w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2], w[0] * p[1] - w[1] * p[0]};
    for (int i = 0; i < 3; ++i) {
      u[3 * a + i] = c[i] + wx[i];
      u[3 * (x.size() + a) + i] = w[i];
    }
  }
  return u;
}

/// What a rigid motion leaves in an element system: the largest stiffness term (the scale), the
/// largest internal force (zero for a rigid motion) and the largest K_ij − K_ji.
struct RigidMotionResidual {
  double scale = 0.0, force = 0.0, skew = 0.0;
};

inline RigidMotionResidual rigid_motion_residual(const solver::elements::ElementSystem& sys) {
  RigidMotionResidual r;
  for (double k : sys.stiffness) r.scale = std::max(r.scale, std::abs(k));
  for (double f : sys.internal_force) r.force = std::max(r.force, std::abs(f));
  for (int i = 0; i < sys.n_dof; ++i)
    for (int j = 0; j < sys.n_dof; ++j) r.skew = std::max(r.skew, std::abs(sys.k(i, j) - sys.k(j, i)));
  return r;
}

}  // namespace inpact::test
