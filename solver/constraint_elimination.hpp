#pragma once
/// Linear constraints Σ a_j u_j = Σ b_k u_k solved for some of their left-hand DOFs: a
/// distributing coupling's prescribed reference node, a kinematic coupling's DOFs in a local
/// system. Full pivoting picks, among the left-hand DOFs that are free and not yet eliminated in
/// this layout (a DOF an earlier layout eliminated counts as free again),
/// as many as there are rows; each becomes dependent on the right-hand DOFs and the other
/// left-hand ones.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dof_map.hpp"

namespace inpact::solver {

struct LinearRow {
  std::vector<MasterTerm> lhs;  ///< Σ a_j u_j: the DOFs to eliminate come from here
  std::vector<MasterTerm> rhs;  ///< Σ b_k u_k
};

/// Eliminates rows.size() DOFs into `dependent` (their kind set to Dependent). Throws
/// AnalysisError(`no_pivot`) when the free left-hand DOFs cannot satisfy the rows.
void eliminate_rows(const std::vector<LinearRow>& rows, std::vector<DofMap::Kind>& kind,
                    std::map<std::int64_t, std::vector<MasterTerm>>& dependent, const std::string& no_pivot);

}  // namespace inpact::solver
