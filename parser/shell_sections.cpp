/// Shell sections checked against the mesh once the deck is read: defined sets, materials and
/// orientations (the section's and its layers'),
/// shells only, one section an element, and a *NODAL THICKNESS at every node of a section that
/// asks for one.
#include <fmt/format.h>

#include "finalize.hpp"

namespace inpact::parser {

namespace {

const char* keyword_of(const model::ShellSection& sec) {
  return sec.general ? "*SHELL GENERAL SECTION" : "*SHELL SECTION";
}

/// Every node of the section's elements has a *NODAL THICKNESS.
void check_nodal_thickness(const model::Model& m, const model::ShellSection& sec, const model::Set& set,
                           Diagnostics& diags) {
  const auto& el = m.mesh.elements;
  for (std::int32_t e : set.rows)
    for (std::int32_t n : el.nodes_of(static_cast<std::size_t>(e)))
      if (!m.mesh.nodal_thickness.count(n)) {
        diags.error(sec.loc, keyword_of(sec),
                    fmt::format("NODAL THICKNESS: node {} of element {} has no *NODAL THICKNESS",
                                m.mesh.nodes.labels[static_cast<std::size_t>(n)], el.labels[e]));
        return;
      }
}

void check_shell_section(const model::Model& m, const model::ShellSection& sec, Diagnostics& diags,
                         std::vector<std::uint8_t>& has_section) {
  auto set = m.mesh.elsets.find(sec.elset);
  if (set == m.mesh.elsets.end()) {
    diags.error(sec.loc, keyword_of(sec), fmt::format("element set '{}' is not defined", sec.elset));
    return;
  }
  if (sec.layers.empty() && !m.materials.count(sec.material)) {
    diags.error(sec.loc, keyword_of(sec), fmt::format("material '{}' is not defined", sec.material));
    return;
  }
  if (!sec.orientation.empty() && !m.orientations.count(sec.orientation))
    diags.error(sec.orientation_loc, keyword_of(sec), fmt::format("orientation '{}' is not defined", sec.orientation));
  for (const model::ShellLayer& layer : sec.layers) {
    if (!m.materials.count(layer.material))
      diags.error(layer.loc, keyword_of(sec), fmt::format("layer: material '{}' is not defined", layer.material));
    if (!layer.orientation.empty() && !m.orientations.count(layer.orientation))
      diags.error(layer.orientation_loc, keyword_of(sec),
                  fmt::format("layer: orientation '{}' is not defined (expected an *ORIENTATION's name or an angle in "
                              "degrees)", layer.orientation));
  }
  const auto& el = m.mesh.elements;
  for (std::int32_t e : set->second.rows) {
    const auto& type = model::element_type(el.type[static_cast<std::size_t>(e)]);
    if (!model::is_shell(type)) {
      diags.error(sec.loc, keyword_of(sec), fmt::format("element {} ({}) in set {} is not a shell element (S3, S3R, "
                                                        "S4, S4R, S6, S8R, S8)", el.labels[e], type.name, sec.elset));
      return;
    }
    if (has_section[static_cast<std::size_t>(e)]) {
      diags.error(sec.loc, keyword_of(sec), fmt::format("element {} already has a section", el.labels[e]));
      return;
    }
    has_section[static_cast<std::size_t>(e)] = 1;
  }
  if (sec.nodal_thickness) check_nodal_thickness(m, sec, set->second, diags);
}

}  // namespace

void check_shell_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section) {
  for (const model::ShellSection& sec : m.mesh.shell_sections) check_shell_section(m, sec, diags, has_section);
}

}  // namespace inpact::parser
