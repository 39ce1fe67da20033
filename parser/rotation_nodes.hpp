#pragma once
/// What rigid bodies, couplings and truss pre-tension sections share on the complete deck: the
/// nodes inpact adds (a rotation node for a reference node, a truss's copy), and which nodes
/// solid or plane elements connect (rotation_nodes.cpp).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

/// A new node at `node`'s coordinates with the next free label of `node`'s instance (a
/// rotation node, a pre-tension copy). Returns its row.
std::int32_t add_node_beside(model::Mesh& mesh, std::int32_t node);

/// A node to hold the rotations of reference node `ref` (model/rigid_body.hpp): the next free
/// label of `ref`'s instance, at `ref`'s coordinates. Adds a preprocessing note that starts with
/// `owner` ("*RIGID BODY (line 12)"). Returns the new node's row.
std::int32_t add_rotation_node(model::Model& m, std::int32_t ref, std::string_view owner);

/// Per node row: 1 when a solid or plane element connects the node (its DOFs are that
/// element's, so it cannot be a reference or rotation node).
std::vector<std::uint8_t> continuum_nodes(const model::Model& m);

/// Reports a reference or rotation node (`role`) that solid or plane elements connect: its DOFs
/// would be the constraint's and the element's at once. (A spring or truss to it is fine.)
void check_not_on_continuum(const model::Model& m, std::span<const std::uint8_t> on_continuum, std::int32_t node,
                            model::SourceLoc loc, std::string_view keyword, std::string_view role, Diagnostics& diags);

}  // namespace inpact::parser
