#pragma once
/// Hourglass control of the one-point first-order elements C3D8R, CPE4R, CPS4R and CAX4R.
///
/// What is implemented: the stiffness form of Flanagan & Belytschko (1981), "A uniform strain
/// hexahedron and quadrilateral with orthogonal hourglass control", IJNME 17:679–706.
///   γ_α = (1/n)[h_α − Σ_i (h_α · x_i) b_i]        (n = 8 in 3D, 4 in 2D)
/// with h_α the hourglass base vectors (ξη, ξζ, ηζ, ξηζ at the corners in 3D; ξη in 2D),
/// x_i the nodal coordinates in direction i and b_i = ∂N/∂x_i at the centroid. γ_α is orthogonal
/// to every linear field, so rigid motions (any rotation angle) and the patch test are untouched.
/// Each displacement component i gets the generalised hourglass strain q_iα = γ_α · u_i and the
/// force f_i = k Σ_α γ_α q_iα, i.e. K_hg(ai, bj) = δ_ij k Σ_α γ_αa γ_αb, with
///   k = s · G · V · Σ_ia b_ia²        (s = SectionData::hourglass_scale, default 0.005)
/// so the stiffness scales like Abaqus's "total stiffness" hourglass control, whose default
/// scaling is r_F·G with r_F = 0.005 (Abaqus Analysis User's Guide, "Section controls" and
/// *HOURGLASS STIFFNESS). The exact normalisation Abaqus applies to r_F·G was not available, so
/// hourglass energies match Abaqus's total-stiffness approach in form, not to the digit.
///
/// How it differs from Abaqus's default: current Abaqus/Standard releases use the "enhanced"
/// hourglass control (an assumed enhanced-strain method, Puso-like) for C3D8R & co.; it gives the
/// hourglass modes their physical bending stiffness for elastic parallelepipeds, so coarse meshes
/// in bending are much stiffer (and more accurate) than with a small constant stiffness. The
/// 2005 manual (v6.5 User's Guide, Section controls) still names total stiffness as the
/// Abaqus/Standard default. With NLGEOM this stiffness acts on the total displacement (not
/// co-rotated): exact for rigid motions, not objective for rotated hourglass deformation.
#include <Eigen/Core>

namespace inpact::solver::elements {

/// K_hg for an 8-node brick (dim 3, 24×24) or 4-node quadrilateral (dim 2, 8×8).
/// x: n × dim nodal coordinates; b: n × dim shape-function gradients at the centroid;
/// volume: element volume (t·A plane, 2π r₀ A axisymmetric); shear_modulus G; scale s.
Eigen::MatrixXd hourglass_stiffness(int dim, const Eigen::MatrixXd& x, const Eigen::MatrixXd& b, double volume,
                                    double shear_modulus, double scale);

/// The hourglass shape vectors γ_α (rows), for tests.
Eigen::MatrixXd hourglass_shape_vectors(int dim, const Eigen::MatrixXd& x, const Eigen::MatrixXd& b);

}  // namespace inpact::solver::elements
