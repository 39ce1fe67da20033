#include "beam_elements.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "corotation.hpp"
#include "line_elements.hpp"

namespace inpact::solver::elements {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// The section stiffness at a point of an element of length `length`, in the order of the
/// strains (ε, γ1, γ2, κ3, κ1, κ2).
std::array<double, 6> section_stiffness(const BeamProperties& p, const model::ElementTypeInfo& type, double length) {
  const double xi = type.order == 1 ? 1.0 : 1e-4;  // Abaqus: first- and second-order elements
  const double slender = xi * p.slenderness_compensation * length * length * p.area / 12.0;
  const double f1 = 1.0 / (1.0 + slender / p.i22), f2 = 1.0 / (1.0 + slender / p.i11);
  return {p.youngs_modulus * p.area, p.k13 * f1, p.k23 * f2, p.shear_modulus * p.torsion,
          p.youngs_modulus * p.i11, p.youngs_modulus * p.i22};
}

/// B33: Euler–Bernoulli with cubic (Hermite) deflections and linear axial displacement and
/// twist, in the axes of its chord. Local DOFs per bending plane: (w, dw/ds) at both ends, with
/// w1 = n1·u, dw1/ds = n2·θ (the section turns with the axis) and w2 = n2·u, dw2/ds = −n1·θ; the
/// classical stiffness (EI/L³)[12, 6L, −12, 6L; …] in each plane. Point output at two Gauss points:
/// M2 = EI22 w1″, M1 = −EI11 w2″, the shears from equilibrium V1 = −dM2/ds, V2 = dM1/ds.
void compute_euler_bernoulli(const BeamProperties& p, const std::vector<TrussPoint>& pts,
                             const std::array<Vec3, 3>& axes, std::span<const double> u, const ElementRequest& request,
                             ElementSystem& out) {
  const auto& [t, n1, n2] = axes;
  const double L = pts.front().J * 2.0;  // J = L/2 of the straight chord
  // Rows of T: the 12 local DOFs (axial a, b; twist a, b; plane 1: w, dw/ds at a, b; plane 2
  // likewise) from the element's 12 (u_a, u_b, θ_a, θ_b).
  std::array<std::array<double, 12>, 12> T{};
  auto put = [&](int row, int block, const Vec3& v, double sign) {
    for (int i = 0; i < 3; ++i) T[row][3 * block + i] = sign * v[i];
  };
  put(0, 0, t, 1), put(1, 1, t, 1);       // axial displacement at a, b
  put(2, 2, t, 1), put(3, 3, t, 1);       // twist at a, b
  put(4, 0, n1, 1), put(5, 2, n2, 1);     // plane 1 at a: w1, dw1/ds
  put(6, 1, n1, 1), put(7, 3, n2, 1);     //             at b
  put(8, 0, n2, 1), put(9, 2, n1, -1);    // plane 2 at a: w2, dw2/ds
  put(10, 1, n2, 1), put(11, 3, n1, -1);  //             at b
  std::array<double, 12> local{};
  for (int r = 0; r < 12; ++r)
    for (int j = 0; j < 12; ++j) local[r] += T[r][j] * u[j];
  std::array<std::array<double, 12>, 12> k{};
  const double ka = p.youngs_modulus * p.area / L, kt = p.shear_modulus * p.torsion / L;
  k[0][0] = k[1][1] = ka, k[0][1] = k[1][0] = -ka;
  k[2][2] = k[3][3] = kt, k[2][3] = k[3][2] = -kt;
  const double bend[4][4] = {{12, 6 * L, -12, 6 * L}, {6 * L, 4 * L * L, -6 * L, 2 * L * L},
                             {-12, -6 * L, 12, -6 * L}, {6 * L, 2 * L * L, -6 * L, 4 * L * L}};
  const double ei[2] = {p.youngs_modulus * p.i22, p.youngs_modulus * p.i11};  // plane 1 bends about n2
  for (int plane = 0; plane < 2; ++plane)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) k[4 + 4 * plane + i][4 + 4 * plane + j] = ei[plane] / (L * L * L) * bend[i][j];
  std::array<double, 12> f_local{};
  for (int r = 0; r < 12; ++r)
    for (int j = 0; j < 12; ++j) f_local[r] += k[r][j] * local[j];
  for (int i = 0; i < 12 && !out.internal_force.empty(); ++i)
    for (int r = 0; r < 12; ++r) out.internal_force[i] += T[r][i] * f_local[r];
  for (int i = 0; i < 12 && !out.stiffness.empty(); ++i)
    for (int r = 0; r < 12; ++r) {
      if (T[r][i] == 0.0) continue;
      for (int q = 0; q < 12; ++q) {
        const double krq = T[r][i] * k[r][q];
        if (krq == 0.0) continue;
        for (int j = 0; j < 12; ++j) out.stiffness[static_cast<std::size_t>(i * 12 + j)] += krq * T[q][j];
      }
    }
  if (!request.point_output) return;
  for (const TrussPoint& pt : pts) {
    const double xi = pt.N[1] - pt.N[0];  // the point's ξ in [−1, 1]
    // Second and third derivatives along s of the Hermite functions of (w_a, w'_a, w_b, w'_b).
    const double d2[4] = {6 * xi / (L * L), (3 * xi - 1) / L, -6 * xi / (L * L), (3 * xi + 1) / L};
    const double d3[4] = {12 / (L * L * L), 6 / (L * L), -12 / (L * L * L), 6 / (L * L)};
    double curv1 = 0, curv2 = 0, jerk1 = 0, jerk2 = 0;  // w1″, w2″, w1‴, w2‴
    for (int a = 0; a < 4; ++a) {
      curv1 += d2[a] * local[4 + a], curv2 += d2[a] * local[8 + a];
      jerk1 += d3[a] * local[4 + a], jerk2 += d3[a] * local[8 + a];
    }
    const double axial = (local[1] - local[0]) / L, twist = (local[3] - local[2]) / L;
    PointResult r;
    r.coords = pt.x;
    r.volume = pt.weight * pt.J * p.area;
    // SF1, SF2 = V2, SF3 = V1, SM1, SM2, SM3 (the kernel's order, beam_elements.hpp).
    r.section = {p.youngs_modulus * p.area * axial, -ei[1] * jerk2, -ei[0] * jerk1, -ei[1] * curv2, ei[0] * curv1,
                 p.shear_modulus * p.torsion * twist};
    r.strain = {axial, 0.0, 0.0, -curv2, curv1, twist};
    out.points.push_back(r);
  }
}

}  // namespace

bool beam_axes(const Vec3& tangent, const Vec3& approximate_n1, std::array<Vec3, 3>& axes) {
  const double lt = norm(tangent), ln = norm(approximate_n1);
  if (lt == 0.0 || ln == 0.0) return false;
  Vec3 t{tangent[0] / lt, tangent[1] / lt, tangent[2] / lt};
  Vec3 n2 = cross(t, approximate_n1);
  const double l2 = norm(n2);
  if (l2 < 1e-8 * ln) return false;
  for (double& c : n2) c /= l2;
  axes = {t, cross(n2, t), n2};
  return true;
}

namespace {

/// The small-strain beam on its centroid's line (beam_elements.hpp).
void compute_beam_centred(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                          const BeamProperties& section, const ElementRequest& request, ElementSystem& out) {
  const int n = type.n_nodes;
  const int n_dof = 6 * n;
  if (static_cast<int>(coords.size()) != n || static_cast<int>(u.size()) != n_dof)
    throw std::invalid_argument("compute_beam: coordinate or displacement count mismatch");
  begin_element_system(out, n_dof, request);
  const std::vector<TrussPoint> pts = truss_points(type, coords, 3);
  out.min_jacobian = 1e300;
  double length = 0.0;
  for (const TrussPoint& p : pts) {
    out.min_jacobian = std::min(out.min_jacobian, p.J);
    length += p.weight * p.J;
  }
  if (out.min_jacobian <= 0.0) return;  // zero length: the caller reports it
  if (type.integration == model::Integration::Full) {  // B33
    std::array<Vec3, 3> axes;
    if (!beam_axes(pts.front().tangent, section.n1, axes)) {
      out.min_jacobian = 0.0;
      return;
    }
    compute_euler_bernoulli(section, pts, axes, u, request, out);
    return;
  }
  const std::array<double, 6> d = section_stiffness(section, type, length);
  std::vector<double> b(static_cast<std::size_t>(6 * n_dof));
  for (const TrussPoint& p : pts) {
    std::array<Vec3, 3> axes;
    if (!beam_axes(p.tangent, section.n1, axes)) {  // checked at set-up; a degenerate element
      out.min_jacobian = 0.0;
      return;
    }
    const auto& [t, n1, n2] = axes;
    // B: section strains (ε, γ1, γ2, κ3, κ1, κ2) from the element's DOFs.
    std::fill(b.begin(), b.end(), 0.0);
    auto at = [&](int strain, int dof) -> double& { return b[static_cast<std::size_t>(strain * n_dof + dof)]; };
    for (int a = 0; a < n; ++a) {
      const double ds = p.dN[a] / p.J, na = p.N[a];
      const int ua = 3 * a, ra = 3 * (n + a);
      for (int i = 0; i < 3; ++i) {
        at(0, ua + i) = t[i] * ds;
        at(1, ua + i) = n1[i] * ds;
        at(1, ra + i) = -n2[i] * na;
        at(2, ua + i) = n2[i] * ds;
        at(2, ra + i) = n1[i] * na;
        at(3, ra + i) = t[i] * ds;
        at(4, ra + i) = n1[i] * ds;
        at(5, ra + i) = n2[i] * ds;
      }
    }
    std::array<double, 6> strain{}, force{};
    for (int k = 0; k < 6; ++k) {
      for (int j = 0; j < n_dof; ++j) strain[k] += at(k, j) * u[j];
      force[k] = d[k] * strain[k];
    }
    const double w = p.weight * p.J;
    for (int i = 0; i < n_dof && !out.internal_force.empty(); ++i)
      for (int k = 0; k < 6; ++k) out.internal_force[i] += w * at(k, i) * force[k];
    for (int i = 0; i < n_dof && !out.stiffness.empty(); ++i)
      for (int k = 0; k < 6; ++k) {
        const double bik = w * d[k] * at(k, i);
        if (bik == 0.0) continue;
        for (int j = 0; j < n_dof; ++j) out.stiffness[static_cast<std::size_t>(i * n_dof + j)] += bik * at(k, j);
      }
    if (!request.point_output) continue;
    PointResult r;
    r.coords = p.x;
    r.volume = w * section.area;
    r.section = {force[0], force[2], force[1], force[4], force[5], force[3]};
    r.strain = {strain[0], strain[2], strain[1], strain[4], strain[5], strain[3]};
    out.points.push_back(r);
  }
}

/// The small-strain beam whose centroid lies off its nodes (BeamProperties::centroid): the
/// centroid's line r = c1 n1 + c2 n2 from the nodes (the chord's axes: one r for the element,
/// which a curved B32's points share approximately) is tied to them rigidly,
/// u_c = u + θ × r, so the centred kernel's force f_c and tangent K_c return as Tᵀ f_c and
/// Tᵀ K_c T: a centroid's axial force bends the node line, as Abaqus's offset sections do.
void compute_beam_offset(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                         const BeamProperties& section, const ElementRequest& request, ElementSystem& out) {
  const int n = type.n_nodes, n_dof = 6 * n;
  std::array<Vec3, 3> axes;
  const Vec3 chord{coords.back()[0] - coords[0][0], coords.back()[1] - coords[0][1], coords.back()[2] - coords[0][2]};
  if (!beam_axes(chord, section.n1, axes)) {
    begin_element_system(out, n_dof, request);
    out.min_jacobian = 0.0;
    return;
  }
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = section.centroid[0] * axes[1][i] + section.centroid[1] * axes[2][i];
  std::vector<Vec3> centred(coords.begin(), coords.end());
  std::vector<double> t(static_cast<std::size_t>(n_dof * n_dof), 0.0);  // T, row-major
  for (int j = 0; j < n_dof; ++j) t[static_cast<std::size_t>(j * n_dof + j)] = 1.0;
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 3; ++i) centred[a][i] += r[i];
    // θ × r = −[r]× θ in the translation rows, the rotation columns.
    const double minus_rx[3][3] = {{0, r[2], -r[1]}, {-r[2], 0, r[0]}, {r[1], -r[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t[static_cast<std::size_t>((3 * a + i) * n_dof + 3 * (n + a) + j)] = minus_rx[i][j];
  }
  std::vector<double> uc(static_cast<std::size_t>(n_dof), 0.0);
  for (int i = 0; i < n_dof; ++i)
    for (int j = 0; j < n_dof; ++j) uc[i] += t[static_cast<std::size_t>(i * n_dof + j)] * u[j];
  ElementSystem c;
  compute_beam_centred(type, centred, uc, section, request, c);
  begin_element_system(out, n_dof, request);
  out.min_jacobian = c.min_jacobian;
  out.points = std::move(c.points);
  for (int i = 0; i < n_dof && !out.internal_force.empty(); ++i)
    for (int r_row = 0; r_row < n_dof; ++r_row)
      out.internal_force[i] += t[static_cast<std::size_t>(r_row * n_dof + i)] * c.internal_force[r_row];
  if (out.stiffness.empty()) return;
  std::vector<double> kt(static_cast<std::size_t>(n_dof * n_dof), 0.0);  // K_c T
  for (int i = 0; i < n_dof; ++i)
    for (int k = 0; k < n_dof; ++k) {
      const double kik = c.stiffness[static_cast<std::size_t>(i * n_dof + k)];
      if (kik == 0.0) continue;
      for (int j = 0; j < n_dof; ++j)
        kt[static_cast<std::size_t>(i * n_dof + j)] += kik * t[static_cast<std::size_t>(k * n_dof + j)];
    }
  for (int k = 0; k < n_dof; ++k)
    for (int i = 0; i < n_dof; ++i) {
      const double tki = t[static_cast<std::size_t>(k * n_dof + i)];
      if (tki == 0.0) continue;
      for (int j = 0; j < n_dof; ++j)
        out.stiffness[static_cast<std::size_t>(i * n_dof + j)] += tki * kt[static_cast<std::size_t>(k * n_dof + j)];
    }
}

/// The small-strain beam (beam_elements.hpp), centred or offset.
void compute_beam_small(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                        const BeamProperties& section, const ElementRequest& request, ElementSystem& out) {
  if (section.centroid[0] == 0.0 && section.centroid[1] == 0.0)
    compute_beam_centred(type, coords, u, section, request, out);
  else
    compute_beam_offset(type, coords, u, section, request, out);
}

}  // namespace

void compute_beam(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                  const BeamProperties& section, const ElementRequest& request, ElementSystem& out) {
  if (!request.nlgeom) {
    compute_beam_small(type, coords, u, section, request, out);
    return;
  }
  std::array<Vec3, 3> axes;
  const Vec3& last = coords.back();
  const Vec3 chord{last[0] - coords[0][0], last[1] - coords[0][1], last[2] - coords[0][2]};
  if (!beam_axes(chord, section.n1, axes)) {
    begin_element_system(out, 6 * type.n_nodes, request);
    out.min_jacobian = 0.0;
    return;
  }
  const auto small_strain = [&](std::span<const double> d, const ElementRequest& r, ElementSystem& o) {
    compute_beam_small(type, coords, d, section, r, o);
  };
  compute_corotational(CorotationalFrame::Beam, coords, u, axes[1], small_strain, request, out);
}

}  // namespace inpact::solver::elements
