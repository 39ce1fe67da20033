#include "line_element_setup.hpp"

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/line_elements.hpp"
#include "elements/material.hpp"

namespace inpact::solver {

namespace {

using model::ElementFamily;

double element_length(const model::Model& m, std::size_t e, int dim) {
  const auto nodes = m.mesh.elements.nodes_of(e);
  const auto& a = m.mesh.nodes.coords[nodes.front()];
  const auto& b = m.mesh.nodes.coords[nodes.back()];
  double s = 0.0;
  for (int i = 0; i < dim; ++i) s += (b[i] - a[i]) * (b[i] - a[i]);
  return std::sqrt(s);
}

void setup_trusses(const model::Model& m, AnalysisModel& am) {
  for (const model::SolidSection& sec : m.mesh.sections)
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
      ElementSetup& s = am.elements[static_cast<std::size_t>(row)];
      if (s.type->family != ElementFamily::Truss) continue;
      s.section.area = sec.thickness;
      if (s.material->state_size() > 0)
        throw AnalysisError(fmt::format("{}: error: *SOLID SECTION: truss element {} ({}) has material '{}' with "
                                        "*PLASTIC; plasticity in trusses is not supported yet", m.sources.describe(sec.loc),
                                        m.mesh.elements.labels[row], s.type->name, sec.material));
    }
  for (std::size_t e = 0; e < am.elements.size(); ++e) {
    const ElementSetup& s = am.elements[e];
    const bool axial = s.type->family == ElementFamily::Truss || s.type->name == std::string_view("SPRINGA");
    if (axial && element_length(m, e, am.dim) == 0.0)
      throw AnalysisError(fmt::format("{}: error: *ELEMENT: {} element {} has zero length (its end nodes coincide), so "
                                      "it has no axis to act along", m.sources.describe(m.mesh.elements.loc[e]),
                                      s.type->name, m.mesh.elements.labels[e]));
  }
}

std::shared_ptr<const elements::SpringBehavior> spring_behavior(const model::Model& m, const model::SpringSection& sec,
                                                                const AnalysisModel& am) {
  auto b = std::make_shared<elements::SpringBehavior>();
  b->dof1 = sec.dof1 - 1;
  b->dof2 = (sec.dof2 ? sec.dof2 : sec.dof1) - 1;
  b->stiffness = sec.stiffness;
  b->table = sec.table;
  for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
    const auto& t = *am.elements[static_cast<std::size_t>(row)].type;
    if (t.name == std::string_view("SPRINGA")) continue;
    const int worst = std::max(sec.dof1, t.n_nodes == 2 ? sec.dof2 : 0);
    if (worst > am.dim)
      throw AnalysisError(fmt::format("{}: error: *SPRING: {} element {} acts on DOF {}, but the nodes of this {}D "
                                      "model have DOFs 1 to {}", m.sources.describe(sec.dof_loc), t.name,
                                      m.mesh.elements.labels[row], worst, am.dim, am.dim));
  }
  return b;
}

}  // namespace

void setup_line_elements(const model::Model& m, AnalysisModel& am) {
  setup_trusses(m, am);
  for (const model::SpringSection& sec : m.mesh.springs) {
    const elements::SpringBehavior* b = am.springs.emplace_back(spring_behavior(m, sec, am)).get();
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) am.elements[static_cast<std::size_t>(row)].section.spring = b;
  }
}

}  // namespace inpact::solver
