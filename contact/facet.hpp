#pragma once
/// Contact facets: an element face (3D) or edge (2D) seen as a parametric patch
/// x(ξ) = Σ_a N_a(ξ) x_a over its nodes, evaluated on whatever coordinates the caller passes
/// (reference, or current = reference + u).
///
/// Parametric domains and node order (corners first, then midside nodes, midside node a between
/// corners a and a+1, as model/element_types.hpp lists them):
///   Line2, Line3  ξ ∈ [−1, 1]; corners at ξ = −1, +1; Line3's midside node at ξ = 0.
///   Tri3, Tri6    ξ, η ≥ 0, ξ + η ≤ 1; corners at (0,0), (1,0), (0,1); N_0 = 1 − ξ − η.
///   Quad4, Quad8  (ξ, η) ∈ [−1, 1]²; corners at (−1,−1), (1,−1), (1,1), (−1,1); Quad8 is the
///                 8-node serendipity face of C3D20.
/// Outward normal (out of the element the face belongs to, i.e. out of the body):
///   3D faces: n = (a_2 × a_1)/|a_2 × a_1| with a_α = ∂x/∂ξ_α — the corner order turns into the
///             element by the right-hand rule, so a_1 × a_2 points inwards.
///   2D edges: n = the edge direction a_1 rotated clockwise, (a_1y, −a_1x)/|a_1|.
#include <array>
#include <cstdint>
#include <span>

namespace inpact::contact {

using Vec3 = std::array<double, 3>;

enum class FacetShape : std::uint8_t { Line2, Line3, Tri3, Tri6, Quad4, Quad8 };

int facet_n_nodes(FacetShape s);
int facet_n_corners(FacetShape s);
/// 1 for edges, 2 for faces.
int facet_param_dim(FacetShape s);
bool facet_is_quadratic(FacetShape s);
/// The shape of a face with `n_nodes` nodes and `n_corners` corners on an element of dimension
/// `dim`; throws std::invalid_argument for a combination inpact does not know.
FacetShape facet_shape_of(int dim, int n_nodes, int n_corners);

/// One facet of a contact surface.
struct Facet {
  FacetShape shape = FacetShape::Tri3;
  std::uint8_t n_nodes = 0;
  std::array<std::int32_t, 8> nodes{};  ///< node rows: corners, then midside nodes
  std::int32_t element = -1;            ///< element row it belongs to (-1: built by hand)
  std::uint8_t face = 0;                ///< 0 = S1
  std::span<const std::int32_t> node_rows() const { return {nodes.data(), n_nodes}; }
};

/// Shape functions and their first and second derivatives at one parametric point.
struct ShapeEval {
  int n = 0;
  std::array<double, 8> N{};
  std::array<std::array<double, 2>, 8> dN{};   ///< ∂N_a/∂ξ, ∂N_a/∂η (η part 0 for edges)
  std::array<std::array<double, 3>, 8> d2N{};  ///< ∂²N_a/∂ξ², ∂²N_a/∂ξ∂η, ∂²N_a/∂η²
};
ShapeEval eval_shape(FacetShape s, double xi, double eta = 0.0);
/// The shape functions alone (the first facet_n_nodes(s) entries of N; the same bits as eval_shape's).
void shape_values(FacetShape s, double xi, double eta, std::array<double, 8>& N);

/// Parametric coordinates of node a of the shape (its corners and midside nodes).
std::array<double, 2> facet_node_param(FacetShape s, int a);

/// Position, tangents and outward unit normal of a facet at one parametric point.
struct FacetGeometry {
  Vec3 x{};
  std::array<Vec3, 2> a{};  ///< covariant tangents ∂x/∂ξ, ∂x/∂η (a[1] = 0 for edges)
  Vec3 n{};                 ///< outward unit normal (zero on a degenerate facet)
  double jacobian = 0.0;    ///< |a_1 × a_2| (faces) or |a_1| (edges): dA = jacobian dξ dη
};
FacetGeometry facet_geometry(const Facet& f, std::span<const Vec3> x, double xi, double eta = 0.0);
/// The same from the shape functions at the point, e = eval_shape(f.shape, ξ, η).
FacetGeometry facet_geometry(const Facet& f, std::span<const Vec3> x, const ShapeEval& e);

/// The orthonormal facet frame (t1 along a[0], t2 = n × t1, n) at a point; false on a
/// degenerate facet.
bool facet_frame(const FacetGeometry& g, std::array<Vec3, 3>& q);

/// A quadrature rule over the facet's parametric domain.
struct QuadPoint {
  double xi, eta, weight;
};
/// Gauss rule with `n` points per direction (Gauss–Legendre on lines and quads, the collapsed
/// Duffy product on triangles: exact to degree 2n−1 per direction, 2n−2 on triangles).
std::span<const QuadPoint> facet_rule(FacetShape s, int n);
/// A symmetric rule on the unit triangle (weights summing to ½) exact to total degree `degree`,
/// every point inside and every weight positive: Strang and Fix's 3 points up to degree 2,
/// Dunavant's 6 up to 4 and 12 up to 6 (Dunavant 1985, refined to round-off on the moment
/// equations); empty beyond degree 6. For degrees 2, 4 and 6 the collapsed rule
/// facet_rule(Tri3, n) of the same degree 2n − 2 takes 4, 9 and 16 points.
std::span<const QuadPoint> symmetric_triangle_rule(int degree);

/// Points whose convex hull contains the facet (the Bernstein–Bézier control points: the nodes
/// of linear facets; for quadratic facets the corners, 2 m − (c_i + c_j)/2 per edge and, for
/// Quad8, Σ m − ¾ Σ c at the centre). Returns how many were written (≤ 9).
int facet_control_points(const Facet& f, std::span<const Vec3> x, std::array<Vec3, 9>& out);

}  // namespace inpact::contact
