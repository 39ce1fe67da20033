#pragma once
/// Hybrid elements (C3D8H, C3D20(R)H, C3D4H, C3D10H, CPE4H, CPE8(R)H, CAX4H, CAX8(R)H): the
/// mixed displacement–pressure formulation, the pressure condensed in the element.
///
/// The pressure p and the dilatation Θ are interpolated independently of u, discontinuous
/// from element to element: constant for first-order elements, linear (1, ξ, η[, ζ]) for
/// second-order ones (Simo, Taylor & Pister 1985, the three-field Hu–Washizu form). For an
/// energy split W = W_iso(C̄) + U(J) (every hyperelastic form, and isotropic elasticity) the
/// stationarity in p and Θ solves element by element:
///
///   Θ = P J    (the L2 projection of J onto the pressure space:  ∫ q (J − Θ) dV₀ = 0 ∀q)
///   p = P U'(Θ)
///
/// and what is left is a displacement form with the modified deformation gradient
///
///   F̄ = (Θ/J)^(1/3) F,   Π(u) = Σ_points W(F̄) dV₀,
///
/// whose isochoric part is that of F and whose volume change is Θ: the material is evaluated
/// at F̄ (any Material works), f = ∂Π/∂u and K = ∂²Π/∂u² are exact (symmetric for an energy).
/// Small strain (no NLGEOM): the same with ε̄ = ε + ⅓(θ̄ − tr ε) 1, θ̄ = P tr ε — the B-bar
/// method; K = Σ B̄ᵀ D B̄ dV.
///
/// What the pressure space implies: a first-order element has one constraint instead of one per
/// point (no volumetric locking); C3D4H is C3D4 (one point) and C3D10H is C3D10 (four points,
/// four pressure functions: the projection is the identity), as the mixed element with finite
/// bulk modulus and that quadrature is; any homogeneous deformation gives the standard element's
/// answer. A fully incompressible material (all D = 0) has no finite bulk modulus to condense
/// with: the caller gives it a bulk modulus K0 = 10⁴ μ0 instead (solver/analysis_model.cpp),
/// a volume change of order 1e-4 of the deviatoric strain.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "continuum_kinematics.hpp"
#include "element_kernel.hpp"
#include "material.hpp"

namespace inpact::solver::elements {

/// f, K (when asked) and the points' states (F̄, Ē or ε̄, S) of a hybrid element.
struct HybridSystem {
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  std::vector<PointState> states;
};

/// The pressure functions at the points (m × n_points): 1 for first-order elements,
/// 1, ξ, η[, ζ] for second-order ones.
Eigen::MatrixXd pressure_basis(const model::ElementTypeInfo& type, const std::vector<std::array<double, 3>>& xi);

HybridSystem assemble_hybrid(const model::ElementTypeInfo& type, const Material& law, bool nlgeom,
                             const std::vector<PointData>& pts, const Eigen::MatrixXd& basis,
                             const Eigen::VectorXd& u, bool want_k, const ElementHistory& history);

}  // namespace inpact::solver::elements
