#include "rotation_nodes.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "finalize.hpp"
#include "model/element_types.hpp"
#include "model/mesh_queries.hpp"
#include "model/reference_nodes.hpp"

namespace inpact::parser {

std::int32_t add_node_beside(model::Mesh& mesh, std::int32_t node) {
  const std::int32_t inst = mesh.nodes.instance[static_cast<std::size_t>(node)];
  std::int64_t label = 0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (mesh.nodes.instance[n] == inst) label = std::max(label, mesh.nodes.labels[n]);
  ++label;
  const auto row = static_cast<std::int32_t>(mesh.nodes.size());
  mesh.nodes.labels.push_back(label);
  mesh.nodes.coords.push_back(mesh.nodes.coords[static_cast<std::size_t>(node)]);
  mesh.nodes.instance.push_back(inst);
  mesh.nodes.index.insert(inst, label, row);
  return row;
}

std::int32_t add_rotation_node(model::Model& m, std::int32_t ref, std::string_view owner) {
  const std::int32_t row = add_node_beside(m.mesh, ref);
  const auto& labels = m.mesh.nodes.labels;
  m.preprocessing_notes.push_back(fmt::format(
      "{}: node {} added to hold the rotations of reference node {} (its U are the reference node's UR, its RF the "
      "moments RM, as CalculiX's ROT NODE)",
      owner, labels[static_cast<std::size_t>(row)], labels[static_cast<std::size_t>(ref)]));
  return row;
}

std::vector<std::uint8_t> continuum_nodes(const model::Model& m) {
  std::vector<std::uint8_t> on_continuum(m.mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    if (model::is_continuum(model::element_type(m.mesh.elements.type[e])))
      for (std::int32_t n : m.mesh.elements.nodes_of(e)) on_continuum[static_cast<std::size_t>(n)] = 1;
  return on_continuum;
}

void check_not_on_continuum(const model::Model& m, std::span<const std::uint8_t> on_continuum, std::int32_t node,
                            model::SourceLoc loc, std::string_view keyword, std::string_view role, Diagnostics& diags) {
  if (node < 0 || !on_continuum[static_cast<std::size_t>(node)]) return;
  diags.error(loc, std::string(keyword),
              fmt::format("the {} {} is a node of solid or plane elements; give the {} a node of its own (one no element "
                          "but springs or trusses connects)",
                          role, m.mesh.nodes.labels[static_cast<std::size_t>(node)],
                          keyword == "*RIGID BODY" ? "body" : "coupling"));
}

/// Rotation nodes of beams and shells: DOFs 4–6 of such a node are its rotation node's
/// translations (the rigid bodies' convention, model/reference_nodes.hpp), so *BOUNDARY, *CLOAD,
/// UR and RM reach them like any DOF.
void add_rotation_nodes(model::Model& m) {
  auto& mesh = m.mesh;
  std::vector<std::uint8_t> rotating(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (model::has_rotations(model::element_type(mesh.elements.type[e])))
      for (std::int32_t n : mesh.elements.nodes_of(e)) rotating[static_cast<std::size_t>(n)] = 1;
  std::map<std::int32_t, std::int32_t> existing;  // a reference node keeps its rotation node
  for (const model::RotatingNode& r : model::rotating_nodes(m, 3)) existing[r.ref_node] = r.rot_node;
  std::map<std::int32_t, std::int64_t> last_label;  // per instance: labels go on from the largest
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    auto& l = last_label[mesh.nodes.instance[n]];
    l = std::max(l, mesh.nodes.labels[n]);
  }
  // A beam or shell cut by a pre-tension section: the copy turns with the original (the cut opens
  // along the normal only), which comes first by row.
  std::map<std::int32_t, std::int32_t> original_of;
  for (const model::PretensionSection& s : m.pretension_sections)
    for (const auto& [orig, copy] : s.node_pairs) original_of[copy] = orig;
  std::size_t added = 0;
  const std::size_t n_nodes = mesh.nodes.size();
  for (std::size_t n = 0; n < n_nodes; ++n) {
    if (!rotating[n]) continue;
    const auto node = static_cast<std::int32_t>(n);
    if (auto it = existing.find(node); it != existing.end()) {
      m.node_rotations.push_back({node, it->second});
      continue;
    }
    if (auto it = original_of.find(node); it != original_of.end() && existing.count(it->second)) {
      m.node_rotations.push_back({node, existing.at(it->second)});
      continue;
    }
    const std::int32_t inst = mesh.nodes.instance[n];
    const std::int64_t label = ++last_label[inst];
    const auto row = static_cast<std::int32_t>(mesh.nodes.size());
    mesh.nodes.labels.push_back(label);
    mesh.nodes.coords.push_back(mesh.nodes.coords[n]);
    mesh.nodes.instance.push_back(inst);
    mesh.nodes.index.insert(inst, label, row);
    m.node_rotations.push_back({node, row});
    existing[node] = row;
    ++added;
  }
  if (added)
    m.preprocessing_notes.push_back(fmt::format(
        "beam and shell elements: {} nodes added to hold the rotations of their nodes (labels from {}; their U are "
        "those nodes' UR, their RF the moments RM, as CalculiX's rotational nodes)",
        added, mesh.nodes.labels[n_nodes]));
}

void tie_mpc_rotations(model::Model& m) {
  if (m.mpc_ties.empty()) return;
  std::vector<std::uint8_t> rotating(m.mesh.nodes.size(), 0);
  for (const model::RotatingNode& r : model::rotating_nodes(m, 3)) rotating[static_cast<std::size_t>(r.ref_node)] = 1;
  const int dim = model::spatial_dimension(m.mesh.elements);
  for (const model::MpcTie& t : m.mpc_ties) {
    if (!rotating[static_cast<std::size_t>(t.dependent)] || !rotating[static_cast<std::size_t>(t.independent)]) continue;
    for (int dof = dim == 3 ? 4 : 6; dof <= 6; ++dof)
      m.equations.push_back({{{t.dependent, dof, 1.0}, {t.independent, dof, -1.0}}, t.loc});
  }
}

}  // namespace inpact::parser
