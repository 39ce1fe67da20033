#include "hyperelastic_material.hpp"

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/hyperelastic.hpp"

namespace inpact::solver {

namespace {

using Form = model::Hyperelastic::Form;

/// The energy of the definition with the D's given.
std::shared_ptr<const elements::StrainEnergy> energy(const model::Hyperelastic& h, const std::vector<double>& d) {
  using elements::InvariantEnergy;
  const std::vector<double>& c = h.coefficients;
  switch (h.form) {
    case Form::Polynomial: return std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial(c, h.order, d));
    case Form::ReducedPolynomial: return std::make_shared<InvariantEnergy>(InvariantEnergy::reduced_polynomial(c, d));
    case Form::ArrudaBoyce: return std::make_shared<InvariantEnergy>(InvariantEnergy::arruda_boyce(c[0], c[1], d[0]));
    case Form::Ogden: {
      std::vector<double> mu, alpha;
      for (std::size_t p = 0; p + 1 < c.size(); p += 2) mu.push_back(c[p]), alpha.push_back(c[p + 1]);
      return std::make_shared<elements::OgdenEnergy>(mu, alpha, d);
    }
  }
  return nullptr;
}

}  // namespace

std::shared_ptr<elements::Material> hyperelastic_law(const model::Model& m, const model::Material& mat,
                                                     model::ElementFamily family, bool hybrid,
                                                     std::vector<std::string>& warnings) {
  const model::Hyperelastic& h = *mat.hyperelastic;
  const auto where = [&] { return m.sources.describe(h.loc); };
  std::vector<double> d = h.d;
  const double mu0 = energy(h, d)->initial_shear_modulus();
  if (!(mu0 > 0))
    throw AnalysisError(fmt::format("{}: error: *HYPERELASTIC: the initial shear modulus of material '{}' ({}) is "
                                    "{:g}; it must be positive", where(), mat.name, h.name, mu0));
  if (h.incompressible()) {
    d.assign(d.size(), 0.0);
    if (hybrid) {
      d[0] = 2 / (kHybridIncompressibleBulkRatio * mu0);
      warnings.push_back(fmt::format("material '{}' ({}) is incompressible (D = 0): its hybrid elements condense the "
                                     "pressure with the bulk modulus K0 = {:g} μ0 (D1 = {:.4g}; volume changes of "
                                     "order 1e-4 of the strain, where Abaqus has none)", mat.name, h.name,
                                     kHybridIncompressibleBulkRatio, d[0]));
    } else {
      d[0] = 0.1 / mu0;
      warnings.push_back(fmt::format("material '{}' ({}) is incompressible (D = 0), which needs hybrid elements; "
                                     "in the other elements it gets D1 = {:.4g} (Poisson's ratio 0.475), as CalculiX "
                                     "does", mat.name, h.name, d[0]));
    }
  }
  return std::make_shared<elements::Hyperelastic>(energy(h, d), family == model::ElementFamily::PlaneStress);
}

}  // namespace inpact::solver
