#include "mortar_segments.hpp"

#include <algorithm>
#include <cmath>

#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// A master facet makes pieces only when it faces the slave facet (centre normals within 45° of
/// opposite: the points' own overlap test, surface_to_surface.cpp's kOverlapCosine).
constexpr double kFacingCosine = 0.7071;

/// extended_param: the affine estimate from the centre's tangents, then Gauss–Newton refinements
/// of at most kMaxRefinement each — a fixed number of steps, no convergence test: the result is a
/// continuous function of the coordinates (a test that fails or passes would make the pieces, and
/// the residual, jump between Newton iterations).
constexpr int kProjectionSteps = 4;
constexpr double kSliverFraction = 0.01;

/// Quad4 / Quad8 with its corners a parallelogram and (Quad8) its midside nodes halfway: an
/// affine map, on which the first projection step is exact.
bool is_affine(const Facet& f, std::span<const Vec3> x) {
  if (f.shape == FacetShape::Line2 || f.shape == FacetShape::Tri3) return true;
  if (f.shape != FacetShape::Quad4) return false;
  auto X = [&](int a) -> const Vec3& { return x[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(a)])]; };
  const Vec3 b = sub(add(X(0), X(2)), add(X(1), X(3)));  // the bilinear term (×4)
  const Vec3 d = sub(X(2), X(0));
  return dot(b, b) <= 1e-24 * dot(d, d);
}
constexpr double kMaxRefinement = 0.25;

std::array<double, 2> facet_centre(FacetShape s) {
  if (s == FacetShape::Tri3 || s == FacetShape::Tri6) return {1.0 / 3.0, 1.0 / 3.0};
  return {0.0, 0.0};
}

Vec3 centre_normal(const Facet& f, std::span<const Vec3> x) {
  const auto c = facet_centre(f.shape);
  return facet_geometry(f, x, c[0], c[1]).n;
}

double cross2(const std::array<double, 2>& a, const std::array<double, 2>& b) { return a[0] * b[1] - a[1] * b[0]; }
std::array<double, 2> minus2(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return {a[0] - b[0], a[1] - b[1]};
}

/// The projections of the corners of facing master facets that fall inside the slave edge.
bool edge_rule(const Facet& slave, std::span<const Facet> facets, std::span<const std::int32_t> candidates,
               std::span<const Vec3> x, std::span<const Vec3> normals, int base_points, std::vector<QuadPoint>& out) {
  const Vec3 ns = centre_normal(slave, x);
  thread_local std::vector<double> breaks;
  breaks.clear();
  for (std::int32_t c : candidates) {
    const Facet& m = facets[static_cast<std::size_t>(c)];
    const Vec3 nm = normals.empty() ? centre_normal(m, x) : normals[static_cast<std::size_t>(c)];
    if (dot(ns, nm) > -kFacingCosine) continue;
    for (int a = 0; a < 2; ++a) {
      std::array<double, 2> xi{};
      if (!extended_param(slave, x, x[static_cast<std::size_t>(m.nodes[a])], xi)) return false;
      if (std::abs(xi[0]) < 1.0 - kMinSegment) breaks.push_back(xi[0]);
    }
  }
  if (breaks.empty()) return false;
  // W_a N_m is of degree 2 (Line2; 3 with an axisymmetric radius) or 4 (Line3): 2 or 3 points.
  const int min_points = slave.shape == FacetShape::Line3 ? 3 : 2;
  return segment_rule(breaks, min_points, base_points, out) > 1;
}

/// Each facing master facet's projected corner polygon, clipped against the slave face.
bool face_rule(const Facet& slave, std::span<const Facet> facets, std::span<const std::int32_t> candidates,
               std::span<const Vec3> x, std::span<const Vec3> normals, int base_points, std::vector<QuadPoint>& out,
               bool& ambiguous) {
  const Vec3 ns = centre_normal(slave, x);
  const double domain_area = polygon_area(domain_polygon(slave.shape));
  thread_local std::vector<std::pair<std::int32_t, std::array<double, 2>>> projected;  // node row → ξ
  thread_local std::vector<Polygon> cells;
  projected.clear();
  cells.clear();
  bool quadratic = facet_is_quadratic(slave.shape);
  double covered = 0.0, largest = 0.0;
  for (std::int32_t c : candidates) {
    const Facet& m = facets[static_cast<std::size_t>(c)];
    const Vec3 nm = normals.empty() ? centre_normal(m, x) : normals[static_cast<std::size_t>(c)];
    if (dot(ns, nm) > -kFacingCosine) continue;
    Polygon poly;
    for (int a = 0; a < facet_n_corners(m.shape); ++a) {
      const std::int32_t row = m.nodes[static_cast<std::size_t>(a)];
      auto it = std::find_if(projected.begin(), projected.end(), [&](const auto& e) { return e.first == row; });
      if (it == projected.end()) {
        std::array<double, 2> xi{};
        if (!extended_param(slave, x, x[static_cast<std::size_t>(row)], xi)) return ambiguous = true, false;
        projected.emplace_back(row, xi);
        it = projected.end() - 1;
      }
      poly.push_back(it->second);
    }
    if (polygon_area(poly) < 0) std::reverse(poly.begin(), poly.end());
    Polygon cell = clip_to_domain(poly, slave.shape);
    const double a = cell.size() >= 3 ? polygon_area(cell) : 0.0;
    if (a <= kMinSegment * domain_area) continue;
    covered += a;
    largest = std::max(largest, a);
    quadratic = quadratic || facet_is_quadratic(m.shape);
    cells.push_back(std::move(cell));
  }
  if (cells.empty()) return false;
  if (covered > domain_area * (1 + 1e-9)) return ambiguous = true, false;  // two layers
  if (cells.size() == 1 && largest >= domain_area * (1 - kMinSegment)) return false;  // one master facet
  // W_a N_m: degree 4 on linear faces (bilinear × bilinear), up to 6 with quadratic ones: 3 or 4
  // points per direction at least; more when few cells share the facet, about the plain rule's
  // base² points in all (surface to surface's base is that least: plain_rule_points()).
  // A sliver (under kSliverFraction of the facet: a master edge just inside it) gets one point
  // per direction fewer: over its width the integrand is nearly linear.
  const int n_min = quadratic ? 4 : 3;
  const int n = std::max(n_min, static_cast<int>(std::lround(base_points / std::sqrt(static_cast<double>(cells.size())))));
  for (const Polygon& cell : cells) {
    const int nc = polygon_area(cell) < kSliverFraction * domain_area ? n_min - 1 : n;
    if (!(cell.size() == 4 && quad_rule(cell, nc, out)) && !polygon_rule(cell, nc, out)) return ambiguous = true, false;
  }
  return true;
}

}  // namespace

bool extended_param(const Facet& f, std::span<const Vec3> x, const Vec3& p, std::array<double, 2>& xi) {
  xi = facet_centre(f.shape);
  const bool affine = is_affine(f, x);
  for (int it = 0; it < kProjectionSteps; ++it) {
    const FacetGeometry g = facet_geometry(f, x, xi[0], xi[1]);
    const Vec3 r = sub(p, g.x);
    std::array<double, 2> d{};
    if (facet_param_dim(f.shape) == 1) {
      const double aa = dot(g.a[0], g.a[0]);
      if (!(aa > 0)) return it > 0;
      d[0] = dot(g.a[0], r) / aa;
    } else {
      const double m00 = dot(g.a[0], g.a[0]), m01 = dot(g.a[0], g.a[1]), m11 = dot(g.a[1], g.a[1]);
      const double det = m00 * m11 - m01 * m01;
      if (!(det > 1e-14 * m00 * m11)) return it > 0;
      const double b0 = dot(g.a[0], r), b1 = dot(g.a[1], r);
      d = {(m11 * b0 - m01 * b1) / det, (m00 * b1 - m01 * b0) / det};
    }
    if (it > 0)  // the refinements: bounded, so that far beyond the domain nothing runs away
      for (double& c : d) c = std::clamp(c, -kMaxRefinement, kMaxRefinement);
    xi = {xi[0] + d[0], xi[1] + d[1]};
    if (affine) break;  // one step is exact on an affine map
  }
  return std::isfinite(xi[0]) && std::isfinite(xi[1]);
}

int segment_rule(std::vector<double>& breaks, int min_points, int base_points, std::vector<QuadPoint>& out) {
  std::sort(breaks.begin(), breaks.end());
  double last = -1.0;
  std::size_t kept = 0;
  for (double b : breaks)
    if (b - last >= kMinSegment && 1.0 - b >= kMinSegment) last = breaks[kept++] = b;
  breaks.resize(kept);
  breaks.push_back(1.0);
  const int n_segments = static_cast<int>(breaks.size());
  const int n = std::max(min_points, (base_points + n_segments - 1) / n_segments);
  const auto rule = facet_rule(FacetShape::Line2, n);
  double lo = -1.0;
  for (double hi : breaks) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (const QuadPoint& q : rule) out.push_back({mid + half * q.xi, 0.0, half * q.weight});
    lo = hi;
  }
  return n_segments;
}

Polygon domain_polygon(FacetShape shape) {
  if (shape == FacetShape::Tri3 || shape == FacetShape::Tri6) return {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  return {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
}

double polygon_area(const Polygon& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) twice += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5 * twice;
}

Polygon clip_to_domain(const Polygon& subject, FacetShape shape) {
  const Polygon window = domain_polygon(shape);
  Polygon out = subject, in;
  for (std::size_t e = 0; e < window.size() && !out.empty(); ++e) {
    const auto& p = window[e];
    const auto edge = minus2(window[(e + 1) % window.size()], p);
    auto side = [&](const std::array<double, 2>& v) { return cross2(edge, minus2(v, p)); };  // ≥ 0: inside
    in.swap(out);
    out.clear();
    for (std::size_t j = 0; j < in.size(); ++j) {
      const auto& prev = in[(j + in.size() - 1) % in.size()];
      const auto& cur = in[j];
      const double sp = side(prev), sc = side(cur);
      if ((sc >= 0) != (sp >= 0)) {  // the edge crosses the window's line
        const double t = sp / (sp - sc);
        out.push_back({prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1])});
      }
      if (sc >= 0) out.push_back(cur);
    }
  }
  return out;
}

bool polygon_rule(const Polygon& p, int n, std::vector<QuadPoint>& out) {
  const std::size_t start = out.size();
  // (on the unit triangle, weights summing to ½)
  std::span<const QuadPoint> rule = symmetric_triangle_rule(2 * n - 2);
  if (rule.empty()) rule = facet_rule(FacetShape::Tri3, n);
  const double scale2 = std::abs(2 * polygon_area(p));
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const auto e1 = minus2(p[i], p[0]), e2 = minus2(p[i + 1], p[0]);
    const double twice = cross2(e1, e2);
    if (twice < -1e-12 * scale2) {
      out.resize(start);
      return false;
    }
    if (twice <= 0) continue;  // a degenerate fan triangle (collinear clipped corners)
    for (const QuadPoint& q : rule)
      out.push_back({p[0][0] + q.xi * e1[0] + q.eta * e2[0], p[0][1] + q.xi * e1[1] + q.eta * e2[1], q.weight * twice});
  }
  return true;
}

bool quad_rule(const Polygon& p, int n, std::vector<QuadPoint>& out) {
  const std::size_t start = out.size();
  const auto rule = facet_rule(FacetShape::Quad4, n);  // on [−1, 1]²
  for (const QuadPoint& q : rule) {
    const double s = q.xi, t = q.eta;
    const std::array<double, 4> N{(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4, (1 - s) * (1 + t) / 4};
    const std::array<double, 4> Ns{-(1 - t) / 4, (1 - t) / 4, (1 + t) / 4, -(1 + t) / 4};
    const std::array<double, 4> Nt{-(1 - s) / 4, -(1 + s) / 4, (1 + s) / 4, (1 - s) / 4};
    std::array<double, 2> xi{}, ds{}, dt{};
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t k = 0; k < 2; ++k) {
        xi[k] += N[a] * p[a][k];
        ds[k] += Ns[a] * p[a][k];
        dt[k] += Nt[a] * p[a][k];
      }
    const double det = cross2(ds, dt);
    if (!(det > 0)) {  // folded (not convex): the caller fans it into triangles
      out.resize(start);
      return false;
    }
    out.push_back({xi[0], xi[1], q.weight * det});
  }
  return true;
}

void centre_normals(std::span<const Facet> facets, std::span<const Vec3> x, std::vector<Vec3>& out) {
  out.resize(facets.size());
  for (std::size_t i = 0; i < facets.size(); ++i) out[i] = centre_normal(facets[i], x);
}

bool mortar_rule(const Facet& slave, std::span<const Facet> facets, std::span<const std::int32_t> candidates,
                 std::span<const Vec3> x, int base_points, std::vector<QuadPoint>& out, std::span<const Vec3> normals,
                 bool* ambiguous) {
  out.clear();
  bool unclear = false;
  const bool ok = facet_param_dim(slave.shape) == 1
                      ? edge_rule(slave, facets, candidates, x, normals, base_points, out)
                      : face_rule(slave, facets, candidates, x, normals, base_points, out, unclear);
  if (!ok) out.clear();
  if (ambiguous) *ambiguous = !ok && unclear;
  return ok;
}

}  // namespace inpact::contact
