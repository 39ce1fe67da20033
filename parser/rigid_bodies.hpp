#pragma once
/// *RIGID BODY resolved on the complete deck (rigid_bodies.cpp).
#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

/// Collects each body's nodes (the ELSET's nodes, without the reference and rotation nodes),
/// checks them (a reference or rotation node on solid or plane elements, a node of two bodies)
/// and adds a rotation node for each body without ROT NODE.
void finalize_rigid_bodies(model::Model& m, Diagnostics& diags);

}  // namespace inpact::parser
