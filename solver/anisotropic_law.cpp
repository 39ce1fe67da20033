#include "anisotropic_law.hpp"

#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/anisotropic_elastic.hpp"
#include "model/elastic_stiffness.hpp"

namespace inpact::solver {

std::shared_ptr<elements::Material> anisotropic_law(const model::Model& m, const model::SolidSection& section,
                                                    const model::Material& mat, model::ElementFamily family) {
  const model::Elastic& el = *mat.elastic;
  const bool lamina = el.type == model::Elastic::Type::Lamina;
  if (mat.plastic)
    throw AnalysisError(fmt::format("{}: error: *PLASTIC: Mises plasticity needs isotropic elasticity (material '{}' "
                                    "has a directional *ELASTIC)", m.sources.describe(mat.plastic->loc), mat.name));
  if (lamina && family != model::ElementFamily::PlaneStress)
    throw AnalysisError(fmt::format("{}: error: *ELASTIC: TYPE=LAMINA is for plane-stress elements only (material '{}', "
                                    "*SOLID SECTION, ELSET={})", m.sources.describe(el.loc), mat.name, section.elset));
  const model::Stiffness d = model::material_stiffness(el);
  const elements::Mat6 d_material = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(d.data());
  std::optional<elements::MaterialOrientation> orientation;
  if (!section.orientation.empty()) orientation.emplace(m.orientations.at(section.orientation));
  const double alpha = mat.expansion ? mat.expansion->alpha : 0.0;
  try {
    return std::make_shared<elements::AnisotropicElastic>(family, d_material, alpha, std::move(orientation), lamina);
  } catch (const std::invalid_argument& e) {
    throw AnalysisError(fmt::format("{}: error: *SOLID SECTION: {} (material '{}')", m.sources.describe(section.loc),
                                    e.what(), mat.name));
  }
}

}  // namespace inpact::solver
