#pragma once
/// The history variables of the integration points whose material has any
/// (elements::Material::state_size() > 0), for the whole analysis (they carry over from step to
/// step). Two copies of each point's state:
///  - committed: the state of the last converged increment (at first, the material's initial
///    state); every evaluation starts from it;
///  - trial: what the last assembly's evaluation at its strain left.
/// The contract with the loop:
///  1. every assembly evaluates each point from its committed state and writes the trial state
///     (Newton iterations, the augmentations, and the attempts after a cutback alike);
///  2. when an increment has converged, after its output, the increment loop commits:
///     trial → committed;
///  3. a failed attempt is discarded (trial ← committed): the attempt after the cutback starts
///     from the same committed state the failed one did.
/// Output computed away from an assembly evaluates from the committed state into a scratch copy.
/// Elements of stateless materials hold nothing: a model of only such elements (every model with
/// today's elastic materials) has no offsets and no state at all, zero bytes.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "analysis_model.hpp"
#include "elements/element_kernel.hpp"

namespace inpact::solver {

class MaterialStates {
 public:
  MaterialStates() = default;
  /// Sized for `am`'s elements whose material has state, each point at its initial state.
  explicit MaterialStates(const AnalysisModel& am);

  /// No element has state.
  bool empty() const { return offset_.empty(); }
  /// Memory held (the vectors' contents).
  std::size_t bytes() const;

  /// Element e's history for an assembly: committed to read, trial to write (empty: stateless).
  /// Distinct elements get disjoint spans, so threads may assemble distinct elements at once.
  elements::ElementHistory assembly_history(std::size_t e);
  /// Element e's history for output computed away from an assembly: committed to read, the
  /// trial state into `scratch`.
  elements::ElementHistory output_history(std::size_t e, std::vector<double>& scratch) const;

  std::span<const double> committed(std::size_t e) const { return slice(committed_, e); }
  std::span<const double> trial(std::size_t e) const { return slice(trial_, e); }

  /// The points whose material says the step from committed to trial is too large
  /// (elements::Material::increment_too_large).
  std::size_t points_with_too_large_increments(const AnalysisModel& am) const;

  /// Element e back to its initial state, committed and trial (*MODEL CHANGE, ADD).
  void reset(const AnalysisModel& am, std::size_t e);
  /// The increment converged: its trial states become the committed ones.
  void commit();
  /// The attempt failed: its trial states are dropped.
  void discard();

 private:
  std::span<const double> slice(const std::vector<double>& v, std::size_t e) const;
  /// *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN into the committed states (checked by
  /// build_analysis_model: every element named has plasticity, every point exists).
  void apply_initial_plastic_strains(const AnalysisModel& am);

  std::vector<std::size_t> offset_;       ///< element e: values [offset_[e], offset_[e + 1]); n + 1 or empty
  std::vector<std::uint32_t> per_point_;  ///< element e: values per point (0: stateless)
  std::vector<double> committed_, trial_;
};

}  // namespace inpact::solver
