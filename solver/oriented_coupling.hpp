#pragma once
/// A kinematic *COUPLING with ORIENTATION that couples some of the local translations only: at
/// each coupling node, for each listed local axis e_k (the orientation's, at the node),
///   e_k · u_i = e_k · (u_R + θ × r_i),
/// solved for as many of the node's global components (constraint_elimination.hpp). Small
/// rotations: a step with NLGEOM refuses it. (All three listed: the global rigid motion, done as
/// for *RIGID BODY, finite rotations included.)
#include <cstdint>
#include <map>
#include <vector>

#include "dof_map.hpp"

namespace inpact::solver {

/// The coupling takes this path: kinematic, an orientation, not every translation listed.
bool is_oriented_kinematic(const model::Coupling& c, int dim);

/// Marks the reference DOFs the couplings' rows use as free (u_R,c and θ_m with a non-zero
/// weight). Throws AnalysisError when `finite_rotations` (NLGEOM).
void mark_oriented_reference_dofs(const AnalysisModel& am, bool finite_rotations, std::vector<DofMap::Kind>& kind);

/// Every such coupling's rows into `dependent`, node by node.
void add_oriented_kinematic_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                                       std::map<std::int64_t, std::vector<MasterTerm>>& dependent);

}  // namespace inpact::solver
