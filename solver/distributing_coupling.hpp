#pragma once
/// *COUPLING with *DISTRIBUTING [K16 *DISTRIBUTING], [AUG Coupling constraints]: the reference
/// node moves with the coupling nodes' weighted mean motion. With ŵ_i the normalised weights
/// (tributary area × the weighting function), x̄ = Σ ŵ_i x_i their centroid, r_i = x_i − x̄,
/// d = x_R − x̄ and J = Σ ŵ_i (|r_i|² I − r_i r_iᵀ):
///   θ_R = J⁻¹ Σ ŵ_i r_i × u_i,        u_R = Σ ŵ_i u_i + θ_R × d.
/// By virtual work a force F and moment M at the reference node reach node i as
/// f_i = ŵ_i [F + (J⁻¹ (M + d × F)) × r_i]: their sum is F and their moment about x_R is M
/// [AUG Distributing coupling elements]. The translations of the reference node are always
/// coupled (Abaqus and CalculiX alike), its rotations where *DISTRIBUTING lists them; a force off
/// the centroid is carried with its moment d × F in any case, as CalculiX does.
/// Linear in u: exact for small rotations (steps with NLGEOM refuse coupled rotations).
#include <cstdint>
#include <map>
#include <vector>

#include "dof_map.hpp"

namespace inpact::solver {

/// One coupled DOF of the reference node (a translation, or a rotation: the rotation node's)
/// and its rule over the coupling nodes' translations.
struct CouplingRow {
  std::int64_t ref_dof;
  std::vector<MasterTerm> terms;
};

/// The weights ŵ_i of the coupling nodes (c.nodes order), summing to 1. Throws AnalysisError
/// when they are all zero.
std::vector<double> distributing_weights(const AnalysisModel& am, const model::Coupling& c);

/// The rows of a distributing coupling. Throws AnalysisError when it couples a rotation the
/// coupling nodes cannot define (all of them on one line through the centroid).
std::vector<CouplingRow> distributing_rows(const AnalysisModel& am, const model::Coupling& c);

/// Every distributing coupling's rows into `dependent`: a free reference DOF becomes dependent;
/// a prescribed one (a *BOUNDARY on the reference node) stays an independent DOF, and the
/// prescribed rows together eliminate as many coupling-node DOFs instead (full pivoting picks
/// them among the free ones).
void add_distributing_dependents(const AnalysisModel& am, std::vector<DofMap::Kind>& kind,
                                 std::map<std::int64_t, std::vector<MasterTerm>>& dependent);

}  // namespace inpact::solver
