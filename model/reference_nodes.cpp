#include "reference_nodes.hpp"

#include <algorithm>

namespace inpact::model {

std::vector<RotatingNode> rotating_nodes(const Model& m, int dim) {
  std::vector<RotatingNode> out;
  for (const RigidBody& b : m.rigid_bodies) out.push_back({b.ref_node, b.rot_node, b.rot_node_added});
  for (const Coupling& c : m.couplings)
    if (c.needs_rotations(dim) && c.rot_node >= 0) out.push_back({c.ref_node, c.rot_node, c.rot_node_added});
  const std::size_t n_references = out.size();
  for (const NodeRotation& b : m.node_rotations) {
    const auto first = out.begin(), last = first + static_cast<std::ptrdiff_t>(n_references);
    if (std::find_if(first, last, [&](const RotatingNode& r) { return r.ref_node == b.node; }) == last)
      out.push_back({b.node, b.rot_node, true});
  }
  return out;
}

bool is_reference_node(const Model& m, std::int32_t node) {
  return std::any_of(m.rigid_bodies.begin(), m.rigid_bodies.end(), [&](const RigidBody& b) { return b.ref_node == node; }) ||
         std::any_of(m.couplings.begin(), m.couplings.end(), [&](const Coupling& c) { return c.ref_node == node; });
}

}  // namespace inpact::model
