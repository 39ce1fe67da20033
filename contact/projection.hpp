#pragma once
/// Closest-point projection of a slave point onto master facets, the normal gap and its
/// linearisation for node-to-surface contact.
///
/// Conventions (Abaqus's, for COPEN and CSLIP):
///   g = (x_s − x_m)·n, positive = open, negative = penetration; n is the outward normal of the
///   master body at the contact point x_m; (t1, t2, n) is right-handed, t1 the projection of the
///   global x axis onto the tangent plane (the global z axis when x is within 0.1° of n); in 2D,
///   t1 = n rotated counter-clockwise (the edge direction) and t2 = 0.
///
/// Per facet (project_to_facet): x_m = x(ξ*) with ξ* the closest point of the facet, the
/// parametric domain included (clamping). Linear triangles are solved exactly; other faces by
/// Newton on ∇φ = 0, φ(ξ) = ½|x_s − x(ξ)|², started from the best of a grid of samples, with
/// a Gauss–Newton step and backtracking whenever the Newton step is not a descent step. If
/// Newton does not converge inside the domain, the minimum over the domain's edges and vertices
/// is taken (each edge a 1D problem: φ' bracketed on 8 samples, then safeguarded Newton).
///
/// Among candidate facets (closest_projection): the facet with the smallest distance |x_s − x_m|
/// wins. The contact normal is continuous across facets:
///   - closest point inside a facet: the facet normal there (= ±(x_s − x_m)/|x_s − x_m|);
///   - closest point on a facet's edge or vertex (a convex edge/corner seen from outside, or a
///     free boundary): n = s (x_s − x_m)/|x_s − x_m|, the direction of the distance itself, which
///     turns continuously from one facet's normal to the next one's; the sign s is that of
///     (x_s − x_m)·n̄, n̄ the sum of the facet normals at x_m of every candidate facet sharing that
///     closest point;
///   - slave on the surface to round-off at an edge or vertex (distance ≤ 1e-8 of a facet):
///     n = n̄/|n̄|, g = (x_s − x_m)·n (signed, of the size of round-off, never forced to 0), and
///     the facet with the lowest index among those sharing the point is reported (no double
///     count: one slave node, one projection).
/// Inside a concave corner two facets can be equally close with different normals; the normal
/// jumps there, as it does for any faceted surface without smoothing.
/// Only the candidates a distance bound cannot rule out are projected (closest_projection.cpp:
/// the bound from the facet's control points; the comparisons keep the candidates' order, so the
/// result is the one projecting every candidate gives, to the bit).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/facet.hpp"

namespace inpact::contact {

enum class ProjectionRegion : std::uint8_t {
  Interior,  ///< x_m inside the facet: an orthogonal projection
  Edge,      ///< on an edge of the facet's parametric domain (faces only)
  Vertex     ///< on a corner
};

struct Projection {
  std::int32_t facet = -1;         ///< index into the facet list given (−1: none)
  std::array<double, 2> xi{0, 0};  ///< parametric point of x_m
  ProjectionRegion region = ProjectionRegion::Interior;
  Vec3 x_master{};
  double distance = 0.0;  ///< |x_s − x_m|
  double gap = 0.0;       ///< signed normal gap (x_s − x_m)·n
  Vec3 normal{};          ///< contact normal, outward from the master body
  Vec3 facet_normal{};    ///< the facet's own normal at ξ*
  /// closest_projection: the unit sum of the normals at x_m of every candidate facet sharing
  /// that point (the facet's own at an interior point; at a free edge too).
  Vec3 shared_normal{};
  Vec3 t1{}, t2{};        ///< tangent basis (CSLIP1/2 directions)
  bool converged = true;  ///< false: Newton ran out of iterations (the boundary result is kept)
  /// Node to surface, beyond a free edge of the master within its EXTENSION ZONE: x_master is
  /// the edge's point, the normal the facet's, and the gap the distance to the facet's plane
  /// extended (contact/node_to_surface.hpp).
  bool extended = false;
};

/// Closest point of `xs` on facet `f` on coordinates `x` (all node rows); `facet_index` is
/// copied into the result.
/// `start`: where a face's Newton iteration starts (the last ξ of the same point, say) instead of
/// the best point of a 5 × 5 grid; it converges to the same ξ to round-off when that is inside.
Projection project_to_facet(const Facet& f, std::span<const Vec3> x, const Vec3& xs, std::int32_t facet_index = 0,
                            const std::array<double, 2>* start = nullptr);

/// The projection of `xs` onto the closest of the `candidates` (indices into `facets`), with the
/// continuous normal described above. facet = −1 when there is no candidate.
/// A start for the projection onto one facet (project_to_facet's `start`).
struct ProjectionHint {
  std::int32_t facet = -1;  ///< −1: none
  std::array<double, 2> xi{0, 0};
};
/// The box of a facet's control points (its convex hull holds the facet) and its size squared
/// (the largest squared distance of a node from node 0): what closest_projection bounds
/// distances and tolerances with.
struct FacetBox {
  Vec3 lo, hi;
  double size2 = 0.0;
};
FacetBox facet_box(const Facet& f, std::span<const Vec3> x);
/// facet_box() of every facet, into `out` (resized).
void facet_boxes(std::span<const Facet> facets, std::span<const Vec3> x, std::vector<FacetBox>& out);

/// What closest_projection() saw of the candidates besides the one it chose.
struct ClosestMargin {
  double others = 0.0;  ///< none of them is closer to the point than this (+∞: there is none)
  double slack = 0.0;   ///< its tie tolerance and the round-off of the coordinates' size in its bounds
};

/// `boxes`: facet_boxes() of `facets` on `x`, when the caller has them (many points against the
/// same facets); otherwise each candidate's box is computed here. `margin`: filled when given.
/// `known`: project_to_facet()'s result for candidate known->facet on the same x, xs and hint,
/// when the caller has it (sole_projection()'s `raw`): used wherever the search would project
/// that candidate, so the answer is the same to the bit.
Projection closest_projection(std::span<const Facet> facets, std::span<const std::int32_t> candidates,
                              std::span<const Vec3> x, const Vec3& xs, const ProjectionHint* hint = nullptr,
                              std::span<const FacetBox> boxes = {}, ClosestMargin* margin = nullptr,
                              const Projection* known = nullptr);

/// closest_projection()'s result when facet `index` is its only candidate within its tie
/// tolerance of the closest distance: the same numbers, to the bit, without the other
/// candidates. The caller must know that no other facet comes that close, and pass a `tol` at
/// least that tolerance and below the distance (so that, as in the search, the normal is the
/// facet's own, not an average over facets sharing the point).
/// `raw`, when given, receives project_to_facet()'s result before it is finished (for
/// closest_projection()'s `known`, when the caller searches after all).
Projection sole_projection(std::span<const Facet> facets, std::int32_t index, std::span<const Vec3> x, const Vec3& xs,
                           const ProjectionHint* hint, double tol, Projection* raw = nullptr);

/// The tangent basis for a unit normal `n` (dim 3: Abaqus's surface convention; dim 2: t1 = n
/// rotated counter-clockwise, t2 = 0).
void tangent_basis(const Vec3& n, int dim, Vec3& t1, Vec3& t2);

/// Linearisation of the gap of one slave node against facet `f` at projection `p`.
/// Unknowns u = [x_s; x_1; …; x_k] (slave, then the facet's nodes in facet order), `dim`
/// components each, n_dof = dim (k + 1).
///   gradient  ∂g/∂u = [n; −N_1 n; …; −N_k n]                         (every region)
///   hessian   ∂²g/∂u² (n_dof × n_dof, row-major), the second variation for finite sliding:
///     Interior: with P_α = [a_α; −N_b a_α], Q_α = [0; N_b,α n], metric m_αβ = a_α·a_β,
///       curvature b_αβ = n·a_αβ and A = m − g b,
///       ∂²g = −(Pᵀ A⁻¹ Q + Qᵀ A⁻¹ P) − Pᵀ m⁻¹ b A⁻¹ P − g Qᵀ A⁻¹ Q;
///     Edge / Vertex with distance d > 0: g = s d with d² = 2φ minimised over the edge
///       parameter t (vertex: none), ∂²(½d²) = BᵀB − c cᵀ/φ_tt, ∂²g = s (∂²(½d²) − ∇d ∇dᵀ)/d;
///     Edge / Vertex with d = 0: not defined (the distance has a kink); hessian is zero and
///       hessian_defined = false.
///   dxi  ∂ξ*/∂u (param_dim rows of n_dof): A⁻¹(P + g Q) inside; along the edge on an edge;
///     zero at a vertex. What CSLIP increments need.
struct GapLinearization {
  int dim = 3;
  int n_dof = 0;
  std::vector<std::int32_t> nodes;  ///< node rows in u order: slave row (or −1), facet nodes
  std::vector<double> gradient;
  std::vector<double> hessian;
  bool hessian_defined = true;
  std::array<std::vector<double>, 2> dxi;
};
GapLinearization linearize_gap(const Facet& f, std::span<const Vec3> x, const Vec3& xs, const Projection& p, int dim,
                               std::int32_t slave_row = -1);
/// Only the gradient of linearize_gap() (the same numbers; hessian and dxi left empty): what a
/// linearisation without finite sliding reads.
GapLinearization gap_gradient(const Facet& f, const Projection& p, int dim,
                              std::int32_t slave_row = -1);

}  // namespace inpact::contact
