#pragma once
/// General contact's exterior (ALL EXTERIOR, or an inclusion's empty field) is made of the faces
/// that occur once in the mesh (contact/interaction_table.cpp). The two faces of a shell or of a
/// rigid element (R3D3, R3D4, R2D2, RAX2) share their nodes, so such elements are never in it: a
/// rigid punch would pass through the block, and a plate fall through its support, without a word.
#include "model/model.hpp"

namespace inpact::solver {

/// Throws AnalysisError at the exterior inclusion's line when the model has a body of shell or
/// rigid elements (elements connected through their nodes) with no face on a *CONTACT PAIR's
/// surface or on a named general-contact inclusion surface: where a pair or an inclusion names
/// such faces, the deck has said where their contact is.
void check_two_sided_bodies_in_exterior(const model::Model& model);

}  // namespace inpact::solver
