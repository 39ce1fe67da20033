#pragma once
/// Which elements each rank of a distributed run evaluates: PETSc's graph partitioner
/// (PT-Scotch in Debian's PETSc, linear/petsc_partition.cpp) on the elements' dual graph, two
/// elements being neighbours when they share a node, so that each rank's elements form compact
/// regions whose borders (the rows two ranks add into) are short.
#include <cstddef>
#include <vector>

#include "analysis_model.hpp"
#include "linear/petsc_module.hpp"

namespace inpact::solver {

struct ElementPartition {
  std::vector<int> rank_of_element;  ///< per element row
  std::vector<std::size_t> counts;   ///< elements per rank
  /// Per node row, the rank that owns its rows of the system: the lowest rank among the
  /// elements whose rows it is (AnalysisModel::element_rows: a shell's rotation node too; a node
  /// of no element: the last rank).
  std::vector<int> rank_of_node;
};

/// The partition of am's elements over the ranks of `world` (every element rank 0's on one
/// rank). Collective on a distributed run: every rank calls it, in the same order. Computed
/// once per model and kept (the steps' assemblers share it).
const ElementPartition& element_partition(const AnalysisModel& am, RankWorld world);

}  // namespace inpact::solver
