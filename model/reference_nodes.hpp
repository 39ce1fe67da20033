#pragma once
/// The nodes with rotations: the reference nodes of rigid bodies and couplings, and the nodes of
/// beam elements. Their DOFs 4–6 (6 in 2D) are the translations of a rotation node
/// (model/rigid_body.hpp).
#include <cstdint>
#include <vector>

#include "model.hpp"

namespace inpact::model {

struct RotatingNode {
  std::int32_t ref_node;
  std::int32_t rot_node;
  bool rot_node_added;  ///< inpact's own: reported as UR/RM of ref_node, not as a node
};

/// Every node with rotations: reference nodes (rigid bodies first, in deck order), then the beam
/// nodes that are not one, by node row. `dim`: the model's.
std::vector<RotatingNode> rotating_nodes(const Model& m, int dim);

/// `node` is the reference node of a rigid body or of a coupling.
bool is_reference_node(const Model& m, std::int32_t node);

}  // namespace inpact::model
