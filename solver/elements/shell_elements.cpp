#include "shell_elements.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "corotation.hpp"
#include "material.hpp"
#include "quadrature.hpp"
#include "shape_functions.hpp"

namespace inpact::solver::elements {

namespace {

constexpr int kMaxDof = 48;  // S8R: 8 nodes × 6
using Row = std::array<double, kMaxDof>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

/// The element's geometry: node coordinates, directors and thicknesses, offset.
struct Geometry {
  Shape shape;
  int n = 0;
  std::span<const Vec3> x;
  std::array<Vec3, 8> director{};
  std::array<double, 8> thickness{};  ///< at each node: the section's, or *NODAL THICKNESS's
  double offset = 0.0;
  int n_dof() const { return 6 * n; }
  int rot(int a) const { return 3 * (n + a); }  // first rotation DOF of node a
  double mean_thickness() const {
    double sum = 0.0;
    for (int a = 0; a < n; ++a) sum += thickness[a];
    return sum / n;
  }
};

/// The covariant strains at a point (ξ, η, ζ) as rows over the element's DOFs: 2e_ij = g_i·u,j +
/// g_j·u,i for ij = 11, 22, 12, 13, 23 (the two last engineering, doubled like the third).
struct CovariantPoint {
  std::array<Vec3, 3> g{};  ///< g1 = ∂X/∂ξ, g2 = ∂X/∂η, g3 = ∂X/∂ζ
  Vec3 x{};                 ///< the point
  double det = 0.0;         ///< g1 · (g2 × g3)
  std::array<double, 8> N{};
  std::array<Row, 5> rows{};
};

CovariantPoint covariant_point(const Geometry& geo, double xi, double eta, double zeta) {
  CovariantPoint p;
  const ShapeValues sv = evaluate_shape(geo.shape, {xi, eta, 0.0});
  for (int a = 0; a < geo.n; ++a) {
    p.N[a] = sv.N[a];
    const double z = geo.thickness[a] * (zeta / 2 - geo.offset), half = geo.thickness[a] / 2;
    for (int i = 0; i < 3; ++i) {
      const double xa = geo.x[a][i] + z * geo.director[a][i];
      p.g[0][i] += sv.dN[a][0] * xa;
      p.g[1][i] += sv.dN[a][1] * xa;
      p.g[2][i] += sv.N[a] * half * geo.director[a][i];
      p.x[i] += sv.N[a] * xa;
    }
  }
  p.det = dot(p.g[0], cross(p.g[1], p.g[2]));
  for (Row& r : p.rows) r.fill(0.0);
  auto& [e11, e22, e12, e13, e23] = p.rows;
  for (int a = 0; a < geo.n; ++a) {
    const double d1 = sv.dN[a][0], d2 = sv.dN[a][1], na = sv.N[a];
    const double z = geo.thickness[a] * (zeta / 2 - geo.offset), half = geo.thickness[a] / 2;
    // d(θ × V)/dθ_k = e_k × V, so g · d(θ × V)/dθ_k = (V × g)_k.
    const Vec3 c1 = cross(geo.director[a], p.g[0]), c2 = cross(geo.director[a], p.g[1]),
               c3 = cross(geo.director[a], p.g[2]);
    for (int k = 0; k < 3; ++k) {
      const int t = 3 * a + k, r = geo.rot(a) + k;
      e11[t] = d1 * p.g[0][k];
      e22[t] = d2 * p.g[1][k];
      e12[t] = d2 * p.g[0][k] + d1 * p.g[1][k];
      e13[t] = d1 * p.g[2][k];
      e23[t] = d2 * p.g[2][k];
      e11[r] = d1 * z * c1[k];
      e22[r] = d2 * z * c2[k];
      e12[r] = z * (d2 * c1[k] + d1 * c2[k]);
      e13[r] = na * half * c1[k] + d1 * z * c3[k];
      e23[r] = na * half * c2[k] + d2 * z * c3[k];
    }
  }
  return p;
}

void blend(Row& out, double wa, const Row& a, double wb, const Row& b, int n_dof) {
  for (int j = 0; j < n_dof; ++j) out[j] = wa * a[j] + wb * b[j];
}

/// Replaces the transverse shear rows by the assumed strains of MITC4 (tied at the edge
/// midpoints) or MITC3; S8R, S8 and S6 keep theirs.
void tie_transverse_shear(const Geometry& geo, double xi, double eta, double zeta, CovariantPoint& p) {
  const int nd = geo.n_dof();
  if (geo.shape == Shape::Quad4) {
    const CovariantPoint a = covariant_point(geo, 0, 1, zeta), c = covariant_point(geo, 0, -1, zeta);
    const CovariantPoint b = covariant_point(geo, -1, 0, zeta), d = covariant_point(geo, 1, 0, zeta);
    blend(p.rows[3], 0.5 * (1 + eta), a.rows[3], 0.5 * (1 - eta), c.rows[3], nd);
    blend(p.rows[4], 0.5 * (1 + xi), d.rows[4], 0.5 * (1 - xi), b.rows[4], nd);
  } else if (geo.shape == Shape::Tri3) {
    // e_rt = e_rt¹ + c s, e_st = e_st² − c r, c = e_rt³ − e_rt¹ − e_st³ + e_st², tied at
    // (½, 0), (0, ½) and (½, ½): the tangential shear is constant along each edge.
    const CovariantPoint p1 = covariant_point(geo, 0.5, 0, zeta), p2 = covariant_point(geo, 0, 0.5, zeta);
    const CovariantPoint p3 = covariant_point(geo, 0.5, 0.5, zeta);
    for (int j = 0; j < nd; ++j) {
      const double c = p3.rows[3][j] - p1.rows[3][j] - p3.rows[4][j] + p2.rows[4][j];
      p.rows[3][j] = p1.rows[3][j] + c * eta;
      p.rows[4][j] = p2.rows[4][j] - c * xi;
    }
  }
}

/// The engineering strains (ε11, ε22, γ12, γ13, γ23) in the local axes from the covariant rows:
/// ε_ab = (e_a·g^i)(e_b·g^j) e_ij, e33 left out (plane stress).
std::array<Row, 5> local_strain_rows(const CovariantPoint& p, const std::array<Vec3, 3>& axes, int n_dof) {
  const std::array<Vec3, 3> contra = {scaled(cross(p.g[1], p.g[2]), 1 / p.det), scaled(cross(p.g[2], p.g[0]), 1 / p.det),
                                      scaled(cross(p.g[0], p.g[1]), 1 / p.det)};
  double T[3][3];  // T[a][i] = e_a · g^i
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 3; ++i) T[a][i] = dot(axes[a], contra[i]);
  // The tensor components e_ij as (row, factor) pairs: e_12 = E12/2 and so on.
  auto covariant = [&](int i, int j, int dof) {
    if (i > j) std::swap(i, j);
    if (i == j) return i == 2 ? 0.0 : p.rows[i][dof];
    const int r = (i == 0 && j == 1) ? 2 : (i == 0) ? 3 : 4;
    return 0.5 * p.rows[r][dof];
  };
  constexpr int pairs[5][2] = {{0, 0}, {1, 1}, {0, 1}, {0, 2}, {1, 2}};
  std::array<Row, 5> out{};
  for (int c = 0; c < 5; ++c) {
    const int a = pairs[c][0], b = pairs[c][1];
    const double factor = a == b ? 1.0 : 2.0;
    for (int dof = 0; dof < n_dof; ++dof) {
      double s = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (T[a][i] != 0.0 && T[b][j] != 0.0) s += T[a][i] * T[b][j] * covariant(i, j, dof);
      out[c][dof] = factor * s;
    }
  }
  return out;
}

/// The lamina at one section point: its stress (σ11, σ22, τ12, τ13, τ23) and tangent, the
/// in-plane 3 × 3 block and the transverse shear moduli (elastic: Abaqus's shells too).
struct LaminaPoint {
  std::array<double, 5> stress{};
  Matrix3x3 in_plane{};
  Matrix2x2 shear{};
};

/// The elastic lamina (in the shell's local axes): plane stress with the thermal strain taken
/// off e11 and e22.
LaminaPoint elastic_lamina(const ShellLamina& lamina, std::array<double, 5> e, double thermal,
                           const Matrix2x2& shear) {
  LaminaPoint l;
  e[0] -= thermal, e[1] -= thermal;
  const Matrix3x3& q = lamina.in_plane;
  for (int a = 0; a < 3; ++a) l.stress[a] = q[a][0] * e[0] + q[a][1] * e[1] + q[a][2] * e[2];
  for (int a = 0; a < 2; ++a) l.stress[3 + a] = shear[a][0] * e[3] + shear[a][1] * e[4];
  l.in_plane = q;
  l.shear = shear;
  return l;
}

/// A lamina of a material law (plane-stress Mises plasticity, or elasticity with temperature
/// tables; shell_element_setup.cpp):
/// the law at the in-plane strains (ε11, ε22, γ12; it finds ε33 for σ33 = 0), from the point's
/// committed state into its trial state; the transverse shear elastic.
LaminaPoint material_lamina(const Material& law, const std::array<double, 5>& e, double thermal, double temperature,
                            const Vec3& position, const Matrix2x2& shear, const PointHistory& history) {
  static const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Vec6 strain = (Vec6() << e[0], e[1], 0.0, e[2], 0.0, 0.0).finished();
  Vec6 stress;
  Mat6 scratch;
  const Mat6& d = law.update({identity, strain, thermal, &position, false, temperature}, history, stress, scratch);
  constexpr int in_plane[3] = {0, 1, 3};
  LaminaPoint l;
  l.stress = {stress[0], stress[1], stress[3], shear[0][0] * e[3] + shear[0][1] * e[4],
              shear[1][0] * e[3] + shear[1][1] * e[4]};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) l.in_plane[a][b] = d(in_plane[a], in_plane[b]);
  l.shear = shear;
  return l;
}

/// A point's history as its law keeps it: the first state_size() values of the element's slot
/// (a COMPOSITE's elastic layer with temperature tables keeps none beside a plastic layer).
PointHistory law_history(const ElementHistory& history, std::size_t point, const Material& law) {
  const PointHistory all = history.at(point);
  const std::size_t size = std::min(law.state_size(), all.committed.size());
  return {all.committed.first(size), all.trial.first(size)};
}

/// D B: the lamina's tangent applied to each column of the strain rows.
void lamina_tangent_rows(const LaminaPoint& l, const std::array<Row, 5>& b, int n_dof, std::array<Row, 5>& db) {
  for (int j = 0; j < n_dof; ++j) {
    for (int a = 0; a < 3; ++a) db[a][j] = l.in_plane[a][0] * b[0][j] + l.in_plane[a][1] * b[1][j] + l.in_plane[a][2] * b[2][j];
    db[3][j] = l.shear[0][0] * b[3][j] + l.shear[0][1] * b[4][j];
    db[4][j] = l.shear[1][0] * b[3][j] + l.shear[1][1] * b[4][j];
  }
}

/// The drilling row of node a, r_a = V_a·θ_a − ω_a, ω_a the membrane rotation about V_a at the
/// node, ½(e2·∂u/∂x1 − e1·∂u/∂x2) in the node's shell axes. A rigid rotation ω gives ω_a = ω·V_a
/// (the interpolation reproduces u = ω × X, whose tangent plane at the node is normal to V_a),
/// so it costs nothing, flat or curved.
bool drilling_row(const Geometry& geo, int a, Row& r) {
  const ShapeValues sv = evaluate_shape(geo.shape, node_parametric_coords(geo.shape, a));
  Vec3 g1{}, g2{};
  for (int b = 0; b < geo.n; ++b)
    for (int i = 0; i < 3; ++i) g1[i] += sv.dN[b][0] * geo.x[b][i], g2[i] += sv.dN[b][1] * geo.x[b][i];
  std::array<Vec3, 3> axes;
  if (!shell_axes(g1, g2, axes)) return false;
  const Vec3 n = cross(g1, g2);
  const double jn = dot(n, n);
  const Vec3 c1 = scaled(cross(g2, n), 1 / jn), c2 = scaled(cross(n, g1), 1 / jn);  // in-plane g^1, g^2
  const int nd = geo.n_dof();
  std::fill(r.begin(), r.begin() + nd, 0.0);
  for (int b = 0; b < geo.n; ++b) {
    // ∂u/∂x_m = Σ_b (dN_b/dξ_i g^i·e_m) u_b
    const double dx1 = sv.dN[b][0] * dot(axes[0], c1) + sv.dN[b][1] * dot(axes[0], c2);
    const double dx2 = sv.dN[b][0] * dot(axes[1], c1) + sv.dN[b][1] * dot(axes[1], c2);
    for (int k = 0; k < 3; ++k) r[3 * b + k] = -0.5 * (axes[1][k] * dx1 - axes[0][k] * dx2);
  }
  for (int k = 0; k < 3; ++k) r[geo.rot(a) + k] += geo.director[a][k];
  return true;
}

/// k_d Σ_a r_a² / 2 added to the stiffness and the internal force.
void add_drilling(const Geometry& geo, double k_drill, std::span<const double> u, ElementSystem& out) {
  const int nd = geo.n_dof();
  Row r{};
  for (int a = 0; a < geo.n; ++a) {
    if (!drilling_row(geo, a, r)) continue;
    double value = 0.0;
    for (int j = 0; j < nd; ++j) value += r[j] * u[j];
    for (int i = 0; i < nd && !out.internal_force.empty(); ++i) out.internal_force[i] += k_drill * r[i] * value;
    for (int i = 0; i < nd && !out.stiffness.empty(); ++i) {
      if (r[i] == 0.0) continue;
      for (int j = 0; j < nd; ++j) out.stiffness[static_cast<std::size_t>(i * nd + j)] += k_drill * r[i] * r[j];
    }
  }
}

/// The directors: the element's unit normal at each node; false where it vanishes.
bool nodal_directors(Geometry& geo) {
  for (int a = 0; a < geo.n; ++a) {
    const ShapeValues sv = evaluate_shape(geo.shape, node_parametric_coords(geo.shape, a));
    Vec3 g1{}, g2{};
    for (int b = 0; b < geo.n; ++b)
      for (int i = 0; i < 3; ++i) g1[i] += sv.dN[b][0] * geo.x[b][i], g2[i] += sv.dN[b][1] * geo.x[b][i];
    const Vec3 v = cross(g1, g2);
    const double l = norm(v);
    if (!(l > 0.0)) return false;
    geo.director[a] = scaled(v, 1 / l);
  }
  return true;
}

}  // namespace

bool shell_nodal_normals(const model::ElementTypeInfo& type, std::span<const Vec3> coords,
                         std::array<Vec3, 8>& normals) {
  Geometry geo{element_shape(type), type.n_nodes, coords, {}, {}, 0.0};
  if (!nodal_directors(geo)) return false;
  normals = geo.director;
  return true;
}

bool shell_axes(const Vec3& g1, const Vec3& g2, std::array<Vec3, 3>& axes) {
  Vec3 n = cross(g1, g2);
  const double l = norm(n);
  if (!(l > 0.0)) return false;
  n = scaled(n, 1 / l);
  // Abaqus: the projection of global x, or of global z when x is within 0.1° of the normal.
  const Vec3 ex{1, 0, 0}, ez{0, 0, 1};
  const Vec3& ref = std::abs(n[0]) > std::cos(0.1 * 3.14159265358979323846 / 180) ? ez : ex;
  Vec3 e1{ref[0] - dot(ref, n) * n[0], ref[1] - dot(ref, n) * n[1], ref[2] - dot(ref, n) * n[2]};
  e1 = scaled(e1, 1 / norm(e1));
  axes = {e1, cross(n, e1), n};
  return true;
}

namespace {

/// The transverse shear moduli at a section point of the lamina `here` (turned into the local
/// axes): *TRANSVERSE SHEAR STIFFNESS's K/t, else 5/6 of the lamina's own.
Matrix2x2 transverse_shear_moduli(const ShellProperties& section, const ShellLamina& here, double thickness,
                                  const Material* law, double initial_temperature) {
  if (section.transverse_shear)
    return {{{(*section.transverse_shear)[0] / thickness, 0.0}, {0.0, (*section.transverse_shear)[1] / thickness}}};
  Matrix2x2 g = here.shear;
  // An isotropic law with temperature tables: G at the point's initial temperature, as Abaqus
  // sizes a section's derived stiffnesses from the initial elastic properties.
  if (law && law->temperature_dependent()) {
    const double g_here = law->elastic_at(initial_temperature).shear_modulus();
    g = {{{g_here, 0.0}, {0.0, g_here}}};
  }
  for (auto& row : g)
    for (double& v : row) v *= 5.0 / 6;
  return g;
}

/// The thickness at the in-plane point (ξ, η), interpolated from the nodes'.
double point_thickness(const Geometry& geo, double xi, double eta) {
  const ShapeValues sv = evaluate_shape(geo.shape, {xi, eta, 0.0});
  double t = 0.0;
  for (int a = 0; a < geo.n; ++a) t += sv.N[a] * geo.thickness[a];
  return t;
}

/// The geometry of the element with its nodes' thicknesses; false for a thickness not positive.
bool shell_geometry(const model::ElementTypeInfo& type, std::span<const Vec3> coords, const ShellNodeData& at_nodes,
                    double offset, Geometry& geo) {
  geo = Geometry{element_shape(type), type.n_nodes, coords, {}, {}, offset};
  if (!at_nodes.nodal.empty() && static_cast<int>(at_nodes.nodal.size()) != geo.n)
    throw std::invalid_argument("compute_shell: one nodal thickness per node");
  for (int a = 0; a < geo.n; ++a) {
    geo.thickness[a] = at_nodes.nodal.empty() ? at_nodes.uniform : at_nodes.nodal[a];
    if (!(geo.thickness[a] > 0.0)) return false;
  }
  return true;
}

/// N and M (N11, N22, N12, M11, M22, M12, in the shell's default axes at `mid`) turned into the
/// axes of the section's orientation there.
std::array<double, 6> section_force_in_section_axes(const ShellProperties& section, const CovariantPoint& mid,
                                                    const std::array<double, 6>& in_default_axes) {
  std::array<Vec3, 3> axes;
  if (!shell_axes(mid.g[0], mid.g[1], axes)) return in_default_axes;
  const double theta = orientation_angle(section.orientation, axes, mid.x);
  const auto& f = in_default_axes;
  const std::array<double, 5> n = stresses_in_material_axes({f[0], f[1], f[2], 0.0, 0.0}, theta);
  const std::array<double, 5> m = stresses_in_material_axes({f[3], f[4], f[5], 0.0, 0.0}, theta);
  return {n[0], n[1], n[2], m[0], m[1], m[2]};
}

/// The small-strain shell (shell_elements.hpp).
void compute_shell_small(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                         const ShellProperties& section, const ShellNodeData& at_nodes,
                         const ElementRequest& request, std::span<const double> delta_t,
                         const ShellMaterial& material, ElementSystem& out) {
  Geometry geo;
  const bool thick = shell_geometry(type, coords, at_nodes, section.offset, geo);
  const int nd = geo.n_dof();
  if (static_cast<int>(coords.size()) != geo.n || static_cast<int>(u.size()) != nd)
    throw std::invalid_argument("compute_shell: coordinate or displacement count mismatch");
  if (!delta_t.empty() && delta_t.size() != coords.size() && delta_t.size() != 2 * coords.size())
    throw std::invalid_argument("compute_shell: one temperature change per node (and one gradient change)");
  begin_element_system(out, nd, request);
  out.min_jacobian = 0.0;
  if (!nodal_directors(geo) || !thick) return;  // degenerate: the caller reports it
  for (std::size_t a = 0; a < at_nodes.directors.size(); ++a) geo.director[a] = at_nodes.directors[a];
  out.min_jacobian = 1e300;
  std::array<Row, 5> db{};
  const std::vector<QuadraturePoint>& rule = element_rule(type);
  for (std::size_t iq = 0; iq < rule.size(); ++iq) {
    const QuadraturePoint& q = rule[iq];
    const double xi = q.xi[0], eta = q.xi[1];
    const double t_here = point_thickness(geo, xi, eta);
    std::array<double, 6> section_force{};  // N11, N22, N12, M11, M22, M12
    const std::size_t first_reported = out.points.size();  // every section point, from SNEG up
    double temperature = 0.0, gradient = 0.0;  // ΔT on the reference surface and Δ(∂T/∂n) here
    double reference_t = 0.0, reference_g = 0.0;  // T itself and ∂T/∂n, for temperature-dependent data
    for (std::size_t k = 0; k < section.zeta.size(); ++k) {
      const double zeta = section.zeta[k];
      CovariantPoint p = covariant_point(geo, xi, eta, zeta);
      out.min_jacobian = std::min(out.min_jacobian, p.det);
      if (!(p.det > 0.0)) {
        out.points.resize(first_reported);  // no partial set of section points
        return;
      }
      if (k == 0 && !delta_t.empty())
        for (int a = 0; a < geo.n; ++a) {
          temperature += p.N[a] * delta_t[static_cast<std::size_t>(a)];
          if (delta_t.size() > static_cast<std::size_t>(geo.n))
            gradient += p.N[a] * delta_t[static_cast<std::size_t>(geo.n + a)];
        }
      if (k == 0 && !request.temperature.empty())
        for (int a = 0; a < geo.n; ++a) {
          reference_t += p.N[a] * request.temperature[static_cast<std::size_t>(a)];
          if (request.temperature.size() > static_cast<std::size_t>(geo.n))
            reference_g += p.N[a] * request.temperature[static_cast<std::size_t>(geo.n + a)];
        }
      // At the section point, z from the reference surface along the director (the kernel's
      // z(ζ) = t (ζ/2 − offset)).
      const double z = t_here * (zeta / 2 - geo.offset);
      const double at_point = temperature + z * gradient, temperature_here = reference_t + z * reference_g;
      tie_transverse_shear(geo, xi, eta, zeta, p);
      std::array<Vec3, 3> axes;
      if (!shell_axes(p.g[0], p.g[1], axes)) {
        out.min_jacobian = 0.0;
        out.points.resize(first_reported);
        return;
      }
      const std::array<Row, 5> b = local_strain_rows(p, axes, nd);
      std::array<double, 5> strain{};
      for (int c = 0; c < 5; ++c)
        for (int j = 0; j < nd; ++j) strain[c] += b[c][j] * u[j];
      const std::size_t point = iq * section.zeta.size() + k;
      const ShellLayerProperties& layer = section.layer_at(k);
      const Material* law = section.law_at(k, material.law);
      const double theta = material_angle(layer, axes, p.x);
      const ShellLamina here = turned_lamina(layer.lamina, theta);
      const double thermal = law ? law->thermal_strain(temperature_here, at_point) : here.expansion * at_point;
      const Matrix2x2 shear = transverse_shear_moduli(section, here, t_here, law, temperature_here - at_point);
      const LaminaPoint lamina = law ? material_lamina(*law, strain, thermal, temperature_here, p.x, shear,
                                                       law_history(material.history, point, *law))
                                     : elastic_lamina(here, strain, thermal, shear);
      const std::array<double, 5>& stress = lamina.stress;
      const double dv = q.weight * section.weight[k] * p.det;
      for (int i = 0; i < nd && !out.internal_force.empty(); ++i)
        for (int c = 0; c < 5; ++c) out.internal_force[i] += dv * b[c][i] * stress[c];
      if (!out.stiffness.empty()) {
        lamina_tangent_rows(lamina, b, nd, db);
        for (int i = 0; i < nd; ++i)
          for (int c = 0; c < 5; ++c) {
            const double bic = dv * b[c][i];
            if (bic == 0.0) continue;
            double* row = &out.stiffness[static_cast<std::size_t>(i * nd)];
            for (int j = 0; j < nd; ++j) row[j] += bic * db[c][j];
          }
      }
      // Section forces per unit length: ∫ σ dz with dz = (t/2) dζ, moments about the midsurface.
      const double dz = section.weight[k] * t_here / 2, zm = zeta * t_here / 2;
      const double in_plane[3] = {stress[0], stress[1], stress[2]};
      for (int c = 0; c < 3; ++c) section_force[c] += in_plane[c] * dz, section_force[3 + c] += in_plane[c] * zm * dz;
      if (request.point_output) {
        // In the layer's material axes, as Abaqus reports an oriented or layered section.
        PointResult& r = out.points.emplace_back();
        r.coords = p.x;
        const std::array<double, 5> s_m = stresses_in_material_axes(stress, theta);
        const std::array<double, 5> e_m = strains_in_material_axes(strain, theta);
        r.stress = {s_m[0], s_m[1], 0.0, s_m[2], 0.0, 0.0};
        r.strain = {e_m[0], e_m[1], 0.0, e_m[2], 0.0, 0.0};
        if (law) law->plastic_output(law_history(material.history, point, *law).trial, r);
      }
    }
    if (!request.point_output) continue;
    const CovariantPoint mid = covariant_point(geo, xi, eta, 0.0);
    const double da = q.weight * norm(cross(mid.g[0], mid.g[1]));
    if (section.orientation) section_force = section_force_in_section_axes(section, mid, section_force);
    // Each section point stands for its Simpson share of t·dA: sums over the points (ALLSE,
    // centroids, the stabilisation's lumped mass) integrate through the thickness.
    for (std::size_t k = 0; k < section.zeta.size(); ++k) {
      out.points[first_reported + k].volume = da * t_here / 2 * section.weight[k];
      out.points[first_reported + k].section = section_force;
    }
  }
  add_drilling(geo, 1e-4 * section_bending_stiffness(section, geo.mean_thickness()), u, out);
}

}  // namespace

std::size_t shell_material_points(const model::ElementTypeInfo& type, const ShellProperties& section) {
  return element_rule(type).size() * section.zeta.size();
}

void compute_shell(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                   const ShellProperties& section, const ShellNodeData& at_nodes, const ElementRequest& request,
                   std::span<const double> delta_t, const ShellMaterial& material, ElementSystem& out) {
  if (material.law && material.history.per_point != material.law->state_size())
    throw std::invalid_argument("compute_shell: a material with state needs its points' history");
  if (!request.nlgeom) {
    compute_shell_small(type, coords, u, section, at_nodes, request, delta_t, material, out);
    return;
  }
  const auto small_strain = [&](std::span<const double> d, const ElementRequest& r, ElementSystem& o) {
    compute_shell_small(type, coords, d, section, at_nodes, r, delta_t, material, o);
  };
  compute_corotational(CorotationalFrame::Shell, coords, u, Vec3{}, small_strain, request, out);
}

}  // namespace inpact::solver::elements
