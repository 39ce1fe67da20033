#pragma once
/// Incompatible modes of C3D8I, CPE4I, CPS4I and CAX4I (Wilson, Taylor, Doherty & Ghaboussi
/// 1973, with the modification of Taylor, Beresford & Wilson 1976 that makes them pass the
/// patch test for any element shape).
///
/// Internal displacement ũ = Σ_k α_k M_k(ξ), M_k = 1 − ξ_k² (k = 1..dim): 3 modes × 3 components
/// = 9 internal DOFs in 3D, 2 × 2 = 4 in 2D. The mode gradients are evaluated with the Jacobian
/// at the element centre:
///   ∇₀M_k(ξ) = (j₀ / j(ξ)) J₀⁻ᵀ ∂M_k/∂ξ,    j = det J (CAX: j = r·det J, the ring measure)
/// so that ∫ ∇₀M_k dV = j₀ J₀⁻ᵀ ∫ ∂M_k/∂ξ dξ = 0: a constant stress does no work on the modes,
/// the modes stay zero under a linear displacement field, and the patch test passes.
/// The modes do not enter the hoop strain of CAX4I (N = 0 for the pseudo-nodes).
///
/// The element kernel treats each mode k as a pseudo-node with N = 0 and gradient ∇₀M_k, and
/// eliminates the internal DOFs by static condensation, K = K_uu − K_uα K_αα⁻¹ K_αu. With NLGEOM
/// the modes enhance the deformation gradient, F = I + ∇₀u + Σ α_k ⊗ ∇₀M_k, and α is found by a
/// local Newton iteration (f_α = 0) on every call, so the kernel stays a pure function.
///
/// Difference from Abaqus: Abaqus's incompatible-mode elements are formulated as enhanced
/// assumed strain elements with more parameters (C3D8I has 13 additional variables, Abaqus
/// Elements Guide, three-dimensional solid element library); results agree for the patch test
/// and closely, not exactly, in bending.
#include <Eigen/Core>

namespace inpact::solver::elements {

/// Number of incompatible modes (pseudo-nodes) for an element of dimension `dim`.
inline int n_incompatible_modes(int dim) { return dim; }

/// Gradients ∇₀M_k (rows, 3 columns, third 0 in 2D) at parametric point xi.
/// J0_inv_t: J₀⁻ᵀ (dim × dim); j0 and j: the centre and point measures defined above.
Eigen::MatrixX3d incompatible_mode_gradients(int dim, const double* xi, const Eigen::MatrixXd& J0_inv_t, double j0,
                                             double j);

}  // namespace inpact::solver::elements
