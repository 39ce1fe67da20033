#pragma once
/// Elements removed and reactivated by *MODEL CHANGE, TYPE=ELEMENT (model::ElementChange).
///
/// In a step, an inactive element adds no stiffness and no force; a node that no active element
/// (nor a rigid body, coupling or pretension) connects has no unknowns and keeps its displacement.
/// The forces a removed element exerted at the end of the step before ramp to zero over its
/// removal step (ConditionHistory::released_forces). A reactivated element starts from a virgin
/// material state; STRAIN FREE measures its strain from where its nodes are at the step start
/// (ElementReferences), WITH STRAIN from the original configuration. Its stress output is zero
/// while it is inactive.
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "model/model.hpp"

namespace inpact::solver {

struct AnalysisModel;

/// Which elements are active in one step, and what changed at its start.
struct StepElements {
  std::vector<std::uint8_t> active;         ///< per element row; empty: every element is active
  std::vector<std::int32_t> removed;        ///< active in the step before, inactive in this one
  std::vector<std::int32_t> added;          ///< inactive in the step before, active in this one
  std::vector<std::int32_t> strain_free;    ///< those of `added` reactivated STRAIN FREE
  bool is_active(std::size_t e) const { return active.empty() || active[e] != 0; }
};

/// The elements of step `step` (0-based): the *MODEL CHANGE lines of every step up to it, in order.
StepElements step_elements(const model::Model& model, std::size_t step);

/// Throws AnalysisError (with the *MODEL CHANGE line) for what cannot be removed or reactivated
/// yet: rigid elements, elements with rotations (beams, shells), and elements under a contact
/// surface (its facets would have to leave the search).
void check_element_changes(const AnalysisModel& am);

/// Per element reactivated STRAIN FREE: the displacement of each of its node rows at its
/// reactivation, from which its strain is measured until it is removed again.
class ElementReferences {
 public:
  /// At the start of a step: records `u` for the elements reactivated strain free, forgets the
  /// removed ones and those reactivated with strain.
  void begin_step(const AnalysisModel& am, const StepElements& elements, std::span<const double> u);
  /// Element e's reference displacements (node-row major, as Assembler gathers them); empty: none.
  std::span<const double> of(std::size_t e) const;
  bool empty() const { return reference_.empty(); }

 private:
  std::map<std::size_t, std::vector<double>> reference_;
};

}  // namespace inpact::solver
