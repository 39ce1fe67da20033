#include "rigid_body.hpp"

#include <algorithm>

namespace inpact::model {

const RigidBody* rigid_body_of_ref_node(const std::vector<RigidBody>& bodies, std::int32_t node) {
  for (const RigidBody& b : bodies)
    if (b.ref_node == node) return &b;
  return nullptr;
}

bool RigidBody::ties_rotation(std::int32_t node) const { return !std::binary_search(pinned.begin(), pinned.end(), node); }

}  // namespace inpact::model
