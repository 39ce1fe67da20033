#pragma once
/// Trusses and springs resolved for the analysis: each truss's cross-section area, each spring's
/// *SPRING behaviour, and the deck errors the mesh shows only now (a zero-length truss or
/// SPRINGA, a spring DOF beyond the model's, plasticity in a truss).
#include "analysis_model.hpp"

namespace inpact::solver {

/// Fills ElementSetup::section.area / .spring of the line elements (after the materials are
/// assigned); throws AnalysisError citing the deck.
void setup_line_elements(const model::Model& m, AnalysisModel& am);

}  // namespace inpact::solver
