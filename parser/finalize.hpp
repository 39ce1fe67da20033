#pragma once
/// After the last line: resolve what could refer forward (element nodes, materials,
/// interactions, surfaces), check the deck is complete, and hand the mesh to the model.
#include "build_state.hpp"
#include "diagnostics.hpp"

namespace inpact::parser {

/// Resolves element node labels that were not yet defined when the element was read.
void resolve_pending_nodes(MeshBuild& build, Diagnostics& diags);

void finalize_model(BuildState& state, Diagnostics& diags);

}  // namespace inpact::parser
