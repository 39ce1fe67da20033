#include "rotation_nodes.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "model/element_types.hpp"

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

}  // namespace inpact::parser
