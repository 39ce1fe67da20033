#include "projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "projection_tolerance.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// x(ξ) and its first and second parametric derivatives.
struct Local {
  ShapeEval e;
  Vec3 x{}, a0{}, a1{}, a00{}, a01{}, a11{};
};

struct FacetNodes {
  FacetShape shape;
  int n = 0;
  double size = 0.0;  ///< largest corner distance from node 0
  std::array<Vec3, 8> X{};

  FacetNodes(const Facet& f, std::span<const Vec3> x) : shape(f.shape), n(f.n_nodes), size(facet_size(f, x)) {
    for (int a = 0; a < n; ++a) X[a] = x[static_cast<std::size_t>(f.nodes[a])];
  }

  Local eval(double xi, double eta) const {
    Local l;
    l.e = eval_shape(shape, xi, eta);
    for (int a = 0; a < n; ++a) {
      l.x = axpy(l.e.N[a], X[a], l.x);
      l.a0 = axpy(l.e.dN[a][0], X[a], l.a0);
      l.a1 = axpy(l.e.dN[a][1], X[a], l.a1);
      l.a00 = axpy(l.e.d2N[a][0], X[a], l.a00);
      l.a01 = axpy(l.e.d2N[a][1], X[a], l.a01);
      l.a11 = axpy(l.e.d2N[a][2], X[a], l.a11);
    }
    return l;
  }

  double phi(const Vec3& xs, double xi, double eta) const {
    std::array<double, 8> N;
    shape_values(shape, xi, eta, N);
    return phi(xs, N);
  }
  /// φ where the shape values are N.
  double phi(const Vec3& xs, const std::array<double, 8>& N) const {
    Vec3 x{};
    for (int a = 0; a < n; ++a) x = axpy(N[a], X[a], x);
    const Vec3 r = sub(xs, x);
    return 0.5 * dot(r, r);
  }
};

bool is_tri(FacetShape s) { return s == FacetShape::Tri3 || s == FacetShape::Tri6; }

/// Where a face's Newton iteration may start: a 5 × 5 grid over the domain (triangles: its points
/// inside), with the shape values there, computed once (shape_values(), so φ on it has the bits
/// of φ evaluated point by point).
struct StartGrid {
  int n = 0;
  std::array<std::array<double, 2>, 25> xi{};
  std::array<std::array<double, 8>, 25> N{};
};
StartGrid make_start_grid(FacetShape s) {
  StartGrid g;
  const bool tri = is_tri(s);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      if (tri && i + j > 4) continue;
      const std::array<double, 2> p = tri ? std::array<double, 2>{i / 4.0, j / 4.0}
                                          : std::array<double, 2>{-1 + i / 2.0, -1 + j / 2.0};
      g.xi[static_cast<std::size_t>(g.n)] = p;
      shape_values(s, p[0], p[1], g.N[static_cast<std::size_t>(g.n)]);
      ++g.n;
    }
  return g;
}
const StartGrid& start_grid(FacetShape s) {
  static const std::array<StartGrid, 6> grids = {
      StartGrid{},          StartGrid{},  // (edges: no grid)
      make_start_grid(FacetShape::Tri3),  make_start_grid(FacetShape::Tri6),
      make_start_grid(FacetShape::Quad4), make_start_grid(FacetShape::Quad8)};
  return grids[static_cast<std::size_t>(s)];
}

constexpr double kInside = 1e-12;  // parametric tolerance of "inside the facet"

bool inside(FacetShape s, const std::array<double, 2>& xi) {
  if (facet_param_dim(s) == 1) return std::abs(xi[0]) <= 1 + kInside;
  if (is_tri(s)) return xi[0] >= -kInside && xi[1] >= -kInside && xi[0] + xi[1] <= 1 + kInside;
  return std::abs(xi[0]) <= 1 + kInside && std::abs(xi[1]) <= 1 + kInside;
}

std::array<double, 2> clamp_inside(FacetShape s, std::array<double, 2> xi) {
  if (facet_param_dim(s) == 1) return {std::clamp(xi[0], -1.0, 1.0), 0.0};
  if (is_tri(s)) {
    xi[0] = std::max(xi[0], 0.0);
    xi[1] = std::max(xi[1], 0.0);
    const double sum = xi[0] + xi[1];
    if (sum > 1) xi = {xi[0] / sum, xi[1] / sum};
    return xi;
  }
  return {std::clamp(xi[0], -1.0, 1.0), std::clamp(xi[1], -1.0, 1.0)};
}

/// Corners of the parametric domain, in order (edges run corner i → i+1).
int domain_corners(FacetShape s, std::array<std::array<double, 2>, 4>& c) {
  if (facet_param_dim(s) == 1) {
    c[0] = {-1, 0};
    c[1] = {1, 0};
    return 2;
  }
  if (is_tri(s)) {
    c[0] = {0, 0};
    c[1] = {1, 0};
    c[2] = {0, 1};
    return 3;
  }
  c = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  return 4;
}

struct LineMin {
  double t = 0, phi = std::numeric_limits<double>::infinity();
};

/// Minimum of φ(t) = ½|x_s − x(P0 + t (P1 − P0))|² over t ∈ [0, 1] on a linear facet, whose
/// domain edges are straight in space (x is linear along them): φ is a convex quadratic, least at
/// the end points or at the foot of x_s on the segment. As minimize_on_segment() below, the end
/// points first and the foot when it is lower, φ evaluated alike (ties between facets at a shared
/// corner compare the same bits).
LineMin minimize_on_straight_edge(const FacetNodes& fn, const Vec3& xs, const std::array<double, 2>& P0,
                                  const std::array<double, 2>& P1) {
  auto point = [&](double t) { return std::array<double, 2>{P0[0] + t * (P1[0] - P0[0]), P0[1] + t * (P1[1] - P0[1])}; };
  auto x_at = [&](double t) {
    const auto p = point(t);
    std::array<double, 8> N;
    shape_values(fn.shape, p[0], p[1], N);
    Vec3 x{};
    for (int a = 0; a < fn.n; ++a) x = axpy(N[a], fn.X[a], x);
    return x;
  };
  LineMin best;
  auto consider = [&](double t) {
    const auto p = point(t);
    const double v = fn.phi(xs, p[0], p[1]);
    if (v < best.phi) best = {t, v};
  };
  consider(0.0);
  consider(1.0);
  const Vec3 A = x_at(0.0), e = sub(x_at(1.0), A);
  const double ee = dot(e, e);
  if (ee > 0) {
    const double t = dot(sub(xs, A), e) / ee;
    if (t > 0 && t < 1) consider(t);
  }
  return best;
}

/// Minimum of φ(t) = ½|x_s − x(P0 + t (P1 − P0))|² over t ∈ [0, 1]: the end points and every
/// local minimum bracketed by a sign change of φ' on `samples` intervals, each refined by
/// Newton safeguarded with bisection.
LineMin minimize_on_segment(const FacetNodes& fn, const Vec3& xs, const std::array<double, 2>& P0,
                            const std::array<double, 2>& P1, int samples) {
  const double e0 = P1[0] - P0[0], e1 = P1[1] - P0[1];
  auto point = [&](double t) { return std::array<double, 2>{P0[0] + t * e0, P0[1] + t * e1}; };
  auto derivs = [&](double t, double& d1, double& d2) {
    const auto p = point(t);
    const Local l = fn.eval(p[0], p[1]);
    const Vec3 r = sub(xs, l.x);
    const Vec3 at = axpy(e1, l.a1, scale(e0, l.a0));
    const Vec3 att = axpy(e1 * e1, l.a11, axpy(2 * e0 * e1, l.a01, scale(e0 * e0, l.a00)));
    d1 = -dot(r, at);
    d2 = dot(at, at) - dot(r, att);
  };
  auto phi = [&](double t) {
    const auto p = point(t);
    return fn.phi(xs, p[0], p[1]);
  };
  LineMin best;
  auto consider = [&](double t) {
    const double v = phi(t);
    if (v < best.phi) best = {t, v};
  };
  consider(0.0);
  consider(1.0);
  double t_prev = 0.0, d_prev, dd;
  derivs(0.0, d_prev, dd);
  for (int k = 1; k <= samples; ++k) {
    const double t_k = static_cast<double>(k) / samples;
    double d_k;
    derivs(t_k, d_k, dd);
    // (≥: a minimum exactly at a sample point, φ' = 0 there — a slave node on a Line3's
    // midside node — must still be bracketed)
    if (d_prev < 0 && d_k >= 0) {
      double lo = t_prev, hi = t_k, t = 0.5 * (lo + hi);
      for (int it = 0; it < 100; ++it) {
        double d1, d2;
        derivs(t, d1, d2);
        if (d1 < 0) lo = t;
        else hi = t;
        double next = d2 > 0 ? t - d1 / d2 : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = std::abs(next - t);
        t = next;
        if (step < 1e-15 || hi - lo < 1e-15) break;
      }
      consider(t);
    }
    t_prev = t_k;
    d_prev = d_k;
  }
  return best;
}

struct InteriorResult {
  std::array<double, 2> xi{0, 0};
  bool converged = false;
};

/// Newton on ∇φ(ξ) = 0 for a face, from the best sample of a small grid.
InteriorResult newton_interior(const FacetNodes& fn, const Vec3& xs, const std::array<double, 2>* start) {
  InteriorResult res;
  if (fn.shape == FacetShape::Tri3) {  // x(ξ) is affine: one exact step from (0, 0)
    const Vec3 a0 = sub(fn.X[1], fn.X[0]), a1 = sub(fn.X[2], fn.X[0]), r = sub(xs, fn.X[0]);
    const double m00 = dot(a0, a0), m01 = dot(a0, a1), m11 = dot(a1, a1), det = m00 * m11 - m01 * m01;
    if (det <= 0) return res;
    const double b0 = dot(a0, r), b1 = dot(a1, r);
    res.xi = {(m11 * b0 - m01 * b1) / det, (m00 * b1 - m01 * b0) / det};
    res.converged = true;
    return res;
  }
  // Start: the given point, or the best point of a 5 × 5 grid (triangles: the grid points inside).
  double best = std::numeric_limits<double>::infinity();
  std::array<double, 2> xi = start ? *start : std::array<double, 2>{0, 0};
  if (!start) {
    const StartGrid& grid = start_grid(fn.shape);
    for (int k = 0; k < grid.n; ++k) {
      const double v = fn.phi(xs, grid.N[static_cast<std::size_t>(k)]);
      if (v < best) best = v, xi = grid.xi[static_cast<std::size_t>(k)];
    }
  }
  double previous_step = 0.0;  // the last full Newton step's size (0: none)
  for (int it = 0; it < 60; ++it) {
    const Local l = fn.eval(xi[0], xi[1]);
    const Vec3 r = sub(xs, l.x);
    const double g0 = -dot(l.a0, r), g1 = -dot(l.a1, r);  // ∇φ
    const double m00 = dot(l.a0, l.a0), m01 = dot(l.a0, l.a1), m11 = dot(l.a1, l.a1);
    // The step's round-off: r is a difference of coordinates of size |x|, so ξ is known to about
    // ε |x| / |∂x/∂ξ|; far from the origin (|x| over 30 facet sizes) that exceeds 1e-14, and a
    // point on a flat facet would never count as converged.
    const double magnitude = std::max({std::abs(xs[0]), std::abs(xs[1]), std::abs(xs[2]), std::abs(l.x[0]),
                                       std::abs(l.x[1]), std::abs(l.x[2])});
    const double step_tol =
        std::max(1e-14, 8.0 * std::numeric_limits<double>::epsilon() * magnitude / std::sqrt(std::min(m00, m11)));
    double h00 = m00 - dot(r, l.a00), h01 = m01 - dot(r, l.a01), h11 = m11 - dot(r, l.a11);
    double det = h00 * h11 - h01 * h01;
    const bool newton_hessian = h00 > 0 && det > 0;
    if (!newton_hessian) {  // not a descent direction: Gauss–Newton (metric) instead
      h00 = m00, h01 = m01, h11 = m11;
      det = h00 * h11 - h01 * h01;
      if (!(det > 0)) return res;  // degenerate facet
    }
    const double d0 = -(h11 * g0 - h01 * g1) / det, d1 = -(h00 * g1 - h01 * g0) / det;
    if (std::abs(d0) + std::abs(d1) < step_tol) {
      res.converged = true;
      break;
    }
    // Newton with φ's own Hessian converges quadratically, |d_next| ≈ C |d|² with C measured
    // from the last two steps: when that predicts a next step under step_tol, this step is taken
    // and nothing is left to confirm (a facet evaluation saved).
    const double step = std::abs(d0) + std::abs(d1);
    const bool last_step = newton_hessian && previous_step > 0 && step < 1e-6 &&
                           step / (previous_step * previous_step) * step * step < step_tol;
    if (last_step) {
      xi = {xi[0] + d0, xi[1] + d1};
      res.converged = true;
      break;
    }
    const double phi0 = 0.5 * dot(r, r), slope = g0 * d0 + g1 * d1;
    // Backtracking (Armijo) away from the solution; near it, φ cannot resolve the decrease any
    // more, and the full Newton step converges quadratically.
    double lambda = 1.0;
    if (std::abs(d0) + std::abs(d1) > 1e-6)
      while (lambda > 1e-6 && fn.phi(xs, xi[0] + lambda * d0, xi[1] + lambda * d1) > phi0 + 1e-4 * lambda * slope)
        lambda *= 0.5;
    xi = {xi[0] + lambda * d0, xi[1] + lambda * d1};
    previous_step = newton_hessian && lambda == 1.0 ? step : 0.0;
    if (lambda * (std::abs(d0) + std::abs(d1)) < step_tol) {
      res.converged = true;
      break;
    }
    if (std::abs(xi[0]) > 3 || std::abs(xi[1]) > 3) break;  // far outside: the boundary decides
  }
  res.xi = xi;
  return res;
}

/// A lower bound of φ = ½|x_s − x|² over edge i of a face (corners i and i + 1 of `nc`, and
/// midside node nc + i when quadratic): the edge lies on the segment between its corners, or in
/// the box of its Bézier control points. Less the round-off of the coordinates' size.
double edge_phi_bound(const FacetNodes& fn, const Vec3& xs, int i, int nc) {
  const Vec3& A = fn.X[static_cast<std::size_t>(i)];
  const Vec3& B = fn.X[static_cast<std::size_t>((i + 1) % nc)];
  double magnitude = 0.0, d = 0.0;
  for (int k = 0; k < 3; ++k) magnitude = std::max({magnitude, std::abs(xs[k]), std::abs(A[k]), std::abs(B[k])});
  if (!facet_is_quadratic(fn.shape)) {
    const Vec3 e = sub(B, A);
    const double ee = dot(e, e);
    const double t = ee > 0 ? std::clamp(dot(sub(xs, A), e) / ee, 0.0, 1.0) : 0.0;
    d = norm(sub(xs, axpy(t, e, A)));
  } else {
    const Vec3& M = fn.X[static_cast<std::size_t>(nc + i)];
    Vec3 outside{};
    for (int k = 0; k < 3; ++k) {
      const double C = 2 * M[k] - 0.5 * (A[k] + B[k]);
      const double lo = std::min({A[k], B[k], C}), hi = std::max({A[k], B[k], C});
      outside[k] = std::max({lo - xs[k], 0.0, xs[k] - hi});
      magnitude = std::max({magnitude, std::abs(C)});
    }
    d = norm(outside);
  }
  const double slack = 1e-10 * magnitude;
  if (!(d > slack)) return 0.0;  // (NaN too)
  return 0.5 * (d - slack) * (d - slack) * (1 - 1e-12);
}

/// ξ of the closest point of the domain's boundary: the least φ over its edges, the first edge
/// in order among equal ones. The edges are searched in the order of their bounds, and those
/// whose bound exceeds the least φ found cannot hold it (nor tie) and are not searched.
std::array<double, 2> closest_on_boundary(const FacetNodes& fn, const Vec3& xs) {
  std::array<std::array<double, 2>, 4> c;
  const int nc = domain_corners(fn.shape, c);
  const int n_edges = facet_param_dim(fn.shape) == 1 ? 1 : nc;
  const int samples = facet_is_quadratic(fn.shape) ? 8 : 1;
  const bool straight_edges = n_edges > 1 && !facet_is_quadratic(fn.shape);
  std::array<double, 4> bound{};
  std::array<int, 4> order{0, 1, 2, 3};
  if (n_edges > 1) {
    for (int i = 0; i < n_edges; ++i) bound[static_cast<std::size_t>(i)] = edge_phi_bound(fn, xs, i, nc);
    std::sort(order.begin(), order.begin() + n_edges, [&](int a, int b) { return bound[a] < bound[b]; });
  }
  LineMin best;
  int best_edge = n_edges;
  std::array<double, 2> best_xi{0, 0};
  for (int k = 0; k < n_edges; ++k) {
    const int i = order[static_cast<std::size_t>(k)];
    if (bound[static_cast<std::size_t>(i)] > best.phi) break;  // and so are the edges after it
    const auto& P0 = c[static_cast<std::size_t>(i)];
    const auto& P1 = c[static_cast<std::size_t>((i + 1) % nc)];
    // (a face of linear shape has straight edges; 2D edges keep the Newton, which the smoothed
    // gradient check on conforming 2D meshes was measured with)
    const LineMin m = straight_edges ? minimize_on_straight_edge(fn, xs, P0, P1) : minimize_on_segment(fn, xs, P0, P1, samples);
    if (m.phi < best.phi || (best_edge < n_edges && m.phi == best.phi && i < best_edge)) {
      best = m;
      best_edge = i;
      best_xi = {P0[0] + m.t * (P1[0] - P0[0]), P0[1] + m.t * (P1[1] - P0[1])};
    }
  }
  return best_xi;
}

ProjectionRegion region_of(FacetShape s, const std::array<double, 2>& xi) {
  constexpr double tol = 1e-10;
  if (facet_param_dim(s) == 1) return std::abs(std::abs(xi[0]) - 1) <= tol ? ProjectionRegion::Vertex : ProjectionRegion::Interior;
  int on = 0;
  if (is_tri(s)) {
    on = (xi[0] <= tol) + (xi[1] <= tol) + (xi[0] + xi[1] >= 1 - tol);
  } else {
    on = (std::abs(std::abs(xi[0]) - 1) <= tol) + (std::abs(std::abs(xi[1]) - 1) <= tol);
  }
  return on == 0 ? ProjectionRegion::Interior : on == 1 ? ProjectionRegion::Edge : ProjectionRegion::Vertex;
}

}  // namespace

void tangent_basis(const Vec3& n, int dim, Vec3& t1, Vec3& t2) {
  if (dim == 2) {
    t1 = {-n[1], n[0], 0.0};
    t2 = {0, 0, 0};
    return;
  }
  // Abaqus: t1 = projection of the global x axis onto the tangent plane, or of the global z axis
  // when x is within 0.1° of the normal; t2 = n × t1.
  const double limit = std::cos(0.1 * std::numbers::pi / 180.0);
  const Vec3 axis = std::abs(n[0]) > limit ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  Vec3 t = axpy(-dot(axis, n), n, axis);
  const double len = norm(t);
  t1 = len > 0 ? scale(1.0 / len, t) : Vec3{0, 0, 0};
  t2 = cross(n, t1);
}

Projection project_to_facet(const Facet& f, std::span<const Vec3> x, const Vec3& xs, std::int32_t facet_index,
                            const std::array<double, 2>* start) {
  const FacetNodes fn(f, x);
  Projection p;
  p.facet = facet_index;
  const int pd = facet_param_dim(f.shape);

  bool done = false;
  if (pd == 2) {
    const InteriorResult in = newton_interior(fn, xs, start);
    if (in.converged && inside(f.shape, in.xi)) {
      p.xi = clamp_inside(f.shape, in.xi);
      done = true;
    }
    p.converged = in.converged;
  }
  if (!done) {  // the closest point of the domain's boundary (for edges: of the whole edge)
    p.xi = clamp_inside(f.shape, closest_on_boundary(fn, xs));
    if (pd == 1) p.converged = true;
  }
  p.region = region_of(f.shape, p.xi);

  const FacetGeometry g = facet_geometry(f, x, p.xi[0], p.xi[1]);
  p.x_master = g.x;
  p.facet_normal = g.n;
  const Vec3 r = sub(xs, g.x);
  p.distance = norm(r);
  if (p.region == ProjectionRegion::Interior || p.distance <= on_surface_tol(fn.size)) {
    // (on an edge or vertex within round-off of the surface: the distance along the facet's
    // normal, signed — never 0 by fiat: a stiff law turns a tiny penetration into a force)
    p.normal = g.n;
    p.gap = dot(r, g.n);
  } else {
    const double s = dot(r, g.n) < 0 ? -1.0 : 1.0;
    p.normal = scale(s / p.distance, r);
    p.gap = s * p.distance;
  }
  tangent_basis(p.normal, pd == 1 ? 2 : 3, p.t1, p.t2);
  return p;
}

namespace {

/// A p × p matrix (p = 1 or 2) and its inverse.
struct Small {
  double m[2][2] = {{0, 0}, {0, 0}};
};
Small inverse(const Small& a, int p) {
  Small inv;
  if (p == 1) {
    inv.m[0][0] = 1.0 / a.m[0][0];
    return inv;
  }
  const double det = a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0];
  inv.m[0][0] = a.m[1][1] / det;
  inv.m[1][1] = a.m[0][0] / det;
  inv.m[0][1] = -a.m[0][1] / det;
  inv.m[1][0] = -a.m[1][0] / det;
  return inv;
}
Small multiply(const Small& a, const Small& b, int p) {
  Small c;
  for (int i = 0; i < p; ++i)
    for (int j = 0; j < p; ++j)
      for (int k = 0; k < p; ++k) c.m[i][j] += a.m[i][k] * b.m[k][j];
  return c;
}

/// What every part of linearize_gap() reads: the facet's geometry at ξ* and the layout of
/// u = [x_s; x_1; …; x_k] (node 0 = the slave, node a + 1 = facet node a, `dim` components each).
struct GapFrame {
  const Local& l;  ///< x(ξ*) and its derivatives
  int k = 0;       ///< facet nodes
  int pd = 0;      ///< parametric dimension
  int dim = 3;
  std::size_t nd = 0;  ///< n_dof
  Vec3 r{};            ///< x_s − x(ξ*)

  std::size_t at(int node, int comp) const { return static_cast<std::size_t>(node * dim + comp); }
  double& H(GapLinearization& L, std::size_t i, std::size_t j) const { return L.hessian[i * nd + j]; }
};

/// The linearisation sized for the slave and the facet's k nodes, every derivative zero.
GapLinearization zero_linearization(const Facet& f, int k, int pd, int dim, std::int32_t slave_row) {
  GapLinearization L;
  L.dim = dim;
  L.n_dof = dim * (k + 1);
  const std::size_t nd = static_cast<std::size_t>(L.n_dof);
  L.nodes.push_back(slave_row);
  for (int a = 0; a < k; ++a) L.nodes.push_back(f.nodes[a]);
  L.gradient.assign(nd, 0.0);
  L.hessian.assign(nd * nd, 0.0);
  for (int al = 0; al < pd; ++al) L.dxi[al].assign(nd, 0.0);
  return L;
}

/// ∂g/∂u = [n; −N_a n], the same in every region.
void set_gap_gradient(const GapFrame& u, const Vec3& n, GapLinearization& L) {
  for (int c = 0; c < u.dim; ++c) {
    L.gradient[u.at(0, c)] = n[c];
    for (int a = 0; a < u.k; ++a) L.gradient[u.at(a + 1, c)] = -u.l.e.N[a] * n[c];
  }
}

/// P_α = [a_α; −N_b a_α] and Q_α = [0; N_b,α n] as vectors over u.
struct TangentVariations {
  std::array<std::vector<double>, 2> P, Q;
};
TangentVariations tangent_variations(const GapFrame& u, const Vec3& nf) {
  const std::array<Vec3, 2> a_vec{u.l.a0, u.l.a1};
  TangentVariations t;
  for (int al = 0; al < u.pd; ++al) {
    t.P[al].assign(u.nd, 0.0);
    t.Q[al].assign(u.nd, 0.0);
    for (int c = 0; c < u.dim; ++c) {
      t.P[al][u.at(0, c)] = a_vec[al][c];
      for (int a = 0; a < u.k; ++a) {
        t.P[al][u.at(a + 1, c)] = -u.l.e.N[a] * a_vec[al][c];
        t.Q[al][u.at(a + 1, c)] = u.l.e.dN[a][al] * nf[c];
      }
    }
  }
  return t;
}

/// A⁻¹ and m⁻¹ b A⁻¹, with the metric m_αβ = a_α·a_β, the curvature b_αβ = n·a_αβ and A = m − g b.
struct InteriorMatrices {
  Small Ai, mbA;
};
InteriorMatrices interior_matrices(const Local& l, const Vec3& nf, double g, int pd) {
  const std::array<Vec3, 2> a_vec{l.a0, l.a1};
  Small m, b;
  const std::array<std::array<Vec3, 2>, 2> a2{{{l.a00, l.a01}, {l.a01, l.a11}}};
  for (int i = 0; i < pd; ++i)
    for (int j = 0; j < pd; ++j) {
      m.m[i][j] = dot(a_vec[i], a_vec[j]);
      b.m[i][j] = dot(nf, a2[i][j]);
    }
  Small A;
  for (int i = 0; i < pd; ++i)
    for (int j = 0; j < pd; ++j) A.m[i][j] = m.m[i][j] - g * b.m[i][j];
  const Small Ai = inverse(A, pd), mi = inverse(m, pd);
  return {Ai, multiply(multiply(mi, b, pd), Ai, pd)};
}

/// Inside the facet: ∂²g = −(Pᵀ A⁻¹ Q + Qᵀ A⁻¹ P) − Pᵀ m⁻¹ b A⁻¹ P − g Qᵀ A⁻¹ Q and
/// ∂ξ*/∂u = A⁻¹(P + g Q), nf the facet normal at ξ*.
void linearize_interior(const GapFrame& u, const Vec3& nf, GapLinearization& L) {
  const double g = dot(u.r, nf);
  const TangentVariations t = tangent_variations(u, nf);
  const auto& P = t.P;
  const auto& Q = t.Q;
  const InteriorMatrices im = interior_matrices(u.l, nf, g, u.pd);
  const Small& Ai = im.Ai;
  const Small& mbA = im.mbA;
  const int pd = u.pd;
  for (std::size_t i = 0; i < u.nd; ++i)
    for (std::size_t j = 0; j < u.nd; ++j) {
      double h = 0.0;
      for (int al = 0; al < pd; ++al)
        for (int be = 0; be < pd; ++be)
          h -= Ai.m[al][be] * (P[al][i] * Q[be][j] + Q[al][i] * P[be][j] + g * Q[al][i] * Q[be][j]) +
               mbA.m[al][be] * P[al][i] * P[be][j];
      u.H(L, i, j) = h;
    }
  for (int al = 0; al < pd; ++al)
    for (std::size_t i = 0; i < u.nd; ++i)
      for (int be = 0; be < pd; ++be) L.dxi[al][i] += Ai.m[al][be] * (P[be][i] + g * Q[be][i]);
}

/// The direction, in the parametric domain, of the edge that ξ lies on.
std::array<double, 2> edge_direction(FacetShape s, const std::array<double, 2>& xi) {
  std::array<double, 2> dir{1, 0};
  constexpr double tol_xi = 1e-10;
  if (is_tri(s)) {
    if (xi[1] <= tol_xi) dir = {1, 0};
    else if (xi[0] <= tol_xi) dir = {0, 1};
    else dir = {-1, 1};
  } else {
    dir = std::abs(std::abs(xi[0]) - 1) <= tol_xi ? std::array<double, 2>{0, 1} : std::array<double, 2>{1, 0};
  }
  return dir;
}

/// On an edge, ξ* still slides along it: −c cᵀ/φ_tt is added to ∂²(½d²), and ∂ξ*/∂u runs
/// along the edge (when φ_tt > 0, i.e. the minimum along the edge is strict).
void add_edge_sliding(const GapFrame& u, FacetShape s, const std::array<double, 2>& xi, GapLinearization& L) {
  const Local& l = u.l;
  const std::array<double, 2> dir = edge_direction(s, xi);
  const Vec3 a_t = axpy(dir[1], l.a1, scale(dir[0], l.a0));
  const Vec3 a_tt = axpy(dir[1] * dir[1], l.a11, axpy(2 * dir[0] * dir[1], l.a01, scale(dir[0] * dir[0], l.a00)));
  const double phi_tt = dot(a_t, a_t) - dot(u.r, a_tt);
  std::vector<double> cvec(u.nd, 0.0);
  for (int c = 0; c < u.dim; ++c) {
    cvec[u.at(0, c)] = -a_t[c];
    for (int a = 0; a < u.k; ++a)
      cvec[u.at(a + 1, c)] = l.e.N[a] * a_t[c] - (l.e.dN[a][0] * dir[0] + l.e.dN[a][1] * dir[1]) * u.r[c];
  }
  if (phi_tt > 0) {
    for (std::size_t i = 0; i < u.nd; ++i)
      for (std::size_t j = 0; j < u.nd; ++j) u.H(L, i, j) -= cvec[i] * cvec[j] / phi_tt;
    for (int al = 0; al < u.pd; ++al)
      for (std::size_t i = 0; i < u.nd; ++i) L.dxi[al][i] = -dir[al] * cvec[i] / phi_tt;
  }
}

/// On an edge or vertex at distance d > 0, g = s d: ∂²(½d²) = BᵀB (− c cᵀ/φ_tt on an edge),
/// B = [I, −N_1 I, …], then ∂²g = s (∂²(½d²) − ∇d ∇dᵀ)/d with ∇d = s ∇g.
void linearize_distance(const GapFrame& u, FacetShape shape, const Projection& p, GapLinearization& L) {
  const int k = u.k;
  const double d = p.distance;
  const double s = p.gap < 0 ? -1.0 : 1.0;
  std::vector<double> Bcoef(static_cast<std::size_t>(k + 1));
  Bcoef[0] = 1.0;
  for (int a = 0; a < k; ++a) Bcoef[static_cast<std::size_t>(a) + 1] = -u.l.e.N[a];
  for (int A = 0; A <= k; ++A)
    for (int Bn = 0; Bn <= k; ++Bn)
      for (int c = 0; c < u.dim; ++c)
        u.H(L, u.at(A, c), u.at(Bn, c)) = Bcoef[static_cast<std::size_t>(A)] * Bcoef[static_cast<std::size_t>(Bn)];
  if (p.region == ProjectionRegion::Edge) add_edge_sliding(u, shape, p.xi, L);
  for (std::size_t i = 0; i < u.nd; ++i)
    for (std::size_t j = 0; j < u.nd; ++j) u.H(L, i, j) = s * (u.H(L, i, j) - L.gradient[i] * L.gradient[j]) / d;
}

}  // namespace

GapLinearization linearize_gap(const Facet& f, std::span<const Vec3> x, const Vec3& xs, const Projection& p, int dim,
                               std::int32_t slave_row) {
  const FacetNodes fn(f, x);
  const int k = fn.n, pd = facet_param_dim(f.shape);
  GapLinearization L = zero_linearization(f, k, pd, dim, slave_row);
  const Local l = fn.eval(p.xi[0], p.xi[1]);
  const GapFrame u{l, k, pd, dim, static_cast<std::size_t>(L.n_dof), sub(xs, l.x)};
  set_gap_gradient(u, p.normal, L);
  if (p.region == ProjectionRegion::Interior) {
    linearize_interior(u, p.facet_normal, L);
    return L;
  }
  if (p.distance <= on_surface_tol(fn.size)) {  // the distance has a kink at d = 0
    L.hessian_defined = false;
    return L;
  }
  linearize_distance(u, f.shape, p, L);
  return L;
}

GapLinearization gap_gradient(const Facet& f, const Projection& p, int dim,
                              std::int32_t slave_row) {
  GapLinearization L;
  L.dim = dim;
  L.n_dof = dim * (f.n_nodes + 1);
  L.nodes.push_back(slave_row);
  for (int a = 0; a < f.n_nodes; ++a) L.nodes.push_back(f.nodes[a]);
  L.gradient.assign(static_cast<std::size_t>(L.n_dof), 0.0);
  std::array<double, 8> N;
  shape_values(f.shape, p.xi[0], p.xi[1], N);
  for (int c = 0; c < dim; ++c) {
    L.gradient[static_cast<std::size_t>(c)] = p.normal[c];
    for (int a = 0; a < f.n_nodes; ++a) L.gradient[static_cast<std::size_t>((a + 1) * dim + c)] = -N[a] * p.normal[c];
  }
  return L;
}

}  // namespace inpact::contact
