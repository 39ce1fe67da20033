#include "shell_element_setup.hpp"

#include <algorithm>
#include <memory>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "model/mesh_queries.hpp"
#include "elastic_law.hpp"
#include "elements/shell_section.hpp"
#include "model/elastic_stiffness.hpp"
#include "plastic_law.hpp"
#include "shell_normals.hpp"

namespace inpact::solver {

namespace {

const char* keyword_of(const model::ShellSection& sec) {
  return sec.general ? "*SHELL GENERAL SECTION" : "*SHELL SECTION";
}

/// The elastic lamina of `material` (isotropic, engineering constants, orthotropic or lamina),
/// or a deck error naming what is missing.
elements::ShellLamina material_lamina(const model::Model& m, const model::ShellSection& sec,
                                      const std::string& material, model::SourceLoc loc) {
  const model::Material& mat = m.materials.at(material);
  // Temperature tables go through the section points' law (point_law); a general section and a
  // directional lamina are integrated from constants.
  if (sec.general || (mat.elastic && mat.elastic->type != model::Elastic::Type::Isotropic))
    refuse_temperature_tables(m, mat, "a general or directional shell section");
  const bool linear = mat.elastic && !mat.hyperelastic;
  if (!linear || mat.elastic->type == model::Elastic::Type::Anisotropic)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' is not {}; shells take *ELASTIC, TYPE=ISOTROPIC, "
                                    "ENGINEERING CONSTANTS, ORTHOTROPIC or LAMINA so far", m.sources.describe(loc),
                                    keyword_of(sec), mat.name, linear ? "orthotropic" : "linear elastic"));
  const double alpha = mat.expansion ? mat.expansion->alpha : 0.0;
  if (mat.elastic->type == model::Elastic::Type::Isotropic)
    return elements::isotropic_lamina(mat.elastic->youngs_modulus, mat.elastic->poissons_ratio, alpha);
  return elements::condensed_lamina(model::material_stiffness(*mat.elastic),
                                    mat.elastic->type == model::Elastic::Type::Lamina, alpha);
}

std::optional<elements::MaterialOrientation> orientation_named(const model::Model& m, const std::string& name) {
  if (name.empty()) return std::nullopt;
  return elements::MaterialOrientation(m.orientations.at(name));
}

/// The section's layers: its material through the thickness, or COMPOSITE's layers, each in its
/// own orientation (a name) or at its angle from the section's.
elements::ShellProperties shell_section_properties(const model::Model& m, const model::ShellSection& sec) {
  std::vector<elements::ShellLayerProperties> layers;
  if (sec.layers.empty()) {
    elements::ShellLayerProperties& layer = layers.emplace_back();
    layer.lamina = material_lamina(m, sec, sec.material, sec.loc);
    layer.orientation = orientation_named(m, sec.orientation);
  }
  for (const model::ShellLayer& given : sec.layers) {
    elements::ShellLayerProperties& layer = layers.emplace_back();
    layer.lamina = material_lamina(m, sec, given.material, given.loc);
    layer.orientation = orientation_named(m, given.orientation.empty() ? sec.orientation : given.orientation);
    layer.angle = given.angle * std::numbers::pi / 180;
  }
  elements::ShellProperties properties = elements::shell_properties(sec, std::move(layers));
  properties.orientation = orientation_named(m, sec.orientation);
  return properties;
}

/// The section's mass per volume: its layers' densities averaged over their thicknesses.
double section_density(const model::Model& m, const model::ShellSection& sec) {
  if (sec.layers.empty()) return m.materials.at(sec.material).density.value_or(0.0);
  double sum = 0.0;
  for (const model::ShellLayer& layer : sec.layers)
    sum += layer.thickness * m.materials.at(layer.material).density.value_or(0.0);
  return sum / sec.thickness;
}

/// The law at the section points of `mat` where they need one, null for an elastic lamina of
/// constants. *PLASTIC: Mises in plane stress (σ33 = 0 at each point) with any hardening *PLASTIC
/// takes (plastic_law.hpp), at small strain; under NLGEOM the law sees the corotated strains
/// (corotation.hpp), so the strains stay small while the shell turns. Temperature tables of an
/// isotropic *ELASTIC or *EXPANSION: the plane stress elastic law at each point's temperature.
/// The transverse shear stays elastic, as in Abaqus's shells. `oriented`: the material's axes
/// are turned (an ORIENTATION or a layer's angle), which a plastic law does not take so far.
std::shared_ptr<const elements::Material> point_law(const model::Model& m, const model::ShellSection& sec,
                                                    const model::Material& mat, model::SourceLoc loc, bool oriented,
                                                    std::vector<std::string>& warnings) {
  const bool tables = (mat.elastic && mat.elastic->temperature_dependent()) ||
                      (mat.expansion && mat.expansion->temperature_dependent());
  if (!mat.plastic && !tables) return nullptr;
  elements::ElasticConstants c;
  c.youngs_modulus = mat.elastic->youngs_modulus;
  c.poissons_ratio = mat.elastic->poissons_ratio;
  c.expansion = mat.expansion ? mat.expansion->alpha : 0.0;
  if (!mat.plastic)  // (a general section's tables are refused with its lamina)
    return sec.general ? nullptr : isotropic_elastic_law(&mat, model::ElementFamily::PlaneStress, c);
  refuse_temperature_tables(m, mat, "*PLASTIC");
  if (oriented || mat.elastic->type != model::Elastic::Type::Isotropic)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; a plastic shell or layer takes "
                                    "isotropic elasticity and no ORIENTATION or angle so far", m.sources.describe(loc),
                                    keyword_of(sec), mat.name));
  if (sec.general)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; a general shell section is "
                                    "integrated once, elastically (use *SHELL SECTION for a plastic shell)",
                                    m.sources.describe(loc), keyword_of(sec), mat.name));
  return plastic_law(m, mat, model::ElementFamily::PlaneStress, c, false, warnings);
}

/// The laws of a COMPOSITE's layers into `properties` (layer_laws when any layer has one), and
/// the element's law: the one keeping the most state per point, which sizes and starts every
/// point's history (a layer's law reads the first state_size() values of it). The plastic layers
/// of one section keep the same layout of state (one form of hardening), so that the element's
/// law starts each of them as its own law would.
std::shared_ptr<const elements::Material> layer_laws(const model::Model& m, const model::ShellSection& sec,
                                                     elements::ShellProperties& properties, AnalysisModel& am) {
  std::shared_ptr<const elements::Material> element_law;
  std::string plastic_material;  // the first layer's with state
  for (std::size_t k = 0; k < sec.layers.size(); ++k) {
    const model::ShellLayer& layer = sec.layers[k];
    const bool oriented = !sec.orientation.empty() || !layer.orientation.empty() || layer.angle != 0.0;
    auto law = point_law(m, sec, m.materials.at(layer.material), layer.loc, oriented, am.warnings);
    if (!law) continue;
    if (element_law && law->state_size() > 0 && element_law->state_size() > 0 &&
        law->state_size() != element_law->state_size())
      throw AnalysisError(fmt::format("{}: error: {}: the plastic layers of a COMPOSITE section keep one layout of "
                                      "state so far; material '{}' keeps {} values a point where material '{}' of an "
                                      "earlier layer keeps {} (expected the same form of hardening)",
                                      m.sources.describe(layer.loc), keyword_of(sec), layer.material,
                                      law->state_size(), plastic_material, element_law->state_size()));
    properties.layer_laws = true;
    properties.layer_temperatures = properties.layer_temperatures || law->temperature_dependent();
    properties.layers[k].law = law.get();
    if (law->state_size() > 0 && plastic_material.empty()) plastic_material = layer.material;
    if (!element_law || law->state_size() > element_law->state_size()) element_law = law;
    am.materials.push_back(std::move(law));
  }
  return element_law;
}

/// The law of the section's points (null: elastic constants throughout).
std::shared_ptr<const elements::Material> section_law(const model::Model& m, const model::ShellSection& sec,
                                                      elements::ShellProperties& properties, AnalysisModel& am) {
  if (!sec.layers.empty()) return layer_laws(m, sec, properties, am);
  auto law = point_law(m, sec, m.materials.at(sec.material), sec.loc, !sec.orientation.empty(), am.warnings);
  if (law) am.materials.push_back(law);
  return law;
}

}  // namespace

void setup_shell_elements(const model::Model& m, AnalysisModel& am) {
  for (const model::ShellSection& sec : m.mesh.shell_sections) {
    auto properties = std::make_shared<elements::ShellProperties>(shell_section_properties(m, sec));
    const std::shared_ptr<const elements::Material> law = section_law(m, sec, *properties, am);
    const elements::ShellProperties* p = am.shells.emplace_back(std::move(properties)).get();
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
      const auto e = static_cast<std::size_t>(row);
      ElementSetup& s = am.elements[e];
      s.section.shell = p;
      if (law) s.material = law.get();
      s.section.thickness = model::shell_thickness(m.mesh, sec, e);
      if (sec.nodal_thickness) {
        const auto nodes = m.mesh.elements.nodes_of(e);
        std::array<double, 8>& at_nodes = am.shell_nodal_thickness.emplace_back();
        for (std::size_t a = 0; a < nodes.size(); ++a) at_nodes[a] = m.mesh.nodal_thickness.at(nodes[a]);
        s.section.nodal_thickness = std::span<const double>(at_nodes.data(), nodes.size());
      }
      s.density = section_density(m, sec);
    }
  }
  average_shell_normals(m, am);
}

}  // namespace inpact::solver
