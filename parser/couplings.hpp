#pragma once
/// *COUPLING resolved on the complete deck (couplings.cpp; kw_coupling.cpp reads the keywords).
#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

/// Collects each coupling's nodes (its surface's, within the influence radius, without the
/// reference node), checks them (no *KINEMATIC or *DISTRIBUTING, no node left, a reference node
/// on solid or plane elements or shared with another constraint) and adds the rotation node of
/// each coupling that has rotations. The surfaces must already be checked to exist.
void finalize_couplings(model::Model& m, Diagnostics& diags);

}  // namespace inpact::parser
