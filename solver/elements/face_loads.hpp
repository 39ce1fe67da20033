#pragma once
/// Consistent nodal forces of element loads: uniform pressure on a face (*DLOAD Pn, *DSLOAD P)
/// and a body force per unit volume (*DLOAD BX/BY/BZ, BR/BZ for CAX; GRAV; CENTRIF through the
/// nodes' volume moments). No Eigen.
///
/// Pressure follows Abaqus's sign: a positive pressure pushes into the element, against the
/// outward normal n:  f_a = −∫_face N_a p n dA.  With the face corner order of FaceDef (which
/// turns INTO a solid by the right-hand rule), n dA = −(∂x/∂s × ∂x/∂t) ds dt for solids; for 2D
/// elements n is the edge direction rotated clockwise and dA = ds · (thickness | 2πr).
/// Forces are evaluated on the coordinates passed in: pass the current coordinates X + u for a
/// follower load (the load stiffness of a follower pressure is not provided yet).
#include <span>
#include <vector>

#include "element_kernel.hpp"
#include "model/loads.hpp"

namespace inpact::solver::elements {

/// Nodal forces (node-major, type.dim per node, all element nodes) of pressure `p` on face
/// `face` (0 = S1).
std::vector<double> pressure_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int face,
                                  double p, const SectionData& section);

/// Nodal forces (node-major, 3 per node, all element nodes) of a traction q, force per unit
/// length, on edge `edge` (0 = E1) of a shell, in the direction `traction` names (model/loads.hpp)
/// at each point of the edge: the in-plane normal and the shell normal are the element's there.
std::vector<double> edge_traction_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int edge,
                                       model::EdgeTraction traction, double q);

/// Nodal forces of a body force b (per unit volume; 2D elements use b[0], b[1]).
std::vector<double> body_force_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                                    const Vec3& b, const SectionData& section);

/// ∫ N_a dV and ∫ N_a x dV of one node a: a load linear in the position, such as the
/// centrifugal force ρω²(I − nnᵀ)(x − x0), is f_a = ρω²(I − nnᵀ)(first − x0 volume), exactly.
struct VolumeMoments {
  double volume = 0.0;
  Vec3 first{0, 0, 0};
};

/// The moments of every node of the element (full integration rule, as body_force_load).
std::vector<VolumeMoments> volume_moments(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                                          const SectionData& section);

/// Area of a face (3D) or of an edge times thickness / 2πr (2D): what the pressure acts on.
double face_area(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int face,
                 const SectionData& section);

}  // namespace inpact::solver::elements
