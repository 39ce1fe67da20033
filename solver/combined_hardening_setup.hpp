#pragma once
/// The Chaboche law's parameters (elements::CombinedPlasticity) from a material's *PLASTIC
/// (HARDENING=COMBINED, or KINEMATIC with several temperatures) and *CYCLIC HARDENING: one set
/// of parameters at each temperature any of the data is given at, so that the law's linear
/// interpolation between the sets is the interpolation of each datum between its own
/// temperatures. Half-cycle data are fitted here (elements::fit_half_cycle), once per
/// temperature block.
#include <string>
#include <vector>

#include "elements/combined_plasticity.hpp"
#include "model/model.hpp"

namespace inpact::solver {

struct CombinedLawData {
  std::vector<elements::CombinedHardening> sets;
  std::vector<double> temperatures;  ///< one per set, increasing
  std::vector<std::string> notes;    ///< what the fit found, for the user (warnings)
};

/// Throws AnalysisError (file:line) where half-cycle data do not harden (C < 0).
CombinedLawData combined_law_data(const model::Model& m, const model::Material& mat);

}  // namespace inpact::solver
