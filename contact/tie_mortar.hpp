#pragma once
/// Surface-to-surface tie weights by the dual mortar method (Wohlmuth 2000; Popp et al. 2010):
/// the constraint ∫ Φ_j (u_s − u_m) dA = 0 per slave node j, with Φ_j the dual basis of the
/// slave facets (∫ Φ_j N_k dA = δ_jk ∫ N_j dA), so that each slave node's row is its own:
///   u_j = Σ_l W_jl u_l,   W_jl = ∫ Φ_j N_l^m dA / Σ_l' ∫ Φ_j N_l'^m dA.
/// The integrals run over segments: each slave facet clipped against the master facets it
/// overlaps, in the slave facet's plane (Sutherland–Hodgman), each piece triangulated and
/// integrated with a degree-4 rule; the dual basis of a facet is built on the same points. Then
/// a linear field on the master is reproduced exactly at the slave nodes (Σ_l W_jl x_l = x_j)
/// and a uniform traction is passed on as the master's consistent nodal forces (Σ_j Φ_j = 1):
/// a non-matching flat tie passes the patch test to round-off, where tying each slave node to
/// its closest point does not (its forces do not reach the master nodes as consistent loads).
/// Linear 3-D facets (Tri3, Quad4) only; a slave node the segments do not cover well (its row
/// sum under half of ∫ N_j dA: the edge of the master surface) gets no row, and the caller ties
/// it to its closest point instead.
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "contact/contact_surface.hpp"

namespace inpact::contact {

/// Master node rows and weights per slave node row, for the slave nodes the segments cover.
/// `tolerance`: master facets farther than this from a slave point take no part.
std::map<std::int32_t, std::vector<std::pair<std::int32_t, double>>> mortar_tie_weights(
    const ContactSurface& slave, const ContactSurface& master, std::span<const Vec3> x, double tolerance);

}  // namespace inpact::contact
