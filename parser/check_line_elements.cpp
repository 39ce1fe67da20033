/// The sections of trusses and springs checked against the mesh once the deck is read: a truss
/// needs its cross-section area, a spring its *SPRING (not a *SOLID SECTION), SPRING1 and SPRING2
/// their DOFs, and a *SPRING set holds springs only.
#include <fmt/format.h>

#include "finalize.hpp"

namespace inpact::parser {

namespace {

using model::ElementFamily;

const model::ElementTypeInfo& type_of(const model::Model& m, std::int32_t e) {
  return model::element_type(m.mesh.elements.type[static_cast<std::size_t>(e)]);
}

/// The first element of `rows` for which `pred` holds, or -1.
template <class Pred>
std::int32_t first_where(const std::vector<std::int32_t>& rows, Pred pred) {
  for (std::int32_t e : rows)
    if (pred(e)) return e;
  return -1;
}

void check_solid_section(const model::Model& m, const model::SolidSection& sec, Diagnostics& diags) {
  const auto& rows = m.mesh.elsets.at(sec.elset).rows;
  const auto& labels = m.mesh.elements.labels;
  if (std::int32_t e = first_where(rows, [&](auto r) { return type_of(m, r).family == ElementFamily::Spring; }); e >= 0)
    diags.error(sec.loc, "*SOLID SECTION",
                fmt::format("element {} ({}) is a spring: its behaviour comes from *SPRING, not from a section",
                            labels[e], type_of(m, e).name));
  if (sec.value_given) return;
  if (std::int32_t e = first_where(rows, [&](auto r) { return type_of(m, r).family == ElementFamily::Truss; }); e >= 0)
    diags.error(sec.loc, "*SOLID SECTION",
                fmt::format("truss element {} ({}) needs its cross-section area on the data line under *SOLID SECTION",
                            labels[e], type_of(m, e).name));
}

/// One *SPRING against the elements of its set; marks them as having a section.
void check_spring(const model::Model& m, const model::SpringSection& s, Diagnostics& diags,
                  std::vector<std::uint8_t>& has_section) {
  const auto& labels = m.mesh.elements.labels;
  bool dof_reported = false;
  for (std::int32_t e : m.mesh.elsets.at(s.elset).rows) {
    const model::ElementTypeInfo& t = type_of(m, e);
    if (t.family != ElementFamily::Spring) {
      diags.error(s.loc, "*SPRING", fmt::format("element {} ({}) in set {} is not a spring element (SPRINGA, SPRING1, "
                                                "SPRING2)", labels[e], t.name, s.elset));
      return;
    }
    if (has_section[e]) {
      diags.error(s.loc, "*SPRING", fmt::format("element {} already has a section or spring behaviour", labels[e]));
      return;
    }
    has_section[e] = 1;
    if (dof_reported || t.name == "SPRINGA") continue;
    const bool two = t.name == "SPRING2";
    if (s.dof1 == 0 || (two && s.dof2 == 0)) {
      diags.error(s.dof_loc, "*SPRING", fmt::format("{} element {} needs the DOF{} it acts on: a first data line "
                                                    "`{}` before the stiffness", t.name, labels[e], two ? "s" : "",
                                                    two ? "DOF at node 1, DOF at node 2" : "DOF"));
      dof_reported = true;
    } else if (s.dof1 > 3 || (two && s.dof2 > 3)) {
      diags.error(s.dof_loc, "*SPRING", fmt::format("{} element {} acts on a rotational DOF ({}), which inpact's nodes "
                                                    "do not have (expected 1, 2 or 3)", t.name, labels[e],
                                                    s.dof1 > 3 ? s.dof1 : s.dof2));
      dof_reported = true;
    }
  }
}

}  // namespace

void check_line_element_sections(const model::Model& m, Diagnostics& diags, std::vector<std::uint8_t>& has_section) {
  for (const auto& sec : m.mesh.sections)
    if (m.mesh.elsets.count(sec.elset)) check_solid_section(m, sec, diags);
  for (const auto& s : m.mesh.springs) {
    if (!m.mesh.elsets.count(s.elset)) {
      diags.error(s.loc, "*SPRING", fmt::format("element set '{}' is not defined", s.elset));
      continue;
    }
    check_spring(m, s, diags, has_section);
  }
}

}  // namespace inpact::parser
