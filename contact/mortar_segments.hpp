#pragma once
/// Segment-based (mortar) integration points of a slave facet (Puso & Laursen 2004, Popp et al.
/// 2010): the slave facet's parametric domain is cut where the master's facets begin and end, and
/// every piece gets its own Gauss rule, so that the integrands of surface-to-surface contact
/// (W_a × gap, W_a × N_m: polynomials on each piece of a flat pair of linear facets) are
/// integrated exactly instead of across the kink of the master's shape functions at a master
/// node (a 6-point Gauss rule over a hat function gives 0.490 for 0.5: a 2 % inconsistent load).
///
/// The master facets' corner nodes are projected onto the slave facet along its normal (the
/// closest point of the slave facet's polynomial map continued beyond its domain, extended_param).
///   2D (edges): the slave interval [−1, 1] is split at the projections of the master corners
///     that fall inside it (segment_rule); the segments partition the facet, so no part of it is
///     counted twice whatever the master.
///   3D (faces): each master facet's projected corner polygon is clipped against the slave
///     domain (Sutherland–Hodgman, clip_to_domain); a quadrilateral cell gets a mapped n × n
///     Gauss rule (quad_rule), any other one is fanned into triangles (polygon_rule) with a
///     symmetric triangle rule of the same degree each; n = max(3 (4 on quadratic faces), round(b/√cells)) for
///     the plain rule's b points per direction (surface-to-surface contact: 3 on linear faces and
///     4 on quadratic ones, so n is that least), one less on a sliver (a cell under 1 % of the
///     facet).
///     Only master facets facing the slave facet (centre
///     normals within 45° of opposite, the points' own overlap test) make cells; the part of the
///     slave facet no master facet covers (beyond the master's free edge) gets no point.
/// Where no master edge crosses the slave facet, or the cells are ambiguous (they overlap: two
/// master layers facing the same slave facet; a folded cell; a degenerate facet), mortar_rule()
/// returns false and the caller keeps a plain rule over the whole facet (surface to surface:
/// plain_rule_points(), and more where the cells were ambiguous: master edges cross the facet
/// then, and the plain rule integrates across the kinks of N_m). Every test that decides the layout compares a continuous
/// function of the coordinates with a fixed bound, so the layout — and the residual — changes
/// only where such a function crosses its bound, not with round-off in between.
///
/// Approximations: the cut lies where the master corner projects along the slave normal, while
/// the points themselves are projected onto the master by closest point (the master's normal);
/// the two agree on a flat interface and differ by O(gap × angle) otherwise. Quadratic master
/// facets are cut at their corners only (straight cell edges between the projected corners).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/facet.hpp"

namespace inpact::contact {

/// Pieces shorter than this (in the slave's parameter, range 2 on edges, area 4 or ½ on faces)
/// are merged into their neighbour: a kink within δ of a piece's end costs O(δ²) of its integral.
inline constexpr double kMinSegment = 1e-6;

/// The parametric point ξ nearest p on the facet's polynomial map continued beyond its domain:
/// the affine estimate from the centre's tangent plane (exact on Line2, Tri3 and parallelograms),
/// then three Gauss–Newton steps of at most 0.25 each (a fixed count: ξ is a continuous function
/// of the coordinates). Near the facet that is the closest point to round-off (flat bilinear
/// quads: Newton converges quadratically); far beyond it, a bounded estimate, which only moves
/// where a master edge crosses the slave's boundary. False on a degenerate facet.
bool extended_param(const Facet& f, std::span<const Vec3> x, const Vec3& p, std::array<double, 2>& xi);

/// A Gauss rule over [−1, 1] split at `breaks` (any order; those within kMinSegment of an end or of
/// the previous kept break are dropped): max(min_points, ⌈base_points / segments⌉) points each.
/// Returns the number of segments.
int segment_rule(std::vector<double>& breaks, int min_points, int base_points, std::vector<QuadPoint>& out);

using Polygon = std::vector<std::array<double, 2>>;
/// The corners of the parametric domain of a face shape, counter-clockwise.
Polygon domain_polygon(FacetShape shape);
/// Signed area (counter-clockwise positive).
double polygon_area(const Polygon& p);
/// `subject` clipped against the (convex, counter-clockwise) parametric domain of `shape`.
Polygon clip_to_domain(const Polygon& subject, FacetShape shape);
/// Appends a rule over the polygon (its fan from vertex 0, each triangle with a rule exact to
/// degree 2n − 2, as the n × n rule of a quadrilateral cell: symmetric_triangle_rule(), 6 points
/// where the collapsed Gauss rule takes 9 for n = 3; that rule beyond n = 4). False (nothing
/// appended) when a fan triangle turns the wrong way (a non-convex polygon).
bool polygon_rule(const Polygon& p, int n, std::vector<QuadPoint>& out);

/// Appends the n × n Gauss rule over the quadrilateral `p` (counter-clockwise), mapped
/// bilinearly from [−1, 1]² (its Jacobian is linear: exact for polynomials in ξ of total degree
/// ≤ 2n − 2, 2n − 1 on a parallelogram). False (nothing appended) where the map folds (a
/// non-convex quadrilateral).
bool quad_rule(const Polygon& p, int n, std::vector<QuadPoint>& out);

/// The mortar rule of slave facet `slave` against the master `facets` listed in `candidates`
/// (those the slave facet may touch), in the slave's parametric space with weights of the
/// parametric measure (like facet_rule()). `base_points`: the plain rule's points per direction.
/// False: keep the plain rule (see the header comment). `normals`: centre_normals() of `facets`
/// on x when the caller has them (many slave facets against the same master). `ambiguous`, when
/// given: set to whether a false came from ambiguous cells (rather than from no cut at all).
bool mortar_rule(const Facet& slave, std::span<const Facet> facets, std::span<const std::int32_t> candidates,
                 std::span<const Vec3> x, int base_points, std::vector<QuadPoint>& out,
                 std::span<const Vec3> normals = {}, bool* ambiguous = nullptr);
/// The unit normal of every facet at its parametric centre, into `out` (resized).
void centre_normals(std::span<const Facet> facets, std::span<const Vec3> x, std::vector<Vec3>& out);

}  // namespace inpact::contact
