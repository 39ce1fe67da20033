#include "shell_contact_offsets.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/shell_section.hpp"

namespace inpact::solver {

namespace {

/// How far the contact face of facet f lies from its nodes (0 for a face not on a shell).
double face_distance(const AnalysisModel& am, const contact::Facet& f) {
  if (f.element < 0) return 0.0;
  const ElementSetup& e = am.elements[static_cast<std::size_t>(f.element)];
  if (!e.section.shell) return 0.0;
  const double o = e.section.shell->offset;
  return (f.face == 1 ? 0.5 - o : 0.5 + o) * e.section.thickness;  // face 1 = SPOS, 0 = SNEG
}

/// The master's one face distance; AnalysisError when its facets disagree.
double master_distance(const AnalysisModel& am, const model::ContactPair& pair, const contact::ContactSurface& master) {
  std::optional<double> d;
  for (const contact::Facet& f : master.facets()) {
    const double di = face_distance(am, f);
    if (!d) d = di;
    else if (std::abs(di - *d) > 1e-12 * std::max(std::abs(di), std::abs(*d)))
      throw AnalysisError(fmt::format("{}: error: *CONTACT PAIR: the master surface {} lies on shells whose faces are at "
                                      "different distances from their nodes ({} and {}: thickness or OFFSET differ); "
                                      "contact on such a master is not supported yet: make it the slave, or give NO "
                                      "THICKNESS",
                                      am.model->sources.describe(pair.loc), pair.master, *d, di));
  }
  return d.value_or(0.0);
}

}  // namespace

std::vector<double> shell_thickness_offsets(const AnalysisModel& am, const model::ContactPair& pair,
                                            const contact::PairKinematics& geometry) {
  if (pair.no_thickness) return {};
  const contact::ContactSurface& slave = geometry.slave();
  const double master = master_distance(am, pair, geometry.master());
  std::vector<double> offset(slave.nodes().size(), -master);
  bool any = master != 0.0;
  for (std::size_t i = 0; i < offset.size(); ++i) {
    const auto facets = slave.facets_of_node(i);
    if (facets.empty()) continue;
    double sum = 0.0;
    for (std::int32_t f : facets) sum += face_distance(am, slave.facets()[static_cast<std::size_t>(f)]);
    offset[i] -= sum / static_cast<double>(facets.size());
    any = any || sum != 0.0;
  }
  if (!any) return {};
  return offset;
}

}  // namespace inpact::solver
