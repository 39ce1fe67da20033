#include "line_elements.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "beam_elements.hpp"
#include "quadrature.hpp"

namespace inpact::solver::elements {

std::pair<double, double> SpringBehavior::force(double delta) const {
  if (table.empty()) return {stiffness * delta, stiffness};
  // Beyond the table the force is constant; on its end points the tangent is the end segment's
  // (a spring starting at the table's first point must not start without stiffness).
  if (delta < table.front()[1]) return {table.front()[0], 0.0};
  if (delta > table.back()[1]) return {table.back()[0], 0.0};
  std::size_t i = 1;
  while (i + 1 < table.size() && table[i][1] <= delta) ++i;  // table[i-1][1] <= delta <= table[i][1]
  const auto& a = table[i - 1];
  const auto& b = table[i];
  const double slope = (b[0] - a[0]) / (b[1] - a[1]);
  return {a[0] + slope * (delta - a[1]), slope};
}

namespace {

double dot(const Vec3& a, const Vec3& b, int dim) {
  double s = 0.0;
  for (int i = 0; i < dim; ++i) s += a[i] * b[i];
  return s;
}

/// One truss point: f_a += w A σ̂ dN_a v / J and K_ab += (w A / J) dN_a dN_b (C v vᵀ / J² + σ̂ I),
/// with v = t₀J, σ̂ = σ (small strain: no geometric term) or v = g = dx/dξ, σ̂ = S (NLGEOM).
void add_truss_point(const TrussPoint& p, int n, int dim, double area, const Vec3& v, double modulus, double stress,
                     bool geometric, ElementSystem& out) {
  const int n_dof = n * dim;
  const double wa = p.weight * area;
  for (int a = 0; a < n && !out.internal_force.empty(); ++a)
    for (int i = 0; i < dim; ++i) out.internal_force[a * dim + i] += wa * stress * p.dN[a] * v[i] / p.J;
  if (out.stiffness.empty()) return;
  const double j3 = p.J * p.J * p.J;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) {
          double k = wa * modulus * p.dN[a] * p.dN[b] * v[i] * v[j] / j3;
          if (geometric && i == j) k += wa * stress * p.dN[a] * p.dN[b] / p.J;
          out.stiffness[static_cast<std::size_t>(a * dim + i) * n_dof + b * dim + j] += k;
        }
}

void compute_truss(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u, int dim,
                   const ElasticConstants& material, const SectionData& section, const ElementRequest& request,
                   std::span<const double> delta_t, ElementSystem& out) {
  const int n = type.n_nodes;
  begin_element_system(out, n * dim, request);
  const std::vector<TrussPoint> pts = truss_points(type, coords, dim);
  out.min_jacobian = 1e300;
  for (const TrussPoint& p : pts) out.min_jacobian = std::min(out.min_jacobian, p.J);
  if (out.min_jacobian <= 0.0) return;  // a truss of zero length: the caller reports it
  const double E = material.youngs_modulus;
  for (const TrussPoint& p : pts) {
    Vec3 du{0, 0, 0};
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i) du[i] += p.dN[a] * u[a * dim + i];
    double thermal = 0.0;
    if (!delta_t.empty())
      for (int a = 0; a < n; ++a) thermal += p.N[a] * material.expansion * delta_t[a];
    PointResult r;
    r.coords = p.x;
    r.volume = p.weight * p.J * section.area;
    if (!request.nlgeom) {
      const double strain = dot(p.tangent, du, dim) / (p.J * p.J);  // t₀·∂u/∂s, t₀ = tangent / J
      const double stress = E * (strain - thermal);
      add_truss_point(p, n, dim, section.area, p.tangent, E, stress, false, out);
      r.stress[0] = stress, r.strain[0] = strain;
    } else {
      Vec3 g = p.tangent;
      for (int i = 0; i < dim; ++i) g[i] += du[i];
      const double l2 = dot(g, g, dim), L2 = p.J * p.J;
      const double S = E * ((l2 - L2) / (2 * L2) - thermal);  // second Piola–Kirchhoff
      add_truss_point(p, n, dim, section.area, g, E, S, true, out);
      const double stretch = std::sqrt(l2 / L2);
      r.stress[0] = stretch * S, r.strain[0] = std::log(stretch);
    }
    r.section[0] = section.area * r.stress[0];
    if (request.point_output) out.points.push_back(r);
  }
}

/// SPRINGA: along the line joining the nodes (NLGEOM: the current line).
void compute_axial_spring(std::span<const Vec3> coords, std::span<const double> u, int dim, const SpringBehavior& s,
                          const ElementRequest& request, ElementSystem& out) {
  Vec3 d{0, 0, 0};
  for (int i = 0; i < dim; ++i) d[i] = coords[1][i] - coords[0][i];
  const double L = std::sqrt(dot(d, d, dim));
  Vec3 x = d;
  if (request.nlgeom)
    for (int i = 0; i < dim; ++i) x[i] += u[dim + i] - u[i];
  const double l = std::sqrt(dot(x, x, dim));
  const Vec3& line = request.nlgeom && l > 0.0 ? x : d;
  const double len = request.nlgeom && l > 0.0 ? l : L;
  Vec3 nv{0, 0, 0};
  for (int i = 0; i < dim; ++i) nv[i] = len > 0.0 ? line[i] / len : 0.0;
  double delta = request.nlgeom ? l - L : 0.0;
  if (!request.nlgeom)
    for (int i = 0; i < dim; ++i) delta += nv[i] * (u[dim + i] - u[i]);
  const auto [F, kt] = s.force(delta);
  const int n_dof = 2 * dim;
  for (int i = 0; i < dim && !out.internal_force.empty(); ++i) {
    out.internal_force[i] = -F * nv[i];
    out.internal_force[dim + i] = F * nv[i];
  }
  for (int i = 0; i < dim && !out.stiffness.empty(); ++i)
    for (int j = 0; j < dim; ++j) {
      double k = kt * nv[i] * nv[j];
      if (request.nlgeom && len > 0.0) k += F / len * ((i == j ? 1.0 : 0.0) - nv[i] * nv[j]);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          out.stiffness[static_cast<std::size_t>(a * dim + i) * n_dof + b * dim + j] += (a == b ? k : -k);
    }
  PointResult r;
  for (int i = 0; i < 3; ++i) r.coords[i] = 0.5 * (coords[0][i] + coords[1][i]);
  r.stress[0] = F, r.strain[0] = delta;
  if (request.point_output) out.points.push_back(r);
}

/// SPRING1 (node to ground, DOF dof1) and SPRING2 (dof2 of node 2 against dof1 of node 1).
void compute_dof_spring(std::span<const Vec3> coords, std::span<const double> u, int dim, const SpringBehavior& s,
                        bool two_nodes, const ElementRequest& request, ElementSystem& out) {
  if (s.dof1 >= dim || (two_nodes && s.dof2 >= dim))
    throw std::invalid_argument("compute_line_element: spring DOF beyond the model's");
  const int a = s.dof1, b = two_nodes ? dim + s.dof2 : -1;
  const double delta = two_nodes ? u[b] - u[a] : u[a];
  const auto [F, kt] = s.force(delta);
  const int n_dof = static_cast<int>(u.size());
  if (!out.internal_force.empty()) {
    out.internal_force[a] += two_nodes ? -F : F;
    if (two_nodes) out.internal_force[b] += F;
  }
  if (!out.stiffness.empty()) {
    out.stiffness[static_cast<std::size_t>(a) * n_dof + a] += kt;
    if (two_nodes) {
      out.stiffness[static_cast<std::size_t>(b) * n_dof + b] += kt;
      out.stiffness[static_cast<std::size_t>(a) * n_dof + b] -= kt;
      out.stiffness[static_cast<std::size_t>(b) * n_dof + a] -= kt;
    }
  }
  PointResult r;
  for (int i = 0; i < 3; ++i) r.coords[i] = two_nodes ? 0.5 * (coords[0][i] + coords[1][i]) : coords[0][i];
  r.stress[0] = F, r.strain[0] = delta;
  if (request.point_output) out.points.push_back(r);
}

}  // namespace

std::vector<TrussPoint> truss_points(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int dim) {
  const int n = type.n_nodes;
  std::vector<TrussPoint> pts;
  for (const QuadraturePoint& q : element_rule(type)) {
    const double s = q.xi[0];
    TrussPoint p;
    if (n == 2) {
      p.N = {(1 - s) / 2, (1 + s) / 2, 0.0};
      p.dN = {-0.5, 0.5, 0.0};
    } else {  // end, middle, end at ξ = -1, 0, 1
      p.N = {s * (s - 1) / 2, 1 - s * s, s * (s + 1) / 2};
      p.dN = {s - 0.5, -2 * s, s + 0.5};
    }
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) {
        p.x[i] += p.N[a] * coords[a][i];
        if (i < dim) p.tangent[i] += p.dN[a] * coords[a][i];
      }
    p.J = std::sqrt(dot(p.tangent, p.tangent, dim));
    p.weight = q.weight;
    pts.push_back(p);
  }
  return pts;
}

void compute_line_element(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                          const ElasticConstants& material, const SectionData& section, const ElementRequest& request,
                          std::span<const double> delta_t, ElementSystem& out) {
  const std::size_t n = type.n_nodes;
  if (coords.size() != n || u.empty() || u.size() % n != 0 || (!delta_t.empty() && delta_t.size() != n))
    throw std::invalid_argument("compute_line_element: coordinate, displacement or temperature count mismatch");
  const int dim = static_cast<int>(u.size() / n);
  if (type.family == model::ElementFamily::Beam) {
    if (!section.beam) throw std::invalid_argument("compute_line_element: a beam without its section");
    compute_beam(type, coords, u, *section.beam, request, out);
    return;
  }
  if (type.family == model::ElementFamily::Truss) {
    compute_truss(type, coords, u, dim, material, section, request, delta_t, out);
    return;
  }
  if (!section.spring) throw std::invalid_argument("compute_line_element: a spring without its *SPRING behaviour");
  begin_element_system(out, static_cast<int>(u.size()), request);
  out.min_jacobian = 1.0;
  if (type.name == std::string_view("SPRINGA")) compute_axial_spring(coords, u, dim, *section.spring, request, out);
  else compute_dof_spring(coords, u, dim, *section.spring, n == 2, request, out);
}

}  // namespace inpact::solver::elements
