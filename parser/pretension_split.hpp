#pragma once
/// *PRE-TENSION SECTION after the deck is read: checks each section against the whole model and
/// cuts the mesh along it (the model's one change of connectivity after reading).
#include "diagnostics.hpp"
#include "model/model.hpp"

namespace inpact::parser {

/// For each pre-tension section: the surface defined and made of element faces (or a shell's
/// edges: the cut then runs across the shell, its copies turning with their originals), the pre-tension
/// node connected to no element, the normal not zero; then its normal (given, or the surface's
/// area-weighted average outward normal), its area, and the split: every section node gets a copy
/// (a new node at the same place, labelled after the instance's largest label) that replaces it
/// in the underlying elements, i.e. the surface's own elements and any other element holding a
/// section node whose centroid lies behind the section (o · (centroid − its section nodes' mean) < 0, o the faces' average outward normal).
void split_pretension_sections(model::Model& m, Diagnostics& diags);

}  // namespace inpact::parser
