#pragma once
/// *RIGID BODY: nodes that move with a reference node as one rigid body [K16 *RIGID BODY],
/// [CCX *RIGID BODY]. The body's rotation is held by the translations of a rotation node: the
/// deck's ROT NODE (CalculiX), or one inpact adds beside the reference node for an Abaqus deck,
/// whose DOFs 4–6 (DOF 6 in 2D) the reference node's rotations refer to.
#include <cstdint>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

struct RigidBody {
  std::int32_t ref_node = -1;   ///< REF NODE: its translations are the body's
  std::int32_t rot_node = -1;   ///< its translations hold the rotation vector θ (θ3 alone in 2D)
  bool rot_node_added = false;  ///< inpact's own rotation node: not reported, its values are UR/RM of ref_node
  /// Every node that follows the body (TIE NSET, PIN NSET, CalculiX's NSET, the ELSET's
  /// nodes): sorted, unique, without the reference and rotation nodes.
  std::vector<std::int32_t> nodes;
  std::vector<std::int32_t> elements;  ///< ELSET: elements made rigid (no stiffness), sorted
  std::int32_t analytical_surface = -1;  ///< ANALYTICAL SURFACE: index into Model::analytical_surfaces
  SourceLoc loc;                       ///< the keyword line
  SourceLoc ref_loc;                   ///< REF NODE='s value
};

/// The rigid body whose reference node is `node`, or null.
const RigidBody* rigid_body_of_ref_node(const std::vector<RigidBody>& bodies, std::int32_t node);

}  // namespace inpact::model
