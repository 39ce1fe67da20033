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
  /// PIN NSET: the nodes among `nodes` that follow in translation only. The others tie their
  /// rotations too where they have them (beam and shell nodes): θ_node = θ_body.
  std::vector<std::int32_t> pinned;
  std::vector<std::int32_t> elements;  ///< ELSET: elements made rigid (no stiffness), sorted
  std::int32_t analytical_surface = -1;  ///< ANALYTICAL SURFACE: index into Model::analytical_surfaces
  SourceLoc loc;                       ///< the keyword line
  SourceLoc ref_loc;                   ///< REF NODE='s value
  /// Made from *MPC BEAM lines sharing their independent node (the reference node): a rigid
  /// beam from it to each dependent node (parser/kw_equation.cpp). Messages name *MPC.
  bool mpc_beam = false;

  /// Does `node` (one of `nodes`) turn with the body as well as move with it?
  bool ties_rotation(std::int32_t node) const;
  const char* keyword() const { return mpc_beam ? "*MPC" : "*RIGID BODY"; }
};

/// The rigid body whose reference node is `node`, or null.
const RigidBody* rigid_body_of_ref_node(const std::vector<RigidBody>& bodies, std::int32_t node);

}  // namespace inpact::model
