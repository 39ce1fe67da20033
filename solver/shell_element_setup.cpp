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
  // Temperature tables go through the section points' law (shell_point_law); a layer, a general
  // section and a directional lamina are integrated from constants.
  if (!sec.layers.empty() || sec.general || (mat.elastic && mat.elastic->type != model::Elastic::Type::Isotropic))
    refuse_temperature_tables(m, mat, "a COMPOSITE, general or directional shell section");
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

/// The law at the section points of a shell whose points need one, null for an elastic lamina
/// of constants. *PLASTIC: Mises in plane stress (σ33 = 0 at each point) with any hardening
/// *PLASTIC takes (plastic_law.hpp), at small strain; under NLGEOM the law sees the corotated
/// strains (corotation.hpp), so the strains stay small while the shell turns. Temperature tables
/// of an isotropic *ELASTIC or *EXPANSION: the plane stress elastic law at each point's
/// temperature. The transverse shear stays elastic, as in Abaqus's shells.
std::shared_ptr<const elements::Material> shell_point_law(const model::Model& m, const model::ShellSection& sec,
                                                          std::vector<std::string>& warnings) {
  for (const model::ShellLayer& layer : sec.layers)
    if (m.materials.at(layer.material).plastic)
      throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; the layers of a COMPOSITE section "
                                      "are elastic so far", m.sources.describe(layer.loc), keyword_of(sec),
                                      layer.material));
  if (!sec.layers.empty()) return nullptr;
  const model::Material& mat = m.materials.at(sec.material);
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
  if (!sec.orientation.empty() || mat.elastic->type != model::Elastic::Type::Isotropic)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; a plastic shell takes isotropic "
                                    "elasticity and no ORIENTATION so far", m.sources.describe(sec.loc),
                                    keyword_of(sec), mat.name));
  if (sec.general)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; a general shell section is "
                                    "integrated once, elastically (use *SHELL SECTION for a plastic shell)",
                                    m.sources.describe(sec.loc), keyword_of(sec), mat.name));
  return plastic_law(m, mat, model::ElementFamily::PlaneStress, c, false, warnings);
}

}  // namespace

void setup_shell_elements(const model::Model& m, AnalysisModel& am) {
  for (const model::ShellSection& sec : m.mesh.shell_sections) {
    const elements::ShellProperties* p =
        am.shells.emplace_back(std::make_shared<elements::ShellProperties>(shell_section_properties(m, sec))).get();
    const std::shared_ptr<const elements::Material> law = shell_point_law(m, sec, am.warnings);
    if (law) am.materials.push_back(law);
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
