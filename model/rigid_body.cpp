#include "rigid_body.hpp"

namespace inpact::model {

const RigidBody* rigid_body_of_ref_node(const std::vector<RigidBody>& bodies, std::int32_t node) {
  for (const RigidBody& b : bodies)
    if (b.ref_node == node) return &b;
  return nullptr;
}

}  // namespace inpact::model
