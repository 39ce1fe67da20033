/// *RIGID BODY checked against the complete deck, and the rotation node an Abaqus deck's body
/// gets (kw_rigid_body.cpp reads the keyword).
#include "rigid_bodies.hpp"

#include <algorithm>
#include <map>
#include <span>
#include <string>

#include <fmt/format.h>

#include "model/element_types.hpp"
#include "rotation_nodes.hpp"

namespace inpact::parser {

namespace {

/// What a body is called in messages: a deck's *RIGID BODY, or the rigid beams of *MPC BEAM lines.
std::string describe(const model::Model& m, const model::RigidBody& b) {
  if (!b.mpc_beam) return fmt::format("the rigid body at line {}", b.loc.line);
  return fmt::format("the *MPC BEAM to node {} at line {}", m.mesh.nodes.labels[static_cast<std::size_t>(b.ref_node)],
                     b.loc.line);
}

/// The ELSET's nodes join the body's nodes; the reference and rotation nodes leave them.
void collect_nodes(const model::Mesh& mesh, model::RigidBody& b) {
  for (std::int32_t e : b.elements)
    for (std::int32_t n : mesh.elements.nodes_of(static_cast<std::size_t>(e))) b.nodes.push_back(n);
  std::sort(b.nodes.begin(), b.nodes.end());
  b.nodes.erase(std::unique(b.nodes.begin(), b.nodes.end()), b.nodes.end());
  std::erase_if(b.nodes, [&](std::int32_t n) { return n == b.ref_node || n == b.rot_node; });
}

/// A node of two bodies, or the reference node of one body inside another, cannot follow both.
void check_disjoint(const model::Model& m, Diagnostics& diags) {
  std::map<std::int32_t, std::size_t> body_of;
  for (std::size_t k = 0; k < m.rigid_bodies.size(); ++k) {
    const model::RigidBody& b = m.rigid_bodies[k];
    for (std::int32_t n : b.nodes) {
      auto [it, fresh] = body_of.try_emplace(n, k);
      if (!fresh)
        diags.error(b.loc, b.keyword(), fmt::format("node {} follows {} and {}; a node can follow one only",
                                                    m.mesh.nodes.labels[static_cast<std::size_t>(n)], describe(m, b),
                                                    describe(m, m.rigid_bodies[it->second])));
    }
  }
  for (const model::RigidBody& b : m.rigid_bodies) {
    const auto it = body_of.find(b.ref_node);
    if (it == body_of.end()) continue;
    const std::string label = fmt::format("{}", m.mesh.nodes.labels[static_cast<std::size_t>(b.ref_node)]);
    const std::string other = describe(m, m.rigid_bodies[it->second]);
    diags.error(b.ref_loc, b.keyword(),
                b.mpc_beam ? fmt::format("the independent node {} follows {}: chains of rigid links (an *MPC BEAM "
                                         "from a node that itself follows a rigid body or MPC) are not supported yet",
                                         label, other)
                           : fmt::format("the reference node {} follows {}", label, other));
  }
}

/// Abaqus's rigid beam takes the rotations of its independent node: a solid or plane node has
/// none, and CalculiX's BEAM (the two nodes' distance kept constant) is another constraint.
void check_mpc_beam_node(const model::Model& m, std::span<const std::uint8_t> on_continuum, const model::RigidBody& b,
                         Diagnostics& diags) {
  if (!on_continuum[static_cast<std::size_t>(b.ref_node)]) return;
  diags.error(b.ref_loc, "*MPC",
              fmt::format("the independent (second) node {} of MPC BEAM is a node of solid or plane elements, which have "
                          "no rotations: Abaqus's rigid beam takes the independent node's rotations, so give it a beam "
                          "or shell node, or a node of its own. (CalculiX's BEAM, which keeps the distance of two nodes "
                          "constant, is not supported.)",
                          m.mesh.nodes.labels[static_cast<std::size_t>(b.ref_node)]));
}

/// A rigid element (R3D4, ...) has no stiffness: without a body to follow, its nodes would be
/// held by nothing. The first few are reported.
void check_rigid_elements_in_bodies(const model::Model& m, Diagnostics& diags) {
  std::vector<std::uint8_t> in_body(m.mesh.elements.size(), 0);
  for (const model::RigidBody& b : m.rigid_bodies)
    for (std::int32_t e : b.elements) in_body[static_cast<std::size_t>(e)] = 1;
  int reported = 0;
  for (std::size_t e = 0; e < m.mesh.elements.size() && reported < 3; ++e) {
    const auto& type = model::element_type(m.mesh.elements.type[e]);
    if (!model::is_rigid(type) || in_body[e]) continue;
    diags.error(m.mesh.elements.loc[e], "*ELEMENT",
                fmt::format("element {} ({}) is a rigid element, and no *RIGID BODY, ELSET= holds it: its nodes would "
                            "follow nothing",
                            m.mesh.elements.labels[e], type.name));
    ++reported;
  }
}

}  // namespace

void finalize_rigid_bodies(model::Model& m, Diagnostics& diags) {
  check_rigid_elements_in_bodies(m, diags);
  if (m.rigid_bodies.empty()) return;
  const std::vector<std::uint8_t> on_continuum = continuum_nodes(m);
  for (model::RigidBody& b : m.rigid_bodies) {
    collect_nodes(m.mesh, b);
    if (b.mpc_beam) {
      check_mpc_beam_node(m, on_continuum, b, diags);
      continue;
    }
    check_not_on_continuum(m, on_continuum, b.ref_node, b.ref_loc, b.keyword(), "reference node", diags);
    check_not_on_continuum(m, on_continuum, b.rot_node, b.loc, b.keyword(), "rotation node", diags);
    if (b.nodes.empty() && b.analytical_surface < 0)
      diags.error(b.loc, b.keyword(), "the rigid body has no node other than its reference and rotation nodes");
  }
  check_disjoint(m, diags);
  if (diags.has_errors()) return;
  for (model::RigidBody& b : m.rigid_bodies)
    if (b.rot_node < 0) {
      b.rot_node = add_rotation_node(m, b.ref_node, fmt::format("{} (line {})", b.mpc_beam ? "*MPC BEAM" : b.keyword(),
                                                                b.loc.line));
      b.rot_node_added = true;
    }
}

}  // namespace inpact::parser
