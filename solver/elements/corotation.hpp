#pragma once
/// Finite rotations for beams and shells under NLGEOM: the element-independent corotational
/// formulation (Rankin and Nour-Omid 1988; Felippa and Haugen 2005). The element's small-strain
/// kernel stays as it is; a rigid frame follows the element and only the motion relative to that
/// frame reaches the kernel, so the strains stay small while the element turns without limit.
///
/// Unknowns: the kernel's own (beam_elements.hpp, shell_elements.hpp): the translations u_a of
/// the nodes, then their total rotation vectors ψ_a, R_a = exp([ψ_a]×) (Rodrigues), the same
/// convention as a rigid body's rotation node (model/rigid_motion.hpp). ψ is updated additively,
/// so the forces are conjugate to ψ and the tangent is their exact derivative; a node's ψ is
/// singular only where |ψ| reaches 2π about an axis that is free to tilt. A *CLOAD moment reaches
/// ψ as Tᵀ(ψ) m, and RM reports T⁻ᵀ(ψ) of the reaction conjugate to ψ at a node whose rotations
/// are all held (solver/rotation_moments.hpp): both the spatial moment, as Abaqus's.
///
/// The frame R_r = [e1 e2 e3] of the current configuration (E0 of the reference one):
///  - beams: e1 along the chord of the end nodes, e3 = e1 × q / |e1 × q| with q = ½(R_1 + R_2) n1⁰,
///    the section's reference n1 turned by the end nodes' mean rotation (Crisfield), e2 = e3 × e1
///    (a B32's middle node moves and turns against this frame like any other);
///  - shells: e3 along g1 × g2 with g1, g2 the corner nodes' mean edge vectors (the diagonals'
///    cross product for a quadrilateral), e1 the projection of g1, e2 = e3 × e1 (an S8's midside
///    nodes move and turn against this frame).
/// With A = E0 R_rᵀ (the rotation that takes the frame back to its reference orientation) the
/// deformation the kernel sees, in global components of the reference configuration, is
///   ū_a = A (x_a − c) − (X_a − C),   θ̄_a = log(A R_a)
/// (c, C the centroids): zero for any rigid motion. With the kernel's force g and tangent K at d,
/// the element's internal force is Jᵀg and its tangent Jᵀ K J + ∇²(g·d), J = ∂d/∂q, by forward
/// automatic differentiation (second order for the Hessian). For an elastic kernel these are the
/// gradient and Hessian of its energy Π(q) = ½ dᵀK d + f⁰ᵀd: the exact, symmetric tangent; a
/// plastic kernel brings its consistent tangent and its history (the points' trial state is the
/// kernel's at d). Point output is the kernel's at d: stresses and section forces in the
/// reference axes turned with the element (Abaqus's corotational shell and beam axes).
///
/// The derivatives go by the chain rule through A (corotation.cpp): A is differentiated once per
/// element in the 12 unknowns that turn the frame, each node's log(A R_a) in A's 9 entries and its
/// ψ_a; ū_a is bilinear in A and the positions. Every AutoDiff number is 12 wide (13² doubles
/// nested, 1.4 KB) whatever the element's size.
#include <functional>
#include <span>

#include "element_kernel.hpp"

namespace inpact::solver::elements {

/// How the element's rigid frame follows it.
enum class CorotationalFrame { Beam, Shell };

/// The small-strain kernel of the element: writes its tangent, force f(d) and points at a
/// deformation d as `request` asks (request.nlgeom is false).
using SmallStrainKernel =
    std::function<void(std::span<const double> d, const ElementRequest& request, ElementSystem& out)>;

/// Stiffness, internal force and point output of a beam (2 or 3 nodes) or a shell (3, 4 or 8 nodes)
/// with finite rotations. `q` holds the element's unknowns as above; `beam_n1` is a beam's
/// reference n1 axis (unused for shells). An element without a frame (collapsed, or a beam whose
/// end sections are twisted half round against each other) or with a node turned by π or more
/// against its frame (no unique log) reports min_volume_ratio = 0, as an element turned inside
/// out does: the increment is cut back.
void compute_corotational(CorotationalFrame frame, std::span<const Vec3> coords, std::span<const double> q,
                          const Vec3& beam_n1, const SmallStrainKernel& kernel, const ElementRequest& request,
                          ElementSystem& out);

/// Whether the element type turns with finite rotations here: the beams (B31, B32, B32R, B33) and
/// the shells (S3, S3R, S4, S4R, S6, S8, S8R). The one rule the set-up and the kernels use.
bool takes_finite_rotations(const model::ElementTypeInfo& type);

/// exp([ψ]×) and its inverse on rotations by less than π, exposed for tests.
std::array<Vec3, 3> rotation_exp(const Vec3& psi);
Vec3 rotation_log(const std::array<Vec3, 3>& rotation);

}  // namespace inpact::solver::elements
