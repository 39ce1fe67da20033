#include "face_loads.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "beam_section.hpp"
#include "line_elements.hpp"
#include "quadrature.hpp"
#include "shape_functions.hpp"

namespace inpact::solver::elements {

using model::ElementFamily;

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Calls visit(N (face-local), n dA (outward, measure included)) at each face quadrature point.
template <class Visit>
void integrate_face(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int face,
                    const SectionData& section, Visit&& visit) {
  if (face < 0 || face >= static_cast<int>(type.faces.size()))
    throw std::invalid_argument("integrate_face: face index out of range");
  const model::FaceDef& fd = type.faces[face];
  const Shape fs = face_shape(fd.n_nodes, fd.n_corners);
  const bool axi = type.family == ElementFamily::Axisymmetric;
  // N (degree ≤ 2) × the area factor (degree ≤ 2 on a quadratic face, +1 for the CAX radius).
  const int order = 2 * type.order + (axi ? 1 : 0);
  for (const QuadraturePoint& q : face_rule(fs, order)) {
    const ShapeValues sv = evaluate_shape(fs, q.xi);
    Vec3 x{}, ts{}, tt{};
    for (int a = 0; a < fd.n_nodes; ++a) {
      const Vec3& X = coords[fd.nodes[a]];
      for (int i = 0; i < 3; ++i) {
        x[i] += sv.N[a] * X[i];
        ts[i] += sv.dN[a][0] * X[i];
        tt[i] += sv.dN[a][1] * X[i];
      }
    }
    Vec3 nda{};
    if (type.dim == 3) {
      const Vec3 c = cross(ts, tt);  // points into the solid
      nda = {-c[0] * q.weight, -c[1] * q.weight, -c[2] * q.weight};
    } else {
      const double m = type.family == ElementFamily::Axisymmetric ? 2 * std::numbers::pi * x[0] : section.thickness;
      nda = {ts[1] * q.weight * m, -ts[0] * q.weight * m, 0.0};  // edge direction rotated clockwise
    }
    visit(sv, nda);
  }
}

}  // namespace

std::vector<double> pressure_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int face,
                                  double p, const SectionData& section) {
  std::vector<double> f(static_cast<std::size_t>(type.n_nodes) * type.dim, 0.0);
  if (face < 0 || face >= static_cast<int>(type.faces.size()))
    throw std::invalid_argument("pressure_load: face index out of range");
  const model::FaceDef& fd = type.faces[static_cast<std::size_t>(face)];
  integrate_face(type, coords, face, section, [&](const ShapeValues& sv, const Vec3& nda) {
    for (int a = 0; a < fd.n_nodes; ++a)
      for (int i = 0; i < type.dim; ++i) f[static_cast<std::size_t>(fd.nodes[a]) * type.dim + i] -= sv.N[a] * p * nda[i];
  });
  return f;
}

namespace {

Vec3 unit(const Vec3& v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}

/// The force per unit length of `traction` at an edge point with unit tangent t (the element's
/// node order) and unit shell normal n: t × n points out of the element in its plane.
Vec3 edge_traction_vector(model::EdgeTraction traction, const Vec3& t, const Vec3& n, double q) {
  switch (traction) {
    case model::EdgeTraction::Normal: {
      const Vec3 out = cross(t, n);
      return {-q * out[0], -q * out[1], -q * out[2]};
    }
    case model::EdgeTraction::Shear: return {q * t[0], q * t[1], q * t[2]};
    case model::EdgeTraction::Transverse: return {-q * n[0], -q * n[1], -q * n[2]};
  }
  return {0, 0, 0};
}

}  // namespace

std::vector<double> edge_traction_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int edge,
                                       model::EdgeTraction traction, double q) {
  if (edge < 0 || edge >= static_cast<int>(type.edges.size()))
    throw std::invalid_argument("edge_traction_load: edge index out of range");
  const model::FaceDef& ed = type.edges[static_cast<std::size_t>(edge)];
  const Shape shape = element_shape(type);
  const auto from = node_parametric_coords(shape, ed.nodes[0]);
  const auto to = node_parametric_coords(shape, ed.nodes[1]);
  std::vector<double> f(static_cast<std::size_t>(type.n_nodes) * 3, 0.0);
  // The edge point at s ∈ [−1, 1] lies at ξ(s) = ((1 − s) from + (1 + s) to) / 2 of the element;
  // the element's own shape functions vanish there for the nodes off the edge.
  for (const auto& [s, w] : gauss_legendre(3)) {
    std::array<double, 3> xi{};
    for (int j = 0; j < 2; ++j) xi[j] = 0.5 * ((1 - s) * from[j] + (1 + s) * to[j]);
    const ShapeValues sv = evaluate_shape(shape, xi);
    Vec3 g1{0, 0, 0}, g2{0, 0, 0}, dx_ds{0, 0, 0};
    for (int a = 0; a < type.n_nodes; ++a)
      for (int i = 0; i < 3; ++i) {
        g1[i] += sv.dN[a][0] * coords[a][i];
        g2[i] += sv.dN[a][1] * coords[a][i];
        dx_ds[i] += 0.5 * (sv.dN[a][0] * (to[0] - from[0]) + sv.dN[a][1] * (to[1] - from[1])) * coords[a][i];
      }
    const double length = std::sqrt(dx_ds[0] * dx_ds[0] + dx_ds[1] * dx_ds[1] + dx_ds[2] * dx_ds[2]);
    const Vec3 traction_per_length = edge_traction_vector(traction, unit(dx_ds), unit(cross(g1, g2)), q);
    for (int a = 0; a < type.n_nodes; ++a)
      for (int i = 0; i < 3; ++i)
        f[static_cast<std::size_t>(a) * 3 + i] += sv.N[a] * traction_per_length[i] * length * w;
  }
  return f;
}

double face_area(const model::ElementTypeInfo& type, std::span<const Vec3> coords, int face,
                 const SectionData& section) {
  double area = 0.0;
  integrate_face(type, coords, face, section, [&](const ShapeValues&, const Vec3& nda) {
    area += std::sqrt(nda[0] * nda[0] + nda[1] * nda[1] + nda[2] * nda[2]);
  });
  return area;
}

namespace {

/// Calls fn(N, x, dV) at every point of the element's full integration rule, x the point and dV
/// its volume element (× thickness in 2D, × 2πr for CAX). Loads use the full rule even for
/// reduced-integration types: the consistent load of a quadratic element needs it (Abaqus does
/// the same for loads).
template <class Fn>
void integrate_volume(const model::ElementTypeInfo& type, std::span<const Vec3> coords, const SectionData& section,
                      Fn&& fn) {
  const int dim = type.dim, n = type.n_nodes;
  if (type.family == ElementFamily::Truss || type.family == ElementFamily::Beam) {  // along the line: dV = A ds
    const double area = type.family == ElementFamily::Beam && section.beam ? section.beam->area : section.area;
    for (const TrussPoint& p : truss_points(type, coords, dim)) {
      ShapeValues sv;
      sv.n_nodes = n;
      sv.dim = 1;
      for (int a = 0; a < n; ++a) sv.N[a] = p.N[a];
      fn(sv, p.x, p.weight * p.J * area);
    }
    return;
  }
  const Shape shape = element_shape(type);
  model::ElementTypeInfo full = type;
  full.integration = model::Integration::Full;
  if (model::is_shell(type)) {  // over the reference surface: dV = t |g1 × g2| dA
    for (const QuadraturePoint& q : element_rule(full)) {
      const ShapeValues sv = evaluate_shape(shape, q.xi);
      Vec3 x{0, 0, 0}, g1{0, 0, 0}, g2{0, 0, 0};
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i)
          x[i] += sv.N[a] * coords[a][i], g1[i] += sv.dN[a][0] * coords[a][i], g2[i] += sv.dN[a][1] * coords[a][i];
      const Vec3 g{g1[1] * g2[2] - g1[2] * g2[1], g1[2] * g2[0] - g1[0] * g2[2], g1[0] * g2[1] - g1[1] * g2[0]};
      double t = section.thickness;  // *NODAL THICKNESS: interpolated, as the shell kernel does
      if (!section.nodal_thickness.empty()) {
        t = 0.0;
        for (int a = 0; a < n; ++a) t += sv.N[a] * section.nodal_thickness[a];
      }
      fn(sv, x, q.weight * std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * t);
    }
    return;
  }
  for (const QuadraturePoint& q : element_rule(full)) {
    const ShapeValues sv = evaluate_shape(shape, q.xi);
    double J[3][3] = {};
    Vec3 x{0, 0, 0};
    for (int a = 0; a < n; ++a) {
      for (int i = 0; i < 3; ++i) x[i] += sv.N[a] * coords[a][i];
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) J[i][j] += coords[a][i] * sv.dN[a][j];
    }
    double det = dim == 2 ? J[0][0] * J[1][1] - J[0][1] * J[1][0]
                          : J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                                J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                                J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    double dv = q.weight * det;
    if (type.family == ElementFamily::Axisymmetric) dv *= 2 * std::numbers::pi * x[0];
    else if (dim == 2) dv *= section.thickness;
    fn(sv, x, dv);
  }
}

}  // namespace

std::vector<double> body_force_load(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                                    const Vec3& b, const SectionData& section) {
  const int dim = type.dim, n = type.n_nodes;
  std::vector<double> f(static_cast<std::size_t>(n) * dim, 0.0);
  integrate_volume(type, coords, section, [&](const ShapeValues& sv, const Vec3&, double dv) {
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i) f[static_cast<std::size_t>(a) * dim + i] += sv.N[a] * b[i] * dv;
  });
  return f;
}

std::vector<VolumeMoments> volume_moments(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                                          const SectionData& section) {
  std::vector<VolumeMoments> m(static_cast<std::size_t>(type.n_nodes));
  integrate_volume(type, coords, section, [&](const ShapeValues& sv, const Vec3& x, double dv) {
    for (int a = 0; a < type.n_nodes; ++a) {
      auto& ma = m[static_cast<std::size_t>(a)];
      ma.volume += sv.N[a] * dv;
      for (int i = 0; i < 3; ++i) ma.first[i] += sv.N[a] * x[i] * dv;
    }
  });
  return m;
}

}  // namespace inpact::solver::elements
