/// Beam sections checked against the mesh once the deck is read.
#include <fmt/format.h>

#include "finalize.hpp"

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

}  // namespace

void check_beam_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section) {
  for (const model::BeamSection& sec : m.mesh.beam_sections) check_beam_section(m, sec, diags, has_section);
}

}  // namespace inpact::parser
