#pragma once
/// One integration point of a continuum element: elasticity matrix, strain–displacement
/// operator, stress, and the point's contribution to the element stiffness and internal force.
/// Small strain and total Lagrangian share one code path:
///
///   F = I + Σ_a u_a ⊗ ∇₀N_a            (CAX: F33 = 1 + u_r/R, the hoop stretch)
///   small strain:  ε = sym(F − I),       σ = D(ε − ε_th),  B = B(I)
///   NLGEOM:        E = ½(FᵀF − I),       S = D(E − ε_th),  B = B(F)  (δE = B δu)
///   f_int = ∫ Bᵀ S dV₀,   K = ∫ Bᵀ D B dV₀ + K_σ,   K_σ(ai,bi) = ∫ ∇₀N_aᵀ S ∇₀N_b dV₀
///                                                     (+ S33 N_a N_b / R² for u_r in CAX)
///
/// NLGEOM material: St. Venant–Kirchhoff (S = D:E, the same D as small strain). Abaqus instead
/// integrates a hypoelastic Jaumann-rate law on the Kirchhoff stress; both agree to first order
/// in the strain, and both give zero stress under any rigid rotation. Output is the Cauchy
/// stress σ = J⁻¹ F S Fᵀ and the logarithmic strain LE = ½ ln(F Fᵀ), which is what Abaqus prints
/// as S and LE with NLGEOM.
///
/// Internal-mode "pseudo-nodes" (incompatible_modes.hpp) are ordinary rows here with N_a = 0.
#include <Eigen/Core>

#include "element_kernel.hpp"

namespace inpact::solver::elements {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// The elasticity matrix in Voigt order 11, 22, 33, 12, 13, 23 (engineering shear):
/// 3D/plane strain/axisymmetric: the isotropic 3D matrix (λ + 2μ on the diagonal, μ for shear);
/// plane stress: the in-plane matrix condensed for σ33 = 0, E/(1−ν²)[[1, ν], [ν, 1]] and μ for 12,
/// zero rows/columns for 33, 13, 23.
Mat6 elasticity_matrix(model::ElementFamily family, const ElasticConstants& m);

/// Reference-configuration data of one integration point.
struct PointData {
  Eigen::VectorXd N;          ///< shape values (0 for internal modes)
  Eigen::MatrixX3d grad;      ///< ∇₀N_a, third column 0 in 2D
  double radius = 0.0;        ///< CAX: r of the point (> 0)
  double dv = 0.0;            ///< weight · det J · (thickness | 2πr | 1)
  double thermal_strain = 0.0;  ///< α·ΔT at the point
};

struct PointState {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Vec6 strain = Vec6::Zero();  ///< ε or E, engineering shear
  Vec6 stress = Vec6::Zero();  ///< σ or S
};

/// Evaluates F, the strain and the stress at the point for the DOF vector u (node-major, `dim`
/// per row of pd.grad).
PointState point_state(model::ElementFamily family, int dim, const Mat6& D, bool nlgeom, const PointData& pd,
                       const Eigen::Ref<const Eigen::VectorXd>& u);

/// Adds Bᵀσ dV to f and Bᵀ D B dV (+ K_σ) to K (either may be null).
void add_point_contribution(model::ElementFamily family, int dim, const Mat6& D, bool nlgeom,
                            const PointData& pd, const PointState& st, Eigen::VectorXd* f, Eigen::MatrixXd* K);

/// Cauchy stress and strain for output (Abaqus order, engineering shear): small strain passes
/// σ and ε through (plane stress fills ε33); NLGEOM converts to σ = J⁻¹FSFᵀ and LE.
void point_output(model::ElementFamily family, const ElasticConstants& m, bool nlgeom, const PointData& pd,
                  const PointState& st, PointResult& out);

}  // namespace inpact::solver::elements
