#pragma once
/// The check that stops a beam or shell type under NLGEOM that does not take finite rotations
/// yet (elements/corotation.hpp, takes_finite_rotations), at its section's keyword.
#include <cstdint>
#include <string_view>

#include "model/model.hpp"

namespace inpact::solver {

/// Throws AnalysisError at `section_loc` when a step of `m` has NLGEOM and element `label` of
/// type `type` does not take finite rotations; `keyword` names the section ("*BEAM SECTION").
void refuse_finite_rotations(const model::Model& m, const model::ElementTypeInfo& type, std::string_view keyword,
                             const model::SourceLoc& section_loc, std::int64_t label);

}  // namespace inpact::solver
