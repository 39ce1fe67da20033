#pragma once
/// The material law of *HYPERELASTIC (model::Hyperelastic → elements::Hyperelastic), and what
/// an incompressible definition (every D = 0) becomes:
///  - in hybrid elements: a bulk modulus K0 = 10⁴ μ0 (D1 = 2/K0; the pressure is condensed in
///    the element, which needs a finite one; Abaqus keeps the pressure as an unknown instead and
///    is exactly incompressible: the difference is a volume change of order 1e-4);
///  - in other elements: Abaqus stops (they would lock); inpact does as CalculiX, D1 = 0.1/μ0
///    (Poisson's ratio 0.475), so CalculiX's decks run, with a warning that says so.
#include <memory>
#include <string>
#include <vector>

#include "elements/material.hpp"
#include "model/model.hpp"

namespace inpact::solver {

/// K0/μ0 of an incompressible material in hybrid elements.
inline constexpr double kHybridIncompressibleBulkRatio = 1e4;

std::shared_ptr<elements::Material> hyperelastic_law(const model::Model& m, const model::Material& mat,
                                                     model::ElementFamily family, bool hybrid,
                                                     std::vector<std::string>& warnings);

}  // namespace inpact::solver
