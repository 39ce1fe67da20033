#include "shell_element_setup.hpp"

#include <memory>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "model/mesh_queries.hpp"
#include "elastic_law.hpp"
#include "finite_rotation_setup.hpp"
#include "elements/shell_section.hpp"

namespace inpact::solver {

namespace {

const char* keyword_of(const model::ShellSection& sec) {
  return sec.general ? "*SHELL GENERAL SECTION" : "*SHELL SECTION";
}

/// E, ν and α of the section's material: isotropic linear elastic only so far (small strain,
/// small rotations), or a deck error naming what is missing.
elements::ShellProperties shell_section_properties(const model::Model& m, const model::ShellSection& sec) {
  const auto where = [&] { return m.sources.describe(sec.loc); };
  const model::Material& mat = m.materials.at(sec.material);
  refuse_temperature_tables(m, mat, "shell elements");
  if (!mat.elastic || mat.elastic->type != model::Elastic::Type::Isotropic || mat.plastic || mat.hyperelastic)
    throw AnalysisError(fmt::format("{}: error: {}: material '{}' is not isotropic linear elastic; shells take "
                                    "*ELASTIC, TYPE=ISOTROPIC only so far", where(), keyword_of(sec), mat.name));
  return elements::shell_properties(sec, mat.elastic->youngs_modulus, mat.elastic->poissons_ratio,
                                    mat.expansion ? mat.expansion->alpha : 0.0);
}

}  // namespace

void setup_shell_elements(const model::Model& m, AnalysisModel& am) {
  for (const model::ShellSection& sec : m.mesh.shell_sections) {
    const elements::ShellProperties* p =
        am.shells.emplace_back(std::make_shared<elements::ShellProperties>(shell_section_properties(m, sec))).get();
    for (std::int32_t row : m.mesh.elsets.at(sec.elset).rows) {
      const auto e = static_cast<std::size_t>(row);
      ElementSetup& s = am.elements[e];
      refuse_finite_rotations(m, *s.type, keyword_of(sec), sec.loc, m.mesh.elements.labels[e]);
      s.section.shell = p;
      s.section.thickness = model::shell_thickness(m.mesh, sec, e);
      s.density = m.materials.at(sec.material).density.value_or(0.0);
    }
  }
}

}  // namespace inpact::solver
