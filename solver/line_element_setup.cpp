#include "line_element_setup.hpp"

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elastic_law.hpp"
#include "elements/beam_elements.hpp"
#include "elements/beam_section.hpp"
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
    const bool axial = s.type->family == ElementFamily::Truss || model::is_beam(*s.type) ||
                       s.type->name == std::string_view("SPRINGA");
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

/// The section's properties: E and ν from its material's isotropic *ELASTIC (a general section
/// gives E and G itself); what beams do not take yet (other materials) stops here.
elements::BeamProperties beam_section_properties(const model::Model& m, const model::BeamSection& sec) {
  const auto where = [&] { return m.sources.describe(sec.loc); };
  if (sec.material.empty()) return elements::beam_properties(sec, 0.0, 0.0);
  const model::Material& mat = m.materials.at(sec.material);
  refuse_temperature_tables(m, mat, "beam elements");
  if (!mat.elastic || mat.elastic->type != model::Elastic::Type::Isotropic || mat.plastic || mat.hyperelastic)
    throw AnalysisError(fmt::format("{}: error: *BEAM SECTION: material '{}' is not isotropic linear elastic; beams "
                                    "take *ELASTIC, TYPE=ISOTROPIC only so far", where(), mat.name));
  return elements::beam_properties(sec, mat.elastic->youngs_modulus, mat.elastic->poissons_ratio);
}

/// Each beam's section, and its local axes at every point: an n1 along the beam leaves no plane
/// to bend in.
void setup_beams(const model::Model& m, AnalysisModel& am) {
  for (const model::BeamSection& sec : m.mesh.beam_sections) {
    const elements::BeamProperties* p =
        am.beams.emplace_back(std::make_shared<elements::BeamProperties>(beam_section_properties(m, sec))).get();
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
      ElementSetup& s = am.elements[static_cast<std::size_t>(row)];
      s.section.beam = p;
      s.density = sec.material.empty() ? 0.0 : m.materials.at(sec.material).density.value_or(0.0);
      for (std::int32_t node : m.mesh.elements.nodes_of(static_cast<std::size_t>(row)))
        if (auto it = m.mesh.node_normals.find(node); it != m.mesh.node_normals.end())
          throw AnalysisError(fmt::format("{}: error: *NODE: node {} of beam element {} is given a normal; a beam's n2 "
                                          "from nodal normals is not supported yet (give n1 on the *BEAM SECTION's "
                                          "second data line)",
                                          m.sources.describe(it->second.loc), m.mesh.nodes.labels[static_cast<std::size_t>(node)],
                                          m.mesh.elements.labels[static_cast<std::size_t>(row)]));
      std::array<elements::Vec3, 3> axes;
      for (const elements::TrussPoint& pt : elements::truss_points(*s.type, am.coords(static_cast<std::size_t>(row)), 3))
        if (pt.J > 0.0 && !elements::beam_axes(pt.tangent, sec.n1, axes))
          throw AnalysisError(fmt::format("{}: error: *BEAM SECTION: the n1 direction ({:g}, {:g}, {:g}) lies along "
                                          "beam element {}; give an n1 across the beam on the section's second data "
                                          "line", m.sources.describe(sec.n1_loc), sec.n1[0], sec.n1[1], sec.n1[2],
                                          m.mesh.elements.labels[static_cast<std::size_t>(row)]));
    }
  }
}

}  // namespace

void setup_line_elements(const model::Model& m, AnalysisModel& am) {
  setup_trusses(m, am);
  setup_beams(m, am);
  for (const model::SpringSection& sec : m.mesh.springs) {
    const elements::SpringBehavior* b = am.springs.emplace_back(spring_behavior(m, sec, am)).get();
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) am.elements[static_cast<std::size_t>(row)].section.spring = b;
  }
}

}  // namespace inpact::solver
