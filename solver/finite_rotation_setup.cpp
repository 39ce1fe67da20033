#include "finite_rotation_setup.hpp"

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/corotation.hpp"

namespace inpact::solver {

void refuse_finite_rotations(const model::Model& m, const model::ElementTypeInfo& type, std::string_view keyword,
                             const model::SourceLoc& section_loc, std::int64_t label) {
  if (elements::takes_finite_rotations(type)) return;
  if (const model::Step* step = model::first_nlgeom_step(m.steps))
    throw AnalysisError(fmt::format("{}: error: {}: {} element {} under NLGEOM (step '{}') is not supported yet; "
                                    "finite rotations take B31, B32, B32R, B33, S3, S3R, S4 and S4R",
                                    m.sources.describe(section_loc), keyword, type.name, label, step->name));
}

}  // namespace inpact::solver
