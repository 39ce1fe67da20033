#include "analysis_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "element_activity.hpp"
#include "analytical_contact.hpp"
#include "anisotropic_law.hpp"
#include "contact/geometric_correction.hpp"
#include "contact_problem.hpp"
#include "elastic_law.hpp"
#include "elements/material.hpp"
#include "elements/material_orientation.hpp"
#include "elements/quadrature.hpp"
#include "elements/shell_section.hpp"
#include "hyperelastic_material.hpp"
#include "line_element_setup.hpp"
#include "plastic_law.hpp"
#include "shell_element_setup.hpp"
#include "model/mesh_queries.hpp"
#include "model/reference_nodes.hpp"

namespace inpact::solver {

std::size_t AnalysisModel::element_temperature_changes(std::size_t e, std::span<const double> delta_t,
                                                       std::span<double> out) const {
  if (delta_t.empty()) return 0;
  const auto nodes = model->mesh.elements.nodes_of(e);
  const std::size_t n = nodes.size();
  for (std::size_t a = 0; a < n; ++a) out[a] = delta_t[static_cast<std::size_t>(nodes[a])];
  if (delta_t.size() == n_nodes() || !model::is_shell(*elements[e].type)) return n;
  for (std::size_t a = 0; a < n; ++a) out[n + a] = delta_t[n_nodes() + static_cast<std::size_t>(nodes[a])];
  return 2 * n;
}

bool AnalysisModel::reads_temperatures(std::size_t e) const {
  const ElementSetup& s = elements[e];
  return (s.material && s.material->temperature_dependent()) || (s.section.shell && s.section.shell->layer_temperatures);
}

std::size_t AnalysisModel::element_temperatures(std::size_t e, std::span<const double> delta_t,
                                                std::span<double> out) const {
  const auto nodes = model->mesh.elements.nodes_of(e);
  const std::size_t n = nodes.size();
  for (std::size_t a = 0; a < n; ++a) out[a] = temperature(nodes[a], delta_t);
  if (!model::is_shell(*elements[e].type)) return n;
  for (std::size_t a = 0; a < n; ++a) {
    const auto node = static_cast<std::size_t>(nodes[a]);
    const double initial = initial_temperature_gradient.empty() ? 0.0 : initial_temperature_gradient[node];
    out[n + a] = initial + (delta_t.size() > n_nodes() ? delta_t[n_nodes() + node] : 0.0);
  }
  return 2 * n;
}

std::vector<elements::Vec3> AnalysisModel::coords(std::size_t e) const {
  const auto& mesh = model->mesh;
  auto nodes = mesh.elements.nodes_of(e);
  std::vector<elements::Vec3> x(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) x[i] = mesh.nodes.coords[nodes[i]];
  return x;
}

std::size_t AnalysisModel::element_rows(std::size_t e, std::span<std::int32_t> rows) const {
  const auto nodes = model->mesh.elements.nodes_of(e);
  const bool rotations = model::has_rotations(*elements[e].type);
  const std::size_t n = nodes.size() * (rotations ? 2 : 1);
  if (n > rows.size()) throw AnalysisError("internal error: an element with more node rows than the assembler takes");
  std::copy(nodes.begin(), nodes.end(), rows.begin());
  if (rotations)
    for (std::size_t a = 0; a < nodes.size(); ++a)
      rows[nodes.size() + a] = rotation_node_of[static_cast<std::size_t>(nodes[a])];
  return n;
}

namespace {

/// Each element's material law and section data. One law per section and element family (plane
/// stress condenses the elasticity matrix), shared by the section's elements; an element no
/// section covers keeps zero constants.
void assign_materials(const model::Model& m, AnalysisModel& am) {
  // A hyperelastic law also depends on whether the element is hybrid (an incompressible one).
  std::map<std::tuple<std::size_t, model::ElementFamily, bool>, const elements::Material*> laws;
  const bool nlgeom = model::first_nlgeom_step(m.steps) != nullptr;
  const auto law = [&](std::size_t section, const model::ElementTypeInfo& type, const elements::ElasticConstants& c,
                       const model::Material* mat) {
    const model::ElementFamily family = type.family;
    const bool hyperelastic = mat && mat->hyperelastic;
    const elements::Material*& l = laws[{section, family, hyperelastic && type.hybrid}];
    if (l) return l;
    if (mat && !model::is_continuum(type)) refuse_temperature_tables(m, *mat, fmt::format("{} elements", type.name));
    if (hyperelastic) l = am.materials.emplace_back(hyperelastic_law(m, *mat, family, type.hybrid, am.warnings)).get();
    else if (mat && mat->elastic && mat->elastic->type != model::Elastic::Type::Isotropic)
      l = am.materials.emplace_back(anisotropic_law(m, m.mesh.sections[section], *mat, family)).get();
    else if (mat && mat->plastic)
      l = am.materials.emplace_back(plastic_law(m, *mat, family, c, nlgeom, am.warnings)).get();
    else l = am.materials.emplace_back(isotropic_elastic_law(mat, family, c)).get();
    return l;
  };
  for (std::size_t k = 0; k < m.mesh.sections.size(); ++k) {
    const auto& sec = m.mesh.sections[k];
    const model::Material& mat = m.materials.at(sec.material);
    if (!mat.elastic && !mat.hyperelastic)
      throw AnalysisError(fmt::format("{}: error: *MATERIAL: material '{}' has no *ELASTIC definition, which a static "
                                      "analysis needs", m.sources.describe(mat.loc), mat.name));
    if (mat.plastic) refuse_temperature_tables(m, mat, "*PLASTIC");
    if (mat.elastic && mat.elastic->type != model::Elastic::Type::Isotropic)
      refuse_temperature_tables(m, mat, "a directional *ELASTIC");
    elements::ElasticConstants c;
    c.youngs_modulus = mat.elastic ? mat.elastic->youngs_modulus : 0.0;
    c.poissons_ratio = mat.elastic ? mat.elastic->poissons_ratio : 0.0;
    c.expansion = mat.expansion ? mat.expansion->alpha : 0.0;
    const elements::MaterialOrientation* orientation = nullptr;
    if (!sec.orientation.empty()) {
      orientation = am.orientations
                        .emplace_back(std::make_shared<elements::MaterialOrientation>(m.orientations.at(sec.orientation)))
                        .get();
      if (std::any_of(m.steps.begin(), m.steps.end(), [](const model::Step& s) { return s.nlgeom; }))
        am.warnings.push_back(fmt::format("*SOLID SECTION, ELSET={}, ORIENTATION={}: under NLGEOM its S, E and PE are "
                                          "reported in the material axes of the reference configuration (Abaqus turns "
                                          "the axes with the material)", sec.elset, sec.orientation));
    }
    for (std::int32_t e : m.mesh.elsets.at(sec.elset).rows) {
      ElementSetup& s = am.elements[e];
      s.material = law(k, *s.type, c, &mat);
      s.section.thickness = sec.thickness;
      s.density = mat.density.value_or(0.0);
      s.orientation = orientation;
    }
  }
  for (ElementSetup& s : am.elements)
    if (!s.material) s.material = law(m.mesh.sections.size(), *s.type, {}, nullptr);
}

/// *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN names elements with plasticity and points they have.
void check_initial_plastic_strains(const model::Model& m, const AnalysisModel& am) {
  for (const model::InitialPlasticStrain& ic : m.initial_plastic_strains)
    for (std::int32_t e : ic.elements) {
      const ElementSetup& s = am.elements[static_cast<std::size_t>(e)];
      std::vector<double> probe(s.material->state_size());
      const auto where = [&] { return m.sources.describe(ic.loc); };
      if (probe.empty() || !s.material->set_plastic_strain(probe, elements::Vec6::Zero()))
        throw AnalysisError(fmt::format("{}: error: *INITIAL CONDITIONS: TYPE=PLASTIC STRAIN on element {}, whose "
                                        "material has no *PLASTIC", where(), m.mesh.elements.labels[e]));
      if (model::is_shell(*s.type))
        throw AnalysisError(fmt::format("{}: error: *INITIAL CONDITIONS: TYPE=PLASTIC STRAIN on shell element {} is "
                                        "not supported yet (its section points are not read)", where(),
                                        m.mesh.elements.labels[e]));
      const std::size_t points = elements::material_points(*s.type, s.section);
      if (static_cast<std::size_t>(ic.point) > points)
        throw AnalysisError(fmt::format("{}: error: *INITIAL CONDITIONS: element {} ({}) has {} integration points, "
                                        "not {}", where(), m.mesh.elements.labels[e], s.type->name, points, ic.point));
    }
}

/// Near-incompressible material in fully integrated elements locks (Abaqus recommends hybrid
/// elements above ν = 0.495): a silently too stiff answer unless said.
void warn_about_locking(AnalysisModel& am) {
  std::set<std::pair<std::string, std::string>> locking;
  for (const ElementSetup& s : am.elements) {
    if (s.type->integration != model::Integration::Full || s.type->family == model::ElementFamily::PlaneStress ||
        s.type->hybrid || !model::is_continuum(*s.type))
      continue;
    const double nu = s.material->elastic().poissons_ratio;
    if (nu > 0.495) locking.insert({std::string(s.type->name), fmt::format("{:g}", nu)});
  }
  for (const auto& [type, nu] : locking)
    am.warnings.push_back(fmt::format("fully integrated {} elements with Poisson's ratio {} lock (volumetric locking: "
                                      "too stiff, wrong contact pressures); Abaqus uses hybrid elements above 0.495 — use "
                                      "the hybrid (H) form of the element, or its reduced-integration (R) or "
                                      "incompatible-mode (I) form", type, nu));
}

}  // namespace

std::int64_t AnalysisModel::dof_index(std::int32_t node, int dof) const {
  if (dof >= 1 && dof <= dim) {
    const std::int32_t local = local_node_of.empty() ? -1 : local_node_of[static_cast<std::size_t>(node)];
    return static_cast<std::int64_t>(local >= 0 ? local : node) * dim + dof - 1;
  }
  const std::int32_t rot = rotation_node_of.empty() ? -1 : rotation_node_of[static_cast<std::size_t>(node)];
  if (rot < 0) return -1;
  const int component = dim == 3 ? dof - 4 : dof == 6 ? 0 : -1;  // 2D: the in-plane rotation is DOF 6
  if (component < 0 || component >= dim) return -1;
  return static_cast<std::int64_t>(rot) * dim + component;
}

bool AnalysisModel::local_axes(std::int32_t node, std::array<std::array<double, 3>, 3>& e) const {
  const std::int32_t t = transform_of.empty() ? -1 : transform_of[static_cast<std::size_t>(node)];
  return t >= 0 && model::local_axes(model->transforms[static_cast<std::size_t>(t)],
                                     model->mesh.nodes.coords[static_cast<std::size_t>(node)], e);
}

namespace {

/// *TRANSFORM: which nodes have a local system and which of them local DOFs. 3D models only.
void set_transforms(const model::Model& m, AnalysisModel& am) {
  if (m.transforms.empty()) return;
  if (am.dim != 3)
    throw AnalysisError(fmt::format("{}: error: *TRANSFORM: local systems in a two-dimensional model are not supported "
                                    "by inpact yet", m.sources.describe(m.transforms.front().loc)));
  am.transform_of.assign(m.mesh.nodes.size(), -1);
  for (std::size_t t = 0; t < m.transforms.size(); ++t)
    for (std::int32_t n : m.transforms[t].nodes) am.transform_of[static_cast<std::size_t>(n)] = static_cast<std::int32_t>(t);
  am.local_node_of.assign(m.mesh.nodes.size(), -1);
  for (const model::TransformedNode& t : m.transformed_nodes) am.local_node_of[static_cast<std::size_t>(t.node)] = t.local;
}

}  // namespace

namespace {

/// A temperature gradient is a shell's (its thickness): one given at a node that no shell uses
/// would be ignored, so a warning says so, once per line.
void warn_gradients_off_shells(const model::Model& m, AnalysisModel& am) {
  std::vector<char> on_shell(m.mesh.nodes.size(), 0);
  for (std::size_t e = 0; e < m.mesh.elements.size(); ++e)
    if (model::is_shell(model::element_type(m.mesh.elements.type[e])))
      for (std::int32_t n : m.mesh.elements.nodes_of(e)) on_shell[static_cast<std::size_t>(n)] = 1;
  auto check = [&](const model::TemperatureEntry& t, const char* keyword) {
    if (!t.gradient || *t.gradient == 0.0) return;
    for (std::int32_t n : t.nodes)
      if (!on_shell[static_cast<std::size_t>(n)]) {
        am.warnings.push_back(fmt::format("{} at {}: the temperature gradient at node {} is ignored: no shell element "
                                          "uses the node (a beam's gradients are not read yet)",
                                          keyword, m.sources.describe(t.loc), m.mesh.nodes.labels[static_cast<std::size_t>(n)]));
        return;
      }
  };
  for (const auto& t : m.initial_temperatures) check(t, "*INITIAL CONDITIONS");
  for (const auto& step : m.steps)
    for (const auto& b : step.temperatures)
      for (const auto& t : b.entries) check(t, "*TEMPERATURE");
}

}  // namespace

AnalysisModel build_analysis_model(const model::Model& m) {
  AnalysisModel am;
  am.model = &m;
  const auto& el = m.mesh.elements;
  am.elements.resize(el.size());
  if (el.size() == 0) throw AnalysisError("the model has no elements");

  // One kind of model at a time: the DOFs per node and the axisymmetric ring integration
  // apply to the whole model. Springs take the dimension of the rest (3 in a model of springs).
  // Rigid elements take the model's kind too, as long as their dimension is its.
  const auto& first = model::element_type(el.type[model::kind_element(el)]);
  am.dim = model::model_dimension(el);
  am.axisymmetric = model::is_axisymmetric(first);
  for (std::size_t e = 0; e < el.size(); ++e) {
    const auto& t = model::element_type(el.type[e]);
    am.elements[e].type = &t;
    am.elements[e].rigid = model::is_rigid(t);
    if (t.family == model::ElementFamily::Spring) continue;
    if (t.dim != am.dim || (!model::is_rigid(t) && model::is_axisymmetric(t) != am.axisymmetric))
      throw AnalysisError(fmt::format("{}: error: *ELEMENT: element {} ({}) cannot be combined with {} elements in one model",
                                      m.sources.describe(el.loc[e]), el.labels[e], t.name, first.name));
  }

  for (const model::RigidBody& body : m.rigid_bodies)
    for (std::int32_t e : body.elements) am.elements[static_cast<std::size_t>(e)].rigid = true;

  // Smoothing data the mesh contradicts (a surface node on the axis or at the centre) is a
  // deck error, reported before what this version does not analyse yet.
  try {
    contact::validate_corrections(m);
  } catch (const contact::CorrectionError& e) {
    throw AnalysisError(fmt::format("{}: error: {}: {}", m.sources.describe(e.loc), e.keyword, e.what()));
  }

  // Contact: the pairs and general contact (contact/interaction_table.hpp); what is not
  // analysed yet (LAGRANGE friction, TIED, self-contact, ...) stops here with the deck line,
  // rather than run as if the bodies could pass through each other or stick where they should not.
  am.contact = contact::interaction_table(m);
  check_contact_supported(m, *am.contact);
  try {
    am.interactions = contact::resolve_all_steps(m, *am.contact);
  } catch (const contact::InteractionError& e) {
    throw AnalysisError(fmt::format("{}: error: {}: {}", m.sources.describe(e.loc), e.keyword, e.what()));
  }

  check_analytical_surfaces(am);

  try {
    am.ties = contact::resolve_ties(m);
  } catch (const contact::TieError& e) {
    throw AnalysisError(fmt::format("{}: error: *TIE: {}", m.sources.describe(e.loc), e.what()));
  }
  for (auto& w : contact::tie_warnings(m, am.ties)) am.warnings.push_back(std::move(w));

  set_transforms(m, am);
  am.initial_temperature.assign(m.mesh.nodes.size(), 0.0);
  for (const auto& t : m.initial_temperatures)
    for (std::int32_t n : t.nodes) am.initial_temperature[static_cast<std::size_t>(n)] = t.value;
  if (std::any_of(m.initial_temperatures.begin(), m.initial_temperatures.end(), [](const auto& t) { return t.gradient; })) {
    am.initial_temperature_gradient.assign(m.mesh.nodes.size(), 0.0);
    for (const auto& t : m.initial_temperatures)  // a later line without it: 0, as in a step
      for (std::int32_t n : t.nodes) am.initial_temperature_gradient[static_cast<std::size_t>(n)] = t.gradient.value_or(0.0);
  }
  warn_gradients_off_shells(m, am);
  am.rotation_node_of.assign(m.mesh.nodes.size(), -1);
  for (const model::RotatingNode& r : model::rotating_nodes(m, am.dim))
    am.rotation_node_of[static_cast<std::size_t>(r.ref_node)] = r.rot_node;
  assign_materials(m, am);
  setup_line_elements(m, am);
  setup_shell_elements(m, am);
  check_element_changes(am);
  check_initial_plastic_strains(m, am);
  warn_about_locking(am);
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& x : m.mesh.nodes.coords)
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], x[c]), hi[c] = std::max(hi[c], x[c]);
  for (int c = 0; c < 3; ++c) am.size += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  am.size = std::sqrt(am.size);
  return am;
}

}  // namespace inpact::solver
