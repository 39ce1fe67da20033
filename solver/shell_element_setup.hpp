#pragma once
/// Shells resolved for the analysis: each section's properties (shell_section.hpp) from its
/// material, each element's thickness (the section's, or with *NODAL THICKNESS its nodes' and
/// their mean), and the deck errors the model shows only now: materials shells do not take yet,
/// a degenerate shell element.
#include "analysis_model.hpp"

namespace inpact::solver {

/// Fills ElementSetup::section.shell / .thickness and the density of the shell elements (after
/// the materials are assigned); throws AnalysisError citing the deck.
void setup_shell_elements(const model::Model& m, AnalysisModel& am);

}  // namespace inpact::solver
