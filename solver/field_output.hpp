#pragma once
/// The fields of a results frame: only what the step's output requests ask for is computed
/// ("only the requested output is computed"); without any request, U, RF and S every increment.
#include <set>
#include <string>
#include <vector>

#include "analysis_model.hpp"
#include "results_frame.hpp"

namespace inpact::solver {

struct OutputSelection {
  std::set<std::string> fields;  ///< keys to write: U, RF, S, E, ...
  int frequency = 1;             ///< every n-th increment (the step's last is always written)
  std::vector<std::string> not_computed;  ///< requested identifiers inpact does not compute yet
};

/// The results-file selection in force for step `step_index`: the field requests of that step,
/// or of the last step before it that had any (Abaqus carries requests over).
OutputSelection select_output(const model::Model& model, std::size_t step_index);

/// The nodal and integration-point fields at displacement u with reactions `rf` (full DOF
/// vectors); `delta_t` as for the assembly.
std::vector<FieldData> compute_fields(const AnalysisModel& am, const OutputSelection& selection,
                                        std::span<const double> u, std::span<const double> rf, bool nlgeom,
                                        std::span<const double> delta_t);

}  // namespace inpact::solver
