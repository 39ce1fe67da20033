#pragma once
/// Moments at the rotation nodes of a finitely turning model (NLGEOM in 3D). A node's unknowns
/// are its total rotation vector ψ, R = exp([ψ]×) (elements/corotation.hpp), so the forces the
/// elements give there are conjugate to ψ. A spatial moment m (a *CLOAD on DOFs 4–6, which keeps
/// its global direction as Abaqus's does, or a reaction moment RM) does the work m · δθ with
/// δθ = T(ψ) δψ the spatial turn:
///   T(ψ) = I + (1 − cos φ)/φ² [ψ]× + (φ − sin φ)/φ³ [ψ]×²,   φ = |ψ|,
/// so the conjugate force is Tᵀ m, and m = T⁻ᵀ f. T = I at ψ = 0, and Tᵀ ψ = ψ: a moment about
/// the axis the node has turned about is its own conjugate (every planar turn).
#include <array>
#include <span>

#include "analysis_model.hpp"

namespace inpact::solver {

using Mat3 = std::array<std::array<double, 3>, 3>;

/// T(ψ) above (its series near ψ = 0).
Mat3 rotation_tangent(const std::array<double, 3>& psi);

/// f_ψ = Tᵀ(ψ) m at the rotation nodes `nodes` (rows): `f` holds spatial moments there on entry.
void moments_to_conjugate(std::span<const double> u, std::span<const std::int32_t> nodes, std::span<double> f);

/// m = T⁻ᵀ(ψ) f_ψ at the rotation nodes `nodes` (rows): `f` holds forces conjugate to ψ there on
/// entry, spatial moments on return (left as they are where |ψ| is a whole turn, T singular).
void conjugate_to_moments(std::span<const double> u, std::span<const std::int32_t> nodes, std::span<double> f);

/// The rotation nodes (rows) of the model: the nodes whose DOFs are another node's rotations.
std::vector<std::int32_t> rotation_nodes(const AnalysisModel& am);

}  // namespace inpact::solver
