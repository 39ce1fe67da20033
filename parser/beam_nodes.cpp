/// Beam sections checked against the mesh once the deck is read, and the rotation node every beam
/// node gets: its DOFs 4–6 are that node's translations (the rigid bodies' convention,
/// model/reference_nodes.hpp), so *BOUNDARY, *CLOAD, UR and RM reach them like any DOF.
#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "finalize.hpp"
#include "model/reference_nodes.hpp"

namespace inpact::parser {

namespace {

constexpr const char* kKeyword = "*BEAM SECTION";

/// One beam section against its set: defined, beams only, one section an element.
void check_beam_section(const model::Model& m, const model::BeamSection& sec, Diagnostics& diags,
                        std::vector<std::uint8_t>& has_section) {
  const char* keyword = sec.shape == model::BeamSection::Shape::General ? "*BEAM GENERAL SECTION" : kKeyword;
  auto set = m.mesh.elsets.find(sec.elset);
  if (set == m.mesh.elsets.end()) {
    diags.error(sec.loc, keyword, fmt::format("element set '{}' is not defined", sec.elset));
    return;
  }
  if (!sec.material.empty() && !m.materials.count(sec.material))
    diags.error(sec.loc, keyword, fmt::format("material '{}' is not defined", sec.material));
  const auto& el = m.mesh.elements;
  for (std::int32_t e : set->second.rows) {
    const auto& type = model::element_type(el.type[static_cast<std::size_t>(e)]);
    if (!model::is_beam(type)) {
      diags.error(sec.loc, keyword, fmt::format("element {} ({}) in set {} is not a beam element (B31, B32, B33)",
                                                el.labels[e], type.name, sec.elset));
      return;
    }
    if (has_section[static_cast<std::size_t>(e)]) {
      diags.error(sec.loc, keyword, fmt::format("element {} already has a section", el.labels[e]));
      return;
    }
    has_section[static_cast<std::size_t>(e)] = 1;
  }
}

/// A *SOLID SECTION on beams: their section is a *BEAM SECTION.
void check_no_solid_section_on_beams(const model::Model& m, Diagnostics& diags) {
  const auto& el = m.mesh.elements;
  for (const model::SolidSection& sec : m.mesh.sections) {
    auto set = m.mesh.elsets.find(sec.elset);
    if (set == m.mesh.elsets.end()) continue;
    for (std::int32_t e : set->second.rows)
      if (model::is_beam(model::element_type(el.type[static_cast<std::size_t>(e)]))) {
        diags.error(sec.loc, "*SOLID SECTION", fmt::format("element {} is a beam element: its section is a *BEAM "
                                                           "SECTION or *BEAM GENERAL SECTION", el.labels[e]));
        break;
      }
  }
}

}  // namespace

void check_beam_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section) {
  check_no_solid_section_on_beams(m, diags);
  for (const model::BeamSection& sec : m.mesh.beam_sections) check_beam_section(m, sec, diags, has_section);
}

void add_beam_rotation_nodes(model::Model& m) {
  auto& mesh = m.mesh;
  std::vector<std::uint8_t> on_beam(mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (model::is_beam(model::element_type(mesh.elements.type[e])))
      for (std::int32_t n : mesh.elements.nodes_of(e)) on_beam[static_cast<std::size_t>(n)] = 1;
  std::map<std::int32_t, std::int32_t> existing;  // a reference node keeps its rotation node
  for (const model::RotatingNode& r : model::rotating_nodes(m, 3)) existing[r.ref_node] = r.rot_node;
  std::map<std::int32_t, std::int64_t> last_label;  // per instance: labels go on from the largest
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    auto& l = last_label[mesh.nodes.instance[n]];
    l = std::max(l, mesh.nodes.labels[n]);
  }
  // A beam cut by a pre-tension section: the copy turns with the original (the cut opens along
  // the axis only), which comes first by row.
  std::map<std::int32_t, std::int32_t> original_of;
  for (const model::PretensionSection& s : m.pretension_sections)
    if (s.element >= 0)
      for (const auto& [orig, copy] : s.node_pairs) original_of[copy] = orig;
  std::size_t added = 0;
  const std::size_t n_nodes = mesh.nodes.size();
  for (std::size_t n = 0; n < n_nodes; ++n) {
    if (!on_beam[n]) continue;
    const auto node = static_cast<std::int32_t>(n);
    if (auto it = existing.find(node); it != existing.end()) {
      m.beam_rotations.push_back({node, it->second});
      continue;
    }
    if (auto it = original_of.find(node); it != original_of.end() && existing.count(it->second)) {
      m.beam_rotations.push_back({node, existing.at(it->second)});
      continue;
    }
    const std::int32_t inst = mesh.nodes.instance[n];
    const std::int64_t label = ++last_label[inst];
    const auto row = static_cast<std::int32_t>(mesh.nodes.size());
    mesh.nodes.labels.push_back(label);
    mesh.nodes.coords.push_back(mesh.nodes.coords[n]);
    mesh.nodes.instance.push_back(inst);
    mesh.nodes.index.insert(inst, label, row);
    m.beam_rotations.push_back({node, row});
    existing[node] = row;
    ++added;
  }
  if (added)
    m.preprocessing_notes.push_back(fmt::format(
        "beam elements: {} nodes added to hold the rotations of the beam nodes (labels from {}; their U are the beam "
        "nodes' UR, their RF the moments RM, as CalculiX's rotational nodes)",
        added, mesh.nodes.labels[n_nodes]));
}

}  // namespace inpact::parser
