#include "facet.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "vec3.hpp"

namespace inpact::contact {

int facet_n_nodes(FacetShape s) {
  switch (s) {
    case FacetShape::Line2: return 2;
    case FacetShape::Line3: return 3;
    case FacetShape::Tri3: return 3;
    case FacetShape::Tri6: return 6;
    case FacetShape::Quad4: return 4;
    case FacetShape::Quad8: return 8;
  }
  return 0;
}

int facet_n_corners(FacetShape s) {
  switch (s) {
    case FacetShape::Line2:
    case FacetShape::Line3: return 2;
    case FacetShape::Tri3:
    case FacetShape::Tri6: return 3;
    case FacetShape::Quad4:
    case FacetShape::Quad8: return 4;
  }
  return 0;
}

int facet_param_dim(FacetShape s) { return s == FacetShape::Line2 || s == FacetShape::Line3 ? 1 : 2; }

bool facet_is_quadratic(FacetShape s) {
  return s == FacetShape::Line3 || s == FacetShape::Tri6 || s == FacetShape::Quad8;
}

FacetShape facet_shape_of(int dim, int n_nodes, int n_corners) {
  if (dim == 2 && n_corners == 2 && n_nodes == 2) return FacetShape::Line2;
  if (dim == 2 && n_corners == 2 && n_nodes == 3) return FacetShape::Line3;
  if (dim == 3 && n_corners == 3 && n_nodes == 3) return FacetShape::Tri3;
  if (dim == 3 && n_corners == 3 && n_nodes == 6) return FacetShape::Tri6;
  if (dim == 3 && n_corners == 4 && n_nodes == 4) return FacetShape::Quad4;
  if (dim == 3 && n_corners == 4 && n_nodes == 8) return FacetShape::Quad8;
  throw std::invalid_argument("contact facet: no facet shape for a " + std::to_string(dim) + "-D face with " +
                              std::to_string(n_nodes) + " nodes and " + std::to_string(n_corners) + " corners");
}

namespace {

constexpr double kQuadCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// Each shape's functions N (shape_values) and their derivatives (eval_shape) are written apart so
// that a caller needing only x(ξ) (the distance φ of a projection) pays for N alone; eval_shape
// takes its N from the same functions, so both give the same bits.

void tri_linear_values(std::array<double, 8>& N, double xi, double eta) {
  N[0] = 1 - xi - eta;
  N[1] = xi;
  N[2] = eta;
}

void tri_linear(ShapeEval& e) {
  e.dN[0] = {-1, -1};
  e.dN[1] = {1, 0};
  e.dN[2] = {0, 1};
}

void tri_quadratic_values(std::array<double, 8>& N, double xi, double eta) {
  const double L[3] = {1 - xi - eta, xi, eta};
  for (int i = 0; i < 3; ++i) N[i] = L[i] * (2 * L[i] - 1);
  for (int m = 0; m < 3; ++m) N[3 + m] = 4 * L[m] * L[(m + 1) % 3];
}

void tri_quadratic(ShapeEval& e, double xi, double eta) {
  const double L[3] = {1 - xi - eta, xi, eta};
  const double dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 2; ++k) e.dN[i][k] = (4 * L[i] - 1) * dL[i][k];
    e.d2N[i] = {4 * dL[i][0] * dL[i][0], 4 * dL[i][0] * dL[i][1], 4 * dL[i][1] * dL[i][1]};
  }
  for (int m = 0; m < 3; ++m) {
    const int i = m, j = (m + 1) % 3, a = 3 + m;
    for (int k = 0; k < 2; ++k) e.dN[a][k] = 4 * (L[j] * dL[i][k] + L[i] * dL[j][k]);
    e.d2N[a] = {8 * dL[i][0] * dL[j][0], 4 * (dL[i][0] * dL[j][1] + dL[j][0] * dL[i][1]), 8 * dL[i][1] * dL[j][1]};
  }
}

void quad_linear_values(std::array<double, 8>& N, double xi, double eta) {
  for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + kQuadCorner[a][0] * xi) * (1 + kQuadCorner[a][1] * eta);
}

void quad_linear(ShapeEval& e, double xi, double eta) {
  for (int a = 0; a < 4; ++a) {
    const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
    e.dN[a] = {0.25 * xa * (1 + ya * eta), 0.25 * ya * (1 + xa * xi)};
    e.d2N[a] = {0, 0.25 * xa * ya, 0};
  }
}

void quad_serendipity_values(std::array<double, 8>& N, double xi, double eta) {
  for (int a = 0; a < 4; ++a) {
    const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
    N[a] = 0.25 * (1 + xa * xi) * (1 + ya * eta) * (xa * xi + ya * eta - 1);
  }
  // Midside nodes: m0 at (0,−1), m1 at (1,0), m2 at (0,1), m3 at (−1,0).
  N[4] = 0.5 * (1 - xi * xi) * (1 + -1.0 * eta);
  N[6] = 0.5 * (1 - xi * xi) * (1 + 1.0 * eta);
  N[5] = 0.5 * (1 + 1.0 * xi) * (1 - eta * eta);
  N[7] = 0.5 * (1 + -1.0 * xi) * (1 - eta * eta);
}

void quad_serendipity(ShapeEval& e, double xi, double eta) {
  for (int a = 0; a < 4; ++a) {
    const double xa = kQuadCorner[a][0], ya = kQuadCorner[a][1];
    const double A = 1 + xa * xi, B = 1 + ya * eta;
    e.dN[a] = {0.25 * xa * B * (2 * xa * xi + ya * eta), 0.25 * ya * A * (xa * xi + 2 * ya * eta)};
    e.d2N[a] = {0.5 * B, 0.25 * xa * ya * (2 * xa * xi + 2 * ya * eta + 1), 0.5 * A};
  }
  for (int m : {0, 2}) {
    const double ya = m == 0 ? -1.0 : 1.0;
    const int a = 4 + m;
    e.dN[a] = {-xi * (1 + ya * eta), 0.5 * ya * (1 - xi * xi)};
    e.d2N[a] = {-(1 + ya * eta), -xi * ya, 0};
  }
  for (int m : {1, 3}) {
    const double xa = m == 1 ? 1.0 : -1.0;
    const int a = 4 + m;
    e.dN[a] = {0.5 * xa * (1 - eta * eta), -eta * (1 + xa * xi)};
    e.d2N[a] = {0, -xa * eta, -(1 + xa * xi)};
  }
}

}  // namespace

void shape_values(FacetShape s, double xi, double eta, std::array<double, 8>& N) {
  switch (s) {
    case FacetShape::Line2:
      N[0] = 0.5 * (1 - xi);
      N[1] = 0.5 * (1 + xi);
      break;
    case FacetShape::Line3:
      N[0] = 0.5 * xi * (xi - 1);
      N[1] = 0.5 * xi * (xi + 1);
      N[2] = 1 - xi * xi;
      break;
    case FacetShape::Tri3: tri_linear_values(N, xi, eta); break;
    case FacetShape::Tri6: tri_quadratic_values(N, xi, eta); break;
    case FacetShape::Quad4: quad_linear_values(N, xi, eta); break;
    case FacetShape::Quad8: quad_serendipity_values(N, xi, eta); break;
  }
}

ShapeEval eval_shape(FacetShape s, double xi, double eta) {
  ShapeEval e;
  e.n = facet_n_nodes(s);
  shape_values(s, xi, eta, e.N);
  switch (s) {
    case FacetShape::Line2:
      e.dN[0] = {-0.5, 0};
      e.dN[1] = {0.5, 0};
      break;
    case FacetShape::Line3:
      e.dN[0] = {xi - 0.5, 0};
      e.dN[1] = {xi + 0.5, 0};
      e.dN[2] = {-2 * xi, 0};
      e.d2N[0] = {1, 0, 0};
      e.d2N[1] = {1, 0, 0};
      e.d2N[2] = {-2, 0, 0};
      break;
    case FacetShape::Tri3: tri_linear(e); break;
    case FacetShape::Tri6: tri_quadratic(e, xi, eta); break;
    case FacetShape::Quad4: quad_linear(e, xi, eta); break;
    case FacetShape::Quad8: quad_serendipity(e, xi, eta); break;
  }
  return e;
}

std::array<double, 2> facet_node_param(FacetShape s, int a) {
  switch (s) {
    case FacetShape::Line2:
    case FacetShape::Line3: return {a == 0 ? -1.0 : a == 1 ? 1.0 : 0.0, 0.0};
    case FacetShape::Tri3:
    case FacetShape::Tri6: {
      constexpr double p[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
      return {p[a][0], p[a][1]};
    }
    case FacetShape::Quad4:
    case FacetShape::Quad8: {
      constexpr double p[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
      return {p[a][0], p[a][1]};
    }
  }
  return {0, 0};
}

FacetGeometry facet_geometry(const Facet& f, std::span<const Vec3> x, double xi, double eta) {
  return facet_geometry(f, x, eval_shape(f.shape, xi, eta));
}

bool facet_frame(const FacetGeometry& g, std::array<Vec3, 3>& q) {
  const double l1 = norm(g.a[0]);
  if (!(l1 > 0) || !(norm(g.n) > 0)) return false;
  q[0] = scale(1.0 / l1, g.a[0]);
  q[2] = g.n;
  q[1] = cross(q[2], q[0]);
  return true;
}

FacetGeometry facet_geometry(const Facet& f, std::span<const Vec3> x, const ShapeEval& e) {
  FacetGeometry g;
  for (int a = 0; a < e.n; ++a) {
    const Vec3& xa = x[static_cast<std::size_t>(f.nodes[a])];
    g.x = axpy(e.N[a], xa, g.x);
    g.a[0] = axpy(e.dN[a][0], xa, g.a[0]);
    g.a[1] = axpy(e.dN[a][1], xa, g.a[1]);
  }
  if (facet_param_dim(f.shape) == 1) {
    g.jacobian = norm(g.a[0]);
    if (g.jacobian > 0) g.n = {g.a[0][1] / g.jacobian, -g.a[0][0] / g.jacobian, 0.0};
  } else {
    const Vec3 c = cross(g.a[1], g.a[0]);
    g.jacobian = norm(c);
    if (g.jacobian > 0) g.n = scale(1.0 / g.jacobian, c);
  }
  return g;
}

namespace {

/// Gauss–Legendre points and weights on [−1, 1] (Newton on the Legendre recurrence).
std::vector<std::array<double, 2>> gauss_legendre(int n) {
  std::vector<std::array<double, 2>> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    out[static_cast<std::size_t>(i)] = {x, 2 / ((1 - x * x) * dp * dp)};
  }
  return out;
}

constexpr int kMaxRule = 10;

struct Rules {
  std::vector<QuadPoint> line[kMaxRule + 1], quad[kMaxRule + 1], tri[kMaxRule + 1];
  Rules() {
    for (int n = 1; n <= kMaxRule; ++n) {
      const auto g = gauss_legendre(n);
      for (const auto& p : g) line[n].push_back({p[0], 0.0, p[1]});
      for (const auto& p : g)
        for (const auto& q : g) {
          quad[n].push_back({p[0], q[0], p[1] * q[1]});
          // Duffy: ξ = (1+u)/2, η = (1−ξ)(1+v)/2, dξ dη = (1−ξ)/4 du dv.
          const double xi = 0.5 * (1 + p[0]);
          tri[n].push_back({xi, 0.5 * (1 - xi) * (1 + q[0]), 0.25 * (1 - xi) * p[1] * q[1]});
        }
    }
  }
};

}  // namespace

std::span<const QuadPoint> facet_rule(FacetShape s, int n) {
  static const Rules rules;
  n = n < 1 ? 1 : n > kMaxRule ? kMaxRule : n;
  switch (s) {
    case FacetShape::Line2:
    case FacetShape::Line3: return rules.line[n];
    case FacetShape::Tri3:
    case FacetShape::Tri6: return rules.tri[n];
    case FacetShape::Quad4:
    case FacetShape::Quad8: return rules.quad[n];
  }
  return {};
}

std::span<const QuadPoint> symmetric_triangle_rule(int degree) {
  static const std::array<QuadPoint, 3> degree2{{
      {0.16666666666666667, 0.16666666666666667, 0.16666666666666667},
      {0.16666666666666667, 0.66666666666666667, 0.16666666666666667},
      {0.66666666666666667, 0.16666666666666667, 0.16666666666666667},
  }};
  static const std::array<QuadPoint, 6> degree4{{
      {0.10810301816807023, 0.44594849091596489, 0.11169079483900573},
      {0.44594849091596489, 0.10810301816807023, 0.11169079483900573},
      {0.44594849091596489, 0.44594849091596489, 0.11169079483900573},
      {0.091576213509770743, 0.091576213509770743, 0.054975871827660934},
      {0.091576213509770743, 0.81684757298045851, 0.054975871827660934},
      {0.81684757298045851, 0.091576213509770743, 0.054975871827660934},
  }};
  static const std::array<QuadPoint, 12> degree6{{
      {0.24928674517091042, 0.24928674517091042, 0.058393137863189683},
      {0.24928674517091042, 0.50142650965817916, 0.058393137863189683},
      {0.50142650965817916, 0.24928674517091042, 0.058393137863189683},
      {0.053145049844816947, 0.31035245103378441, 0.041425537809186788},
      {0.053145049844816947, 0.63650249912139865, 0.041425537809186788},
      {0.31035245103378441, 0.053145049844816947, 0.041425537809186788},
      {0.31035245103378441, 0.63650249912139865, 0.041425537809186788},
      {0.63650249912139865, 0.053145049844816947, 0.041425537809186788},
      {0.63650249912139865, 0.31035245103378441, 0.041425537809186788},
      {0.063089014491502228, 0.063089014491502228, 0.025422453185103408},
      {0.063089014491502228, 0.87382197101699554, 0.025422453185103408},
      {0.87382197101699554, 0.063089014491502228, 0.025422453185103408},
  }};
  if (degree <= 2) return degree2;
  if (degree <= 4) return degree4;
  if (degree <= 6) return degree6;
  return {};
}

int facet_control_points(const Facet& f, std::span<const Vec3> x, std::array<Vec3, 9>& out) {
  auto X = [&](int a) -> const Vec3& { return x[static_cast<std::size_t>(f.nodes[a])]; };
  const int nc = facet_n_corners(f.shape);
  for (int a = 0; a < nc; ++a) out[a] = X(a);
  if (!facet_is_quadratic(f.shape)) return nc;
  // Edge control point of a quadratic edge through c_i, m, c_j: 2 m − (c_i + c_j)/2.
  const int n_edges = nc == 2 ? 1 : nc;
  for (int m = 0; m < n_edges; ++m) {
    const Vec3 mid = X(nc + m);
    const Vec3 ci = X(m), cj = X((m + 1) % nc);
    for (int k = 0; k < 3; ++k) out[nc + m][k] = 2 * mid[k] - 0.5 * (ci[k] + cj[k]);
  }
  if (f.shape != FacetShape::Quad8) return nc + n_edges;
  Vec3 centre{};
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) centre[k] += X(4 + a)[k] - 0.75 * X(a)[k];
  out[8] = centre;
  return 9;
}

}  // namespace inpact::contact
