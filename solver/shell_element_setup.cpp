#include "shell_element_setup.hpp"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "model/mesh_queries.hpp"
#include "elastic_law.hpp"
#include "elements/mises_plasticity.hpp"
#include "elements/shell_section.hpp"
#include "shell_normals.hpp"

namespace inpact::solver {

namespace {

const char* keyword_of(const model::ShellSection& sec) {
  return sec.general ? "*SHELL GENERAL SECTION" : "*SHELL SECTION";
}

/// E, ν and α of the section's material: isotropic elastic (with *PLASTIC or not), or a deck
/// error naming what is missing.
elements::ShellProperties shell_section_properties(const model::Model& m, const model::ShellSection& sec) {
  const auto where = [&] { return m.sources.describe(sec.loc); };
  const model::Material& mat = m.materials.at(sec.material);
  refuse_temperature_tables(m, mat, "shell elements");
  if (!mat.elastic || mat.elastic->type != model::Elastic::Type::Isotropic || mat.hyperelastic)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' is not isotropic elastic; shells take *ELASTIC, "
                                    "TYPE=ISOTROPIC (with or without *PLASTIC) only so far", where(), keyword_of(sec),
                                    mat.name));
  return elements::shell_properties(sec, mat.elastic->youngs_modulus, mat.elastic->poissons_ratio,
                                    mat.expansion ? mat.expansion->alpha : 0.0);
}

/// The law at the section points of a shell whose material has *PLASTIC: Mises in plane stress
/// (σ33 = 0 at each point), isotropic or linear kinematic hardening at one temperature, small
/// strain; the transverse shear stays elastic, as in Abaqus's shells. Under NLGEOM the law sees
/// the corotated strains (corotation.hpp), so the strains stay small while the shell turns. Null
/// without *PLASTIC.
std::shared_ptr<const elements::Material> shell_plastic_law(const model::Model& m, const model::ShellSection& sec) {
  const model::Material& mat = m.materials.at(sec.material);
  if (!mat.plastic) return nullptr;
  const model::Plastic& p = *mat.plastic;
  if (sec.general)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC; a general shell section is "
                                    "integrated once, elastically (use *SHELL SECTION for a plastic shell)",
                                    m.sources.describe(sec.loc), keyword_of(sec), mat.name));
  if (p.hardening == model::Plastic::Hardening::Combined || mat.cyclic_hardening || p.several_temperatures())
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' has *PLASTIC with combined hardening or several "
                                    "temperatures; shells take isotropic or kinematic hardening at one temperature so "
                                    "far", m.sources.describe(sec.loc), keyword_of(sec), mat.name));
  elements::ElasticConstants c;
  c.youngs_modulus = mat.elastic->youngs_modulus;
  c.poissons_ratio = mat.elastic->poissons_ratio;
  c.expansion = mat.expansion ? mat.expansion->alpha : 0.0;
  elements::MisesHardening h = elements::isotropic_hardening(p.table);
  h.kinematic = p.hardening == model::Plastic::Hardening::Kinematic;
  return std::make_shared<elements::MisesPlasticity>(c, std::move(h), model::ElementFamily::PlaneStress);
}

}  // namespace

void setup_shell_elements(const model::Model& m, AnalysisModel& am) {
  for (const model::ShellSection& sec : m.mesh.shell_sections) {
    const elements::ShellProperties* p =
        am.shells.emplace_back(std::make_shared<elements::ShellProperties>(shell_section_properties(m, sec))).get();
    const std::shared_ptr<const elements::Material> plastic = shell_plastic_law(m, sec);
    if (plastic) am.materials.push_back(plastic);
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
      const auto e = static_cast<std::size_t>(row);
      ElementSetup& s = am.elements[e];
      s.section.shell = p;
      if (plastic) s.material = plastic.get();
      s.section.thickness = model::shell_thickness(m.mesh, sec, e);
      if (sec.nodal_thickness) {
        const auto nodes = m.mesh.elements.nodes_of(e);
        std::array<double, 8>& at_nodes = am.shell_nodal_thickness.emplace_back();
        for (std::size_t a = 0; a < nodes.size(); ++a) at_nodes[a] = m.mesh.nodal_thickness.at(nodes[a]);
        s.section.nodal_thickness = std::span<const double>(at_nodes.data(), nodes.size());
      }
      s.density = m.materials.at(sec.material).density.value_or(0.0);
    }
  }
  average_shell_normals(m, am);
}

}  // namespace inpact::solver
