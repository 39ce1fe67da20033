#include "elastic_law.hpp"

#include <fmt/format.h>

#include "analysis_error.hpp"

namespace inpact::solver {

std::shared_ptr<elements::Material> isotropic_elastic_law(const model::Material* mat, model::ElementFamily family,
                                                          const elements::ElasticConstants& c) {
  std::optional<elements::ElasticTable> elastic;
  std::optional<elements::ExpansionTable> expansion;
  if (mat && mat->elastic && mat->elastic->temperature_dependent()) elastic = elements::elastic_table(*mat->elastic);
  if (mat && mat->expansion && mat->expansion->temperature_dependent())
    expansion = elements::expansion_table(*mat->expansion);
  if (!elastic && !expansion) return std::make_shared<elements::IsotropicElastic>(family, c);  // today's law, exactly
  return std::make_shared<elements::IsotropicElastic>(family, c, std::move(elastic), std::move(expansion));
}

void refuse_temperature_tables(const model::Model& m, const model::Material& mat, std::string_view with) {
  const bool elastic = mat.elastic && mat.elastic->temperature_dependent();
  const bool expansion = mat.expansion && mat.expansion->temperature_dependent();
  if (!elastic && !expansion) return;
  throw AnalysisError(fmt::format("{}: error: {}: temperature-dependent {} (material '{}') together with {} is not "
                                  "supported yet; continuum elements, shells of one isotropic material and a COMPOSITE's "
                                  "isotropic layers take it",
                                  m.sources.describe(elastic ? mat.elastic->loc : mat.expansion->loc),
                                  elastic ? "*ELASTIC" : "*EXPANSION", elastic ? "elastic constants" : "expansion",
                                  mat.name, with));
}

}  // namespace inpact::solver
