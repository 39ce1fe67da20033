#include "plastic_law.hpp"

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "combined_hardening_setup.hpp"
#include "elements/combined_plasticity.hpp"
#include "elements/finite_strain_mises.hpp"
#include "elements/log_strain_plasticity.hpp"
#include "elements/mises_plasticity.hpp"
#include "elements/plane_stress_condensation.hpp"

namespace inpact::solver {

namespace {

/// HARDENING=COMBINED, and KINEMATIC with several temperatures: the Chaboche law
/// (combined_plasticity.hpp) at each temperature of the data, 3D.
std::shared_ptr<elements::Material> combined_law(const model::Model& m, const model::Material& mat,
                                                 const elements::ElasticConstants& c, std::vector<std::string>& warnings) {
  CombinedLawData data = combined_law_data(m, mat);
  warnings.insert(warnings.end(), data.notes.begin(), data.notes.end());
  return std::make_shared<elements::CombinedPlasticity>(c, std::move(data.sets), std::move(data.temperatures));
}

}  // namespace

std::shared_ptr<elements::Material> plastic_law(const model::Model& m, const model::Material& mat,
                                                model::ElementFamily family, const elements::ElasticConstants& c,
                                                bool finite_strain, std::vector<std::string>& warnings) {
  const model::Plastic& p = *mat.plastic;
  if (mat.cyclic_hardening && p.hardening != model::Plastic::Hardening::Combined)
    throw AnalysisError(fmt::format("{}: error: *CYCLIC HARDENING: it needs *PLASTIC, HARDENING=COMBINED (material '{}')",
                                    m.sources.describe(mat.cyclic_hardening->loc), mat.name));
  const bool combined = p.hardening == model::Plastic::Hardening::Combined ||
                        (p.hardening == model::Plastic::Hardening::Kinematic && p.several_temperatures());
  elements::MisesHardening h;
  if (!combined) {
    h = elements::isotropic_hardening(p.table);
    h.kinematic = p.hardening == model::Plastic::Hardening::Kinematic;
  }
  std::shared_ptr<elements::Material> law;
  if (!finite_strain && !combined) return std::make_shared<elements::MisesPlasticity>(c, std::move(h), family);
  if (!finite_strain) law = combined_law(m, mat, c, warnings);
  else if (combined) law = std::make_shared<elements::LogStrainPlasticity>(combined_law(m, mat, c, warnings));
  else if (h.kinematic)
    law = std::make_shared<elements::LogStrainPlasticity>(std::make_shared<elements::MisesPlasticity>(c, std::move(h)));
  else law = std::make_shared<elements::FiniteStrainMises>(c, std::move(h));
  if (family == model::ElementFamily::PlaneStress) return std::make_shared<elements::PlaneStressCondensation>(law);
  return law;
}

}  // namespace inpact::solver
