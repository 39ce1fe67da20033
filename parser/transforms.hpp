#pragma once
/// *TRANSFORM resolved on the complete deck (transforms.cpp).
#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

/// Gives every node of a *TRANSFORM that a *BOUNDARY, *CLOAD (DOFs 1–3) or *EQUATION refers to
/// a local node (but one that boundary conditions hold at zero in all three directions) (Model::transformed_nodes; the others need none: their global DOFs are what
/// the analysis solves for, and only their printed output is turned). Errors: a node in two
/// transforms; among the nodes referred to, a reference node (its rotations are not transformed),
/// one on a cylindrical system's axis, a degenerate system. (A node on the axis that nothing
/// refers to is printed in global axes.)
void finalize_transforms(model::Model& m, Diagnostics& diags);

}  // namespace inpact::parser
