#pragma once
/// The kernels of the beams in space, shear-flexible B31 and B32 (B32R) and Euler–Bernoulli B33
/// (beam_elements.cpp, compute_euler_bernoulli): small strain, linear elastic sections
/// (beam_section.hpp); small rotations, or finite ones under NLGEOM through corotation.hpp. What
/// follows is the shear-flexible kinematics.
///
/// Unknowns: at each node its displacement u and its rotation vector θ. The element's DOFs are
/// the translations of its nodes (end, [middle,] end), then the rotations of the same nodes in
/// the same order, three values each (the rotation node's translations, model::NodeRotation).
///
/// Timoshenko kinematics with u and θ interpolated alike (linear or quadratic Lagrange), in the
/// local system (t, n1, n2) of each integration point: t the tangent, n2 = t × ñ1 / |t × ñ1| for
/// the section's approximate direction ñ1, n1 = n2 × t. The section strains are
///   ε = t·u',  γ1 = n1·u' − n2·θ,  γ2 = n2·u' + n1·θ,  κ3 = t·θ',  κ1 = n1·θ',  κ2 = n2·θ'
/// (′ = d/ds along the reference axis), with the section forces
///   N = EA ε,  V1 = K13 f1 γ1,  V2 = K23 f2 γ2,  M1 = EI11 κ1,  M2 = EI22 κ2,  T = GJ κ3,
/// where f1, f2 are Abaqus's slenderness compensation (beam_section.hpp; f1 with I22 and f2 with
/// I11, the bending each shear strain couples with). Integrated at B31's one point and B32's two
/// (reduced, free of shear locking, no spurious modes).
///
/// Point output (PointResult::section, Abaqus's names and order): SF1 = N, SF2 = V2, SF3 = V1,
/// SM1 = M1, SM2 = M2, SM3 = T; PointResult::strain holds the matching section strains SE1 = ε,
/// SE2 = γ2, SE3 = γ1, SK1 = κ1, SK2 = κ2, SK3 = κ3; volume = A·ds.
#include <span>

#include "beam_section.hpp"
#include "element_kernel.hpp"

namespace inpact::solver::elements {

/// The local axes of a beam point with tangent `tangent` (any length) and the section's
/// approximate n1: {t, n1, n2}; false when ñ1 is (nearly) parallel to t (no plane to bend in).
bool beam_axes(const Vec3& tangent, const Vec3& approximate_n1, std::array<Vec3, 3>& axes);

/// Stiffness, internal force (K u at small rotations; corotated under request.nlgeom) and point
/// output of a B31, B32 or B33.
/// `u` holds 6 values per node in the order above; coords the reference nodes.
void compute_beam(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                  const BeamProperties& section, const ElementRequest& request, ElementSystem& out);

}  // namespace inpact::solver::elements
