/// *RIGID BODY checked against the complete deck, and the rotation node an Abaqus deck's body
/// gets (kw_rigid_body.cpp reads the keyword).
#include "rigid_bodies.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "model/element_types.hpp"

namespace inpact::parser {

namespace {

constexpr const char* kKeyword = "*RIGID BODY";

/// The ELSET's nodes join the body's nodes; the reference and rotation nodes leave them.
void collect_nodes(const model::Mesh& mesh, model::RigidBody& b) {
  for (std::int32_t e : b.elements)
    for (std::int32_t n : mesh.elements.nodes_of(static_cast<std::size_t>(e))) b.nodes.push_back(n);
  std::sort(b.nodes.begin(), b.nodes.end());
  b.nodes.erase(std::unique(b.nodes.begin(), b.nodes.end()), b.nodes.end());
  std::erase_if(b.nodes, [&](std::int32_t n) { return n == b.ref_node || n == b.rot_node; });
}

/// A reference or rotation node that a solid or plane element connects: its DOFs would be the
/// body's and the element's at once. (A spring or truss to the reference node is fine.)
void check_not_on_continuum(const model::Model& m, const std::vector<std::uint8_t>& on_continuum, std::int32_t node,
                            model::SourceLoc loc, std::string_view role, Diagnostics& diags) {
  if (node < 0 || !on_continuum[static_cast<std::size_t>(node)]) return;
  diags.error(loc, kKeyword, fmt::format("the {} {} is a node of solid or plane elements; give the body a node of "
                                         "its own (one no element but springs or trusses connects)",
                                         role, m.mesh.nodes.labels[static_cast<std::size_t>(node)]));
}

/// A node of two bodies, or the reference node of one body inside another, cannot follow both.
void check_disjoint(const model::Model& m, Diagnostics& diags) {
  std::map<std::int32_t, std::size_t> body_of;
  for (std::size_t k = 0; k < m.rigid_bodies.size(); ++k) {
    const model::RigidBody& b = m.rigid_bodies[k];
    for (std::int32_t n : b.nodes) {
      auto [it, fresh] = body_of.try_emplace(n, k);
      if (!fresh)
        diags.error(b.loc, kKeyword, fmt::format("node {} belongs to this rigid body and to the one at line {}; a node "
                                                 "can follow one body only",
                                                 m.mesh.nodes.labels[static_cast<std::size_t>(n)],
                                                 m.rigid_bodies[it->second].loc.line));
    }
  }
  for (const model::RigidBody& b : m.rigid_bodies)
    if (body_of.count(b.ref_node))
      diags.error(b.ref_loc, kKeyword, fmt::format("the reference node {} follows another rigid body",
                                                   m.mesh.nodes.labels[static_cast<std::size_t>(b.ref_node)]));
}

/// A rotation node beside the reference node for a body without ROT NODE: the next free label
/// of the reference node's instance, at the reference node's coordinates.
void add_rotation_node(model::Model& m, model::RigidBody& b) {
  model::Mesh& mesh = m.mesh;
  const std::int32_t inst = mesh.nodes.instance[static_cast<std::size_t>(b.ref_node)];
  std::int64_t label = 0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (mesh.nodes.instance[n] == inst) label = std::max(label, mesh.nodes.labels[n]);
  ++label;
  const auto row = static_cast<std::int32_t>(mesh.nodes.size());
  mesh.nodes.labels.push_back(label);
  mesh.nodes.coords.push_back(mesh.nodes.coords[static_cast<std::size_t>(b.ref_node)]);
  mesh.nodes.instance.push_back(inst);
  mesh.nodes.index.insert(inst, label, row);
  b.rot_node = row;
  b.rot_node_added = true;
  m.preprocessing_notes.push_back(fmt::format(
      "*RIGID BODY (line {}): node {} added to hold the rotations of reference node {} (its U are the body's UR, its "
      "RF the moments RM, as CalculiX's ROT NODE)",
      b.loc.line, label, mesh.nodes.labels[static_cast<std::size_t>(b.ref_node)]));
}

}  // namespace

void finalize_rigid_bodies(model::Model& m, Diagnostics& diags) {
  if (m.rigid_bodies.empty()) return;
  std::vector<std::uint8_t> on_continuum(m.mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    if (model::is_continuum(model::element_type(m.mesh.elements.type[e])))
      for (std::int32_t n : m.mesh.elements.nodes_of(e)) on_continuum[static_cast<std::size_t>(n)] = 1;
  for (model::RigidBody& b : m.rigid_bodies) {
    collect_nodes(m.mesh, b);
    check_not_on_continuum(m, on_continuum, b.ref_node, b.ref_loc, "reference node", diags);
    check_not_on_continuum(m, on_continuum, b.rot_node, b.loc, "rotation node", diags);
    if (b.nodes.empty())
      diags.error(b.loc, kKeyword, "the rigid body has no node other than its reference and rotation nodes");
  }
  check_disjoint(m, diags);
  if (diags.has_errors()) return;
  for (model::RigidBody& b : m.rigid_bodies)
    if (b.rot_node < 0) add_rotation_node(m, b);
}

}  // namespace inpact::parser
