#pragma once
/// Kernels of the elements that are not continua: trusses (T2D2, T3D2, T3D3) and springs
/// (SPRINGA, SPRING1, SPRING2). Same conventions as element_kernel.hpp (node-major DOFs, Abaqus
/// component order); their one stress and strain component sit in slot 11:
///  - trusses: S11 the axial stress N/A, E11 the axial strain (small strain: ε = t₀·∂u/∂s;
///    NLGEOM: total Lagrangian with the Green–Lagrange axial strain E = (l² − L²)/(2L²) and
///    S = E_mod (E − αΔT), as the continua's St. Venant–Kirchhoff; output the logarithmic strain
///    ln(l/L) and N/A with N = λ S A: the area is taken to stay A, a section Poisson's ratio of 0);
///    SF1 (PointResult::section[0]) the axial force N.
///  - springs: S11 the spring force, E11 its relative displacement (Abaqus's convention for
///    spring output). SPRINGA acts along the line joining its nodes (with NLGEOM the current
///    line: K = k nnᵀ + (F/l)(I − nnᵀ)); SPRING1/SPRING2 act on fixed global DOFs.
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "element_kernel.hpp"

namespace inpact::solver::elements {

/// The behaviour of a spring set (*SPRING), shared by its elements.
struct SpringBehavior {
  int dof1 = 0, dof2 = 0;  ///< SPRING1/SPRING2: 0-based DOF at the first and second node
  double stiffness = 0.0;  ///< linear springs
  /// NONLINEAR: {force, relative displacement} in ascending displacement; the force is constant
  /// outside the table (Abaqus and CalculiX), so the tangent there is 0.
  std::vector<std::array<double, 2>> table;

  /// The force F(δ) and its tangent dF/dδ at the relative displacement δ.
  std::pair<double, double> force(double delta) const;
};

/// A point of a truss: shape values and derivatives along ξ, the reference tangent dX/dξ and
/// its length J (= L/2 for a straight two-node truss), the point and its weight.
struct TrussPoint {
  std::array<double, 3> N{}, dN{};
  Vec3 x{}, tangent{};
  double J = 0.0, weight = 0.0;
};

/// The integration points of a truss (element_rule: 1 point for two nodes, 2 for T3D3, whose
/// nodes are end, middle, end), over the first `dim` coordinates.
std::vector<TrussPoint> truss_points(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int dim);

/// Stiffness, internal force and point output of a truss or spring. `u` holds dim values per
/// node with dim = u.size() / n_nodes (springs take the model's dimension). min_jacobian is the
/// truss's smallest J (≤ 0: zero length) and 1 for springs.
void compute_line_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                          const ElasticConstants& material, const SectionData& section, const ElementRequest& request,
                          std::span<const double> delta_t, ElementSystem& out);

}  // namespace inpact::solver::elements
