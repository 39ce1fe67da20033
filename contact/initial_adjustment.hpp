#pragma once
/// ADJUST on *CONTACT PAIR: slave nodes moved onto the master surface before the analysis,
/// strain-free (a change of the reference geometry, as Abaqus's preprocessor makes it):
///   ADJUST=a     every slave node whose gap is ≤ a (overclosed ones included) [IG];
///   ADJUST=nset  the slave nodes of the node set, whatever their gap.
/// A node moves to its closest point on the master (node-to-surface projection on the reference
/// coordinates, contact/projection.hpp), so its initial gap becomes zero for either
/// discretisation. A node that several pairs adjust moves once, by the first pair in deck
/// order. Only model-data pairs adjust (Abaqus adjusts step pairs at the step's start: the
/// analysis refuses those).
#include <cstdint>
#include <string>
#include <vector>

#include "contact/facet.hpp"
#include "model/model.hpp"

namespace inpact::contact {

struct AdjustedNode {
  std::int32_t row = -1;
  Vec3 to{};          ///< the new reference coordinates
  double moved = 0.0;  ///< the distance moved (the absolute initial gap)
};

/// The moves ADJUST asks for, with one note per adjusting pair (how many nodes, the largest move).
std::vector<AdjustedNode> adjusted_nodes(const model::Model& model, std::vector<std::string>& notes);

/// Moves the tied slave nodes of every *TIE with ADJUST=YES onto their master points (recorded in
/// model::Tie::n_adjusted, largest_adjustment; contact/tie.hpp), then
/// the nodes of adjusted_nodes() in `model` and marks it adjusted (model.adjusted): what
/// `inpact check` and `inpact run` do after reading a deck, before the analysis. Returns the notes.
std::vector<std::string> apply_adjust(model::Model& model);

}  // namespace inpact::contact
