#include "shell_contact_offsets.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "model/mesh_queries.hpp"

namespace inpact::solver {

namespace {

/// The shell section of every element (null for other elements).
std::vector<const model::ShellSection*> shell_section_of(const model::Model& m) {
  std::vector<const model::ShellSection*> out(m.mesh.elements.size(), nullptr);
  for (const model::ShellSection& sec : m.mesh.shell_sections)
    if (auto set = m.mesh.elsets.find(sec.elset); set != m.mesh.elsets.end())
      for (std::int32_t e : set->second.rows) out[static_cast<std::size_t>(e)] = &sec;
  return out;
}

/// How far face `face` (0 = SNEG, 1 = SPOS) of element `e` lies from its nodes (0 for a face
/// not on a shell).
double face_distance(const model::Model& m, const std::vector<const model::ShellSection*>& section, std::int32_t e,
                     int face) {
  if (e < 0 || !section[static_cast<std::size_t>(e)]) return 0.0;
  const model::ShellSection& sec = *section[static_cast<std::size_t>(e)];
  const double o = sec.offset;
  return (face == 1 ? 0.5 - o : 0.5 + o) * model::shell_thickness(m.mesh, sec, static_cast<std::size_t>(e));
}

}  // namespace

void check_shell_master(const model::Model& m, const model::ContactPair& pair, const model::Surface& master) {
  if (pair.no_thickness) return;
  const auto section = shell_section_of(m);
  std::optional<double> d;
  for (const model::Face& f : master.faces) {
    const double di = face_distance(m, section, f.element, f.face);
    if (!d) d = di;
    else if (std::abs(di - *d) > 1e-12 * std::max(std::abs(di), std::abs(*d)))
      throw AnalysisError(fmt::format("{}: error: *CONTACT PAIR: the master surface {} lies on shells whose faces are at "
                                      "different distances from their nodes ({} and {}: thickness or OFFSET differ); "
                                      "contact on such a master is not supported yet: make it the slave, or give NO "
                                      "THICKNESS",
                                      m.sources.describe(pair.loc), pair.master, *d, di));
  }
}

std::vector<double> shell_thickness_offsets(const model::Model& m, const model::ContactPair& pair,
                                            const contact::PairKinematics& geometry) {
  if (pair.no_thickness) return {};
  const auto section = shell_section_of(m);
  const auto master_facets = geometry.master().facets();
  const double master =
      master_facets.empty() ? 0.0 : face_distance(m, section, master_facets[0].element, master_facets[0].face);
  const contact::ContactSurface& slave = geometry.slave();
  std::vector<double> offset(slave.nodes().size(), -master);
  bool any = master != 0.0;
  for (std::size_t i = 0; i < offset.size(); ++i) {
    const auto facets = slave.facets_of_node(i);
    if (facets.empty()) continue;
    double sum = 0.0;
    for (std::int32_t f : facets) {
      const contact::Facet& facet = slave.facets()[static_cast<std::size_t>(f)];
      sum += face_distance(m, section, facet.element, facet.face);
    }
    offset[i] -= sum / static_cast<double>(facets.size());
    any = any || sum != 0.0;
  }
  if (!any) return {};
  return offset;
}

}  // namespace inpact::solver
