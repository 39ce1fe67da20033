#include "beam_elements.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

void compute_beam(const model::ElementTypeInfo& type, std::span<const Vec3> coords, std::span<const double> u,
                  const BeamProperties& section, const ElementRequest& request, ElementSystem& out) {
  const int n = type.n_nodes;
  const int n_dof = 6 * n;
  if (static_cast<int>(coords.size()) != n || static_cast<int>(u.size()) != n_dof)
    throw std::invalid_argument("compute_beam: coordinate or displacement count mismatch");
  out.n_dof = n_dof;
  out.local_iterations = 0;
  out.internal_force.assign(request.internal_force ? static_cast<std::size_t>(n_dof) : 0, 0.0);
  out.stiffness.assign(request.stiffness ? static_cast<std::size_t>(n_dof) * n_dof : 0, 0.0);
  out.points.clear();
  const std::vector<TrussPoint> pts = truss_points(type, coords, 3);
  out.min_jacobian = 1e300;
  double length = 0.0;
  for (const TrussPoint& p : pts) {
    out.min_jacobian = std::min(out.min_jacobian, p.J);
    length += p.weight * p.J;
  }
  if (out.min_jacobian <= 0.0) return;  // zero length: the caller reports it
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

}  // namespace inpact::solver::elements
