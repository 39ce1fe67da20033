#pragma once
/// The material law of a section whose *ELASTIC is not isotropic (elements/anisotropic_elastic.hpp),
/// with the section's *ORIENTATION.
#include <memory>

#include "elements/material.hpp"
#include "model/model.hpp"

namespace inpact::solver {

/// Throws AnalysisError (with the deck location) for what it cannot analyse: *PLASTIC on a
/// non-isotropic elasticity, TYPE=LAMINA on elements that are not plane stress.
std::shared_ptr<elements::Material> anisotropic_law(const model::Model& m, const model::SolidSection& section,
                                                    const model::Material& material, model::ElementFamily family);

}  // namespace inpact::solver
