#include "tie_mortar.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "contact/projection.hpp"
#include "contact/search.hpp"
#include "contact/tie.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

using P2 = std::array<double, 2>;

/// The plane of a facet at its centre: origin, tangents, normal.
struct Plane {
  Vec3 c{}, t1{}, t2{}, n{};
  P2 to2(const Vec3& X) const {
    const Vec3 d = sub(X, c);
    return {dot(d, t1), dot(d, t2)};
  }
  Vec3 to3(const P2& p) const { return axpy(p[1], t2, axpy(p[0], t1, c)); }
};

Plane facet_plane(const Facet& f, std::span<const Vec3> x) {
  const bool tri = f.shape == FacetShape::Tri3;
  const FacetGeometry g = facet_geometry(f, x, tri ? 1.0 / 3 : 0.0, tri ? 1.0 / 3 : 0.0);
  Plane p;
  p.c = g.x;
  p.n = g.n;
  p.t1 = scale(1.0 / norm(g.a[0]), g.a[0]);
  p.t2 = cross(p.n, p.t1);
  return p;
}

double cross2(const P2& a, const P2& b, const P2& p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); }

double polygon_area(const std::vector<P2>& poly) {
  double a = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2& p = poly[i];
    const P2& q = poly[(i + 1) % poly.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

/// The facet's corners in the plane, counter-clockwise.
std::vector<P2> corners_in(const Plane& plane, const Facet& f, std::span<const Vec3> x) {
  std::vector<P2> poly;
  for (int a = 0; a < facet_n_corners(f.shape); ++a) poly.push_back(plane.to2(x[f.nodes[a]]));
  if (polygon_area(poly) < 0) std::reverse(poly.begin(), poly.end());
  return poly;
}

/// Sutherland–Hodgman: `subject` clipped by the convex counter-clockwise `clipper`.
std::vector<P2> clip(std::vector<P2> subject, const std::vector<P2>& clipper) {
  for (std::size_t e = 0; e < clipper.size() && !subject.empty(); ++e) {
    const P2& a = clipper[e];
    const P2& b = clipper[(e + 1) % clipper.size()];
    std::vector<P2> out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const P2& p = subject[i];
      const P2& q = subject[(i + 1) % subject.size()];
      const double sp = cross2(a, b, p), sq = cross2(a, b, q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double t = sp / (sp - sq);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = std::move(out);
  }
  return subject;
}

/// One integration point of a slave facet's segments.
struct SegmentPoint {
  std::array<double, 2> xi_s, xi_m;
  std::int32_t master_facet;
  double weight;
};

/// The integration points of slave facet `fs` over the master facets it overlaps.
std::vector<SegmentPoint> segment_points(const Facet& fs, const ContactSurface& master, const FacetSearch& search,
                                         std::span<const Vec3> x, double tolerance) {
  std::vector<SegmentPoint> out;
  const Plane plane = facet_plane(fs, x);
  const std::vector<P2> poly_s = corners_in(plane, fs, x);
  std::vector<std::int32_t> candidates;
  search.query(plane.c, candidates);
  std::sort(candidates.begin(), candidates.end());
  const auto rule = facet_rule(FacetShape::Tri3, 6);  // degree 10: a distorted slave facet's N_j is not a polynomial in the plane
  for (std::int32_t m : candidates) {
    const Facet& fm = master.facets()[static_cast<std::size_t>(m)];
    if (fm.shape != FacetShape::Tri3 && fm.shape != FacetShape::Quad4) continue;
    if (std::abs(dot(facet_plane(fm, x).n, plane.n)) < 0.3) continue;  // a side facet, not across
    const std::vector<P2> seg = clip(poly_s, corners_in(plane, fm, x));
    if (seg.size() < 3 || polygon_area(seg) <= 1e-12 * polygon_area(poly_s)) continue;
    for (std::size_t t = 1; t + 1 < seg.size(); ++t) {
      const P2 &p0 = seg[0], &p1 = seg[t], &p2 = seg[t + 1];
      const double area = 0.5 * cross2(p0, p1, p2);
      for (const QuadPoint& q : rule) {
        const P2 p{p0[0] + q.xi * (p1[0] - p0[0]) + q.eta * (p2[0] - p0[0]),
                   p0[1] + q.xi * (p1[1] - p0[1]) + q.eta * (p2[1] - p0[1])};
        const Vec3 X = plane.to3(p);
        const Projection ps = project_relative(fs, x, X);
        const Projection pm = project_relative(fm, x, facet_geometry(fs, x, ps.xi[0], ps.xi[1]).x);
        if (pm.distance > tolerance) continue;
        out.push_back({ps.xi, pm.xi, m, 2.0 * area * q.weight});
      }
    }
  }
  return out;
}

/// Inverse of a small matrix (n ≤ 4) by Gauss–Jordan with pivoting; false when singular.
bool invert(std::array<std::array<double, 4>, 4>& a, int n) {
  std::array<std::array<double, 4>, 4> inv{};
  for (int i = 0; i < n; ++i) inv[i][i] = 1.0;
  double scale_ref = 0.0;
  for (int i = 0; i < n; ++i) scale_ref = std::max(scale_ref, std::abs(a[i][i]));
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
    if (std::abs(a[piv][c]) <= 1e-10 * scale_ref) return false;
    std::swap(a[piv], a[c]);
    std::swap(inv[piv], inv[c]);
    const double d = a[c][c];
    for (int k = 0; k < n; ++k) a[c][k] /= d, inv[c][k] /= d;
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = a[r][c];
      for (int k = 0; k < n; ++k) a[r][k] -= f * a[c][k], inv[r][k] -= f * inv[c][k];
    }
  }
  a = inv;
  return true;
}

using Rows = std::map<std::int32_t, std::map<std::int32_t, double>>;

/// Adds slave facet fs's terms ∫ Φ_j N_l^m to `rows` and its covered ∫ N_j to `covered`:
/// Φ_j = Σ_k A_jk N_k with A = D M⁻¹, D and M the facet's ∫N_j and ∫N_j N_k on the same points.
void add_facet(const Facet& fs, const ContactSurface& master, const std::vector<SegmentPoint>& pts, Rows& rows,
               std::map<std::int32_t, double>& covered) {
  const int n = fs.n_nodes;
  std::array<std::array<double, 4>, 4> M{};
  std::array<double, 4> D{};
  std::array<double, 8> N{};
  for (const SegmentPoint& q : pts) {
    shape_values(fs.shape, q.xi_s[0], q.xi_s[1], N);
    for (int j = 0; j < n; ++j) {
      D[j] += q.weight * N[j];
      for (int k = 0; k < n; ++k) M[j][k] += q.weight * N[j] * N[k];
    }
  }
  if (!invert(M, n)) return;
  std::array<std::array<double, 4>, 4> A{};
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) A[j][k] = D[j] * M[j][k];
  std::array<double, 8> Nm{};
  for (const SegmentPoint& q : pts) {
    shape_values(fs.shape, q.xi_s[0], q.xi_s[1], N);
    const Facet& fm = master.facets()[static_cast<std::size_t>(q.master_facet)];
    shape_values(fm.shape, q.xi_m[0], q.xi_m[1], Nm);
    for (int j = 0; j < n; ++j) {
      double phi = 0.0;
      for (int k = 0; k < n; ++k) phi += A[j][k] * N[k];
      auto& row = rows[fs.nodes[j]];
      for (int l = 0; l < fm.n_nodes; ++l) row[fm.nodes[l]] += q.weight * phi * Nm[l];
    }
  }
  for (int j = 0; j < n; ++j) covered[fs.nodes[j]] += D[j];
}

/// ∫ N_j dA of every slave node over its whole facets.
std::map<std::int32_t, double> full_shares(const ContactSurface& slave, std::span<const Vec3> x) {
  std::map<std::int32_t, double> out;
  std::array<double, 8> N{};
  for (const Facet& f : slave.facets())
    for (const QuadPoint& q : facet_rule(f.shape, 3)) {
      const double w = q.weight * facet_geometry(f, x, q.xi, q.eta).jacobian;
      shape_values(f.shape, q.xi, q.eta, N);
      for (int a = 0; a < f.n_nodes; ++a) out[f.nodes[a]] += w * N[a];
    }
  return out;
}

}  // namespace

std::map<std::int32_t, std::vector<std::pair<std::int32_t, double>>> mortar_tie_weights(
    const ContactSurface& slave, const ContactSurface& master, std::span<const Vec3> x, double tolerance) {
  std::map<std::int32_t, std::vector<std::pair<std::int32_t, double>>> out;
  if (slave.dim() != 3 || slave.node_based()) return out;
  double largest = 0.0;  // the largest slave facet: the search must reach across it
  for (const Facet& f : slave.facets()) {
    const Plane p = facet_plane(f, x);
    for (int a = 0; a < facet_n_corners(f.shape); ++a) largest = std::max(largest, norm(sub(x[f.nodes[a]], p.c)));
  }
  SearchOptions options;
  options.radius = tolerance + largest;
  FacetSearch search;
  search.build(master.facets(), x, options);
  Rows rows;
  std::map<std::int32_t, double> covered;
  for (const Facet& fs : slave.facets()) {
    if (fs.shape != FacetShape::Tri3 && fs.shape != FacetShape::Quad4) continue;
    const auto pts = segment_points(fs, master, search, x, tolerance);
    if (!pts.empty()) add_facet(fs, master, pts, rows, covered);
  }
  const auto full = full_shares(slave, x);
  for (const auto& [j, row] : rows) {
    // A node the master covers for less than half its share (at the master's edge) is left to
    // its closest point: its dual basis there rests on few points.
    if (covered[j] < 0.5 * full.at(j)) continue;
    double sum = 0.0;
    for (const auto& [l, w] : row) sum += w;
    auto& terms = out[j];
    for (const auto& [l, w] : row)
      if (std::abs(w) > 1e-14 * std::abs(sum)) terms.emplace_back(l, w / sum);
  }
  return out;
}

}  // namespace inpact::contact
