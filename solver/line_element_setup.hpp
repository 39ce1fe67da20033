#pragma once
/// Trusses, beams and springs resolved for the analysis: each truss's cross-section area, each
/// beam's section properties, each spring's *SPRING behaviour, and the deck errors the mesh
/// shows only now (a zero-length truss, beam or SPRINGA, a spring DOF beyond the model's,
/// plasticity in a truss, a beam's n1 along its axis).
#include "analysis_model.hpp"

namespace inpact::solver {

/// Fills ElementSetup::section.area / .spring of the line elements (after the materials are
/// assigned); throws AnalysisError citing the deck.
void setup_line_elements(const model::Model& m, AnalysisModel& am);

}  // namespace inpact::solver
