#include "smoothed_gap.hpp"

#include <cmath>

#include "vec3.hpp"

namespace inpact::contact {

namespace {

/// Is ξ on the boundary of the facet's parametric domain (where the ray iteration clamps it)?
bool on_boundary(FacetShape s, const std::array<double, 2>& xi) {
  if (facet_param_dim(s) == 1) return std::abs(xi[0]) >= 1.0;
  if (s == FacetShape::Tri3 || s == FacetShape::Tri6) return xi[0] <= 0.0 || xi[1] <= 0.0 || xi[0] + xi[1] >= 1.0;
  return std::abs(xi[0]) >= 1.0 || std::abs(xi[1]) >= 1.0;
}

/// ρ, the last row of J⁻¹ for the ray's Jacobian J at gap g (see the header); false if singular.
bool gap_row(const CorrectionDerivatives& d, const Vec3& normal, double gap, Vec3& rho) {
  const int pd = d.param_dim;
  const Vec3 c0 = axpy(gap, d.n_xi[0], d.x_xi[0]);
  if (pd == 1) {  // J = [c0 ñ] on x–y: dg = (c0_x r_y − c0_y r_x) / det
    const double det = c0[0] * normal[1] - normal[0] * c0[1];
    if (!(std::abs(det) > 1e-300)) return false;
    rho = {-c0[1] / det, c0[0] / det, 0.0};
    return true;
  }
  const Vec3 c1 = axpy(gap, d.n_xi[1], d.x_xi[1]);
  const Vec3 c01 = cross(c0, c1);
  const double det = dot(normal, c01);
  if (!(std::abs(det) > 1e-300)) return false;
  rho = scale(1.0 / det, c01);
  return true;
}

}  // namespace

void smoothed_gap_gradient(const SurfaceCorrections& slave, const SurfaceCorrections& master, const SmoothedPoint& pt,
                           std::span<const Vec3> x, int dim, std::vector<double>& out) {
  const Facet& sf = *pt.slave_facet;
  const Facet& mf = *pt.master_facet;
  const Projection& p = *pt.projection;
  const std::size_t d = static_cast<std::size_t>(dim), ns = sf.n_nodes, nm = mf.n_nodes;
  out.assign((ns + nm) * d, 0.0);
  CorrectionDerivatives ds, dm;
  slave.derivatives(sf, pt.slave_xi, x, ds, false);
  const Vec3& n = p.normal;
  if (!pt.master_corrected) {  // faceted master: g = (x̃_q − x_m)·n, [n; −N_a n]
    const ShapeEval sh = eval_shape(mf.shape, p.xi[0], p.xi[1]);
    for (std::size_t b = 0; b < ns; ++b)
      for (std::size_t j = 0; j < d; ++j) out[b * d + j] = dot(n, ds.x_node[b][j]);
    for (std::size_t a = 0; a < nm; ++a)
      for (std::size_t j = 0; j < d; ++j) out[(ns + a) * d + j] = -sh.N[a] * n[j];
    return;
  }
  const bool held = on_boundary(mf.shape, p.xi);
  master.derivatives(mf, p.xi, x, dm, !held);
  Vec3 rho{};
  const bool free_xi = !held && gap_row(dm, n, p.gap, rho);
  const Vec3 sep = sub(pt.x, p.x_master);  // x̃_q − x̃_m
  // dg for a change dq of x̃_q, dm of x̃_m and dn of ñ (at fixed ξ).
  auto dgap = [&](const Vec3& dq, const Vec3& dxm, const Vec3& dn) {
    if (free_xi) return dot(rho, sub(sub(dq, dxm), scale(p.gap, dn)));
    return dot(n, sub(dq, dxm)) + dot(sep, dn);
  };
  const Vec3 zero{0, 0, 0};
  for (std::size_t b = 0; b < ns; ++b)
    for (std::size_t j = 0; j < d; ++j) out[b * d + j] = dgap(ds.x_node[b][j], zero, zero);
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t j = 0; j < d; ++j) out[(ns + a) * d + j] = dgap(zero, dm.x_node[a][j], dm.n_node[a][j]);
}

void area_element_log_gradient(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x, int dim,
                               bool axisymmetric, std::vector<double>& out) {
  const ShapeEval sh = eval_shape(f.shape, xi[0], xi[1]);
  const FacetGeometry g = facet_geometry(f, x, sh);
  const std::size_t d = static_cast<std::size_t>(dim);
  out.assign(static_cast<std::size_t>(f.n_nodes) * d, 0.0);
  if (!(g.jacobian > 0)) return;
  const bool edge = facet_param_dim(f.shape) == 1;
  const Vec3 t1 = scale(1.0 / g.jacobian, g.a[0]);
  const Vec3 w0 = cross(g.n, g.a[1]), w1 = cross(g.a[0], g.n);  // ∂|a_2 × a_1|/∂a_1, ∂/∂a_2
  for (int b = 0; b < f.n_nodes; ++b)
    for (std::size_t j = 0; j < d; ++j) {
      // |a_1|: t1·∂a_1; |a_2 × a_1|: n·(∂a_2 × a_1 + a_2 × ∂a_1).
      const double dJ = edge ? t1[j] * sh.dN[b][0] : w0[j] * sh.dN[b][0] + w1[j] * sh.dN[b][1];
      double v = dJ / g.jacobian;
      if (axisymmetric && j == 0 && g.x[0] != 0.0) v += sh.N[b] / g.x[0];  // 2π r
      out[static_cast<std::size_t>(b) * d + j] = v;
    }
}

}  // namespace inpact::contact
