#pragma once
/// One integration point of a continuum element: deformation and strain, the strain–displacement
/// operator, and the point's contribution to the element stiffness and internal force; the
/// stress and its tangent D come from the point's material (material.hpp).
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
#include "material.hpp"

namespace inpact::solver::elements {

/// Reference-configuration data of one integration point.
struct PointData {
  Eigen::VectorXd N;          ///< shape values (0 for internal modes)
  Eigen::MatrixX3d grad;      ///< ∇₀N_a, third column 0 in 2D
  double radius = 0.0;        ///< CAX: r of the point (> 0)
  double dv = 0.0;            ///< weight · det J · (thickness | 2πr | 1)
  double thermal_strain = 0.0;  ///< α·ΔT at the point
  double temperature = 0.0;     ///< T at the point (ElementRequest::temperature interpolated)
  Vec3 x{};                     ///< reference coordinates of the point (a cylindrical orientation's axes)
};

struct PointState {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Vec6 strain = Vec6::Zero();  ///< ε or E, engineering shear
  Vec6 stress = Vec6::Zero();  ///< σ or S
};

/// Evaluates F and the strain at the point for the DOF vector u (node-major, `dim` per row of
/// pd.grad); the stress is the material's (material.hpp).
PointState point_kinematics(model::ElementFamily family, int dim, bool nlgeom, const PointData& pd,
                            const Eigen::Ref<const Eigen::VectorXd>& u);

/// B(k, a·dim + i) = ∂E_k/∂u_ai (engineering shear rows), F = I for small strain (CAX: the
/// hoop row holds F33 N_a / R).
Eigen::Matrix<double, 6, Eigen::Dynamic> strain_operator(model::ElementFamily family, int dim, const Eigen::Matrix3d& F,
                                                         const PointData& pd);

/// Adds scale · K_σ(S) (the initial-stress stiffness of S, Voigt) to K.
void add_geometric_stiffness(model::ElementFamily family, int dim, const PointData& pd, const Vec6& S, double scale,
                             Eigen::MatrixXd& K);

/// Adds Bᵀσ dV to f and Bᵀ D B dV (+ K_σ) to K (either may be null); D is the material tangent.
void add_point_contribution(model::ElementFamily family, int dim, const Mat6& D, bool nlgeom,
                            const PointData& pd, const PointState& st, Eigen::VectorXd* f, Eigen::MatrixXd* K);

/// Cauchy stress and strain for output (Abaqus order, engineering shear): small strain passes
/// σ and ε through (plane stress fills ε33 from the material and the point's `state`); NLGEOM
/// converts to σ = J⁻¹FSFᵀ and LE.
void point_output(model::ElementFamily family, const Material& m, bool nlgeom, const PointData& pd,
                  const PointState& st, PointResult& out, std::span<const double> state);

}  // namespace inpact::solver::elements
