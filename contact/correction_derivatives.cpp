// Derivatives of the geometric correction's idealised point and normal (geometric_correction.hpp,
// CorrectionDerivatives): what the smoothed gap's linearisation uses.
#include <cmath>

#include <fmt/format.h>

#include "geometric_correction.hpp"
#include "vec3.hpp"

namespace inpact::contact {

namespace {


/// ∂(t1, t2, n) of frame q at geometry g when the tangents move by da = (∂a_1, ∂a_2): t1 = a_1/|a_1|,
/// n = (a_2 × a_1)/|a_2 × a_1| (an edge: a_1 turned clockwise), t2 = n × t1.
std::array<Vec3, 3> frame_change(const FacetGeometry& g, const std::array<Vec3, 3>& q, int pd,
                                 const std::array<Vec3, 2>& da) {
  std::array<Vec3, 3> dq;
  const double l1 = norm(g.a[0]);
  dq[0] = scale(1.0 / l1, axpy(-dot(q[0], da[0]), q[0], da[0]));
  if (pd == 1) {
    dq[2] = {dq[0][1], -dq[0][0], 0.0};
  } else {
    const Vec3 dc = add(cross(da[1], g.a[0]), cross(g.a[1], da[0]));
    dq[2] = scale(1.0 / g.jacobian, axpy(-dot(q[2], dc), q[2], dc));
  }
  dq[1] = add(cross(dq[2], q[0]), cross(q[2], dq[0]));
  return dq;
}

/// Σ_i (v·from_i) dq_i: the change of the rotated vector Q v when the current frame moves by dq.
Vec3 rotated_change(const std::array<Vec3, 3>& from, const std::array<Vec3, 3>& dq, const Vec3& v) {
  Vec3 out{0, 0, 0};
  for (int i = 0; i < 3; ++i) out = axpy(dot(v, from[i]), dq[i], out);
  return out;
}

/// What a change dq of the facet's frame changes x̃ and ñ by (linear in dq).
struct FrameEffect {
  Vec3 dx{}, dn{};
};

/// The facet's point x_f with its node derivatives, and the node derivatives of x̃ and ñ through
/// the facet's frame q at g (`framed`: not degenerate): effect(dq) for the frame's change dq.
/// Node a's component j moves tangent a_α by N_a,α e_j, and the frame's change is linear in the
/// tangents' (frame_change()), so the effects of the 2 × 3 unit tangent changes are combined
/// node by node.
template <class Effect>
void facet_node_derivatives(const FacetGeometry& g, const ShapeEval& sh, int pd, bool framed,
                            const std::array<Vec3, 3>& q, CorrectionDerivatives& d, Effect&& effect) {
  std::array<std::array<FrameEffect, 3>, 2> unit_effect{};
  if (framed)
    for (int al = 0; al < pd; ++al)
      for (int j = 0; j < 3; ++j) {
        std::array<Vec3, 2> da{};
        da[static_cast<std::size_t>(al)][static_cast<std::size_t>(j)] = 1.0;
        unit_effect[static_cast<std::size_t>(al)][static_cast<std::size_t>(j)] = effect(frame_change(g, q, pd, da));
      }
  for (int a = 0; a < sh.n; ++a)
    for (int j = 0; j < 3; ++j) {
      Vec3 dx{}, dn{};
      dx[static_cast<std::size_t>(j)] = sh.N[a];
      for (int al = 0; al < pd; ++al) {
        const FrameEffect& e = unit_effect[static_cast<std::size_t>(al)][static_cast<std::size_t>(j)];
        dx = axpy(sh.dN[a][al], e.dx, dx);
        dn = axpy(sh.dN[a][al], e.dn, dn);
      }
      d.x_node[a][j] = dx;
      d.n_node[a][j] = dn;
    }
}

/// The facet's own point and normal (no correction: x̃ = x_f, ñ = n): the frame carries only n.
void facet_node_derivatives(const FacetGeometry& g, const ShapeEval& sh, int pd, CorrectionDerivatives& d) {
  std::array<Vec3, 3> q{};
  const bool framed = facet_frame(g, q);
  facet_node_derivatives(g, sh, pd, framed, q, d, [](const std::array<Vec3, 3>& dq) { return FrameEffect{{}, dq[2]}; });
}

}  // namespace

CorrectedPoint SurfaceCorrection::node_derivatives(std::size_t i, std::array<double, 2> xi, std::span<const Vec3> x,
                                                   CorrectionDerivatives& d) const {
  const Facet& f = facets_[i];
  const ShapeEval sh = eval_shape(f.shape, xi[0], xi[1]);
  const int pd = facet_param_dim(f.shape);
  d.n_nodes = f.n_nodes;
  d.param_dim = pd;
  Parts c;
  const CorrectedPoint p = correct_at(i, sh, x, c);
  // x̃ = x_f + Q d, ñ = unit(Q ñ_ref): Q moves with the current frame (uncorrected: x_f and n).
  facet_node_derivatives(c.gx, sh, pd, c.framed, c.qx, d, [&](const std::array<Vec3, 3>& dq) {
    if (!c.rotated) return FrameEffect{{}, dq[2]};
    const Vec3 dn = rotated_change(c.qX, dq, c.normal);
    return FrameEffect{rotated_change(c.qX, dq, c.offset), axpy(-dot(p.normal, dn), p.normal, dn)};
  });
  return p;
}

void SurfaceCorrection::xi_derivatives(std::size_t i, std::array<double, 2> xi, std::span<const Vec3> x,
                                       CorrectionDerivatives& d) const {
  const int pd = facet_param_dim(facets_[i].shape);
  for (int al = 0; al < pd; ++al) {
    std::array<double, 2> lo = xi, hi = xi;
    lo[al] -= kCorrectionXiStep;
    hi[al] += kCorrectionXiStep;
    FacetGeometry g;
    const CorrectedPoint pl = correct_at(i, lo, x, g), ph = correct_at(i, hi, x, g);
    d.x_xi[al] = scale(0.5 / kCorrectionXiStep, sub(ph.x, pl.x));
    d.n_xi[al] = scale(0.5 / kCorrectionXiStep, sub(ph.normal, pl.normal));
  }
}

CorrectedPoint SurfaceCorrection::derivatives(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x,
                                              CorrectionDerivatives& d, bool with_xi) const {
  const std::int32_t i = find(f);
  if (i < 0)
    throw std::invalid_argument(
        fmt::format("SurfaceCorrection::derivatives: the facet is not a face of surface {}", data_.surface));
  const CorrectedPoint p = node_derivatives(static_cast<std::size_t>(i), xi, x, d);
  if (with_xi) xi_derivatives(static_cast<std::size_t>(i), xi, x, d);
  return p;
}

CorrectedPoint SurfaceCorrections::derivatives(const Facet& f, std::array<double, 2> xi, std::span<const Vec3> x,
                                               CorrectionDerivatives& d, bool with_xi) const {
  if (const SurfaceCorrection* c = find(f)) return c->derivatives(f, xi, x, d, with_xi);
  const ShapeEval sh = eval_shape(f.shape, xi[0], xi[1]);
  const FacetGeometry g = facet_geometry(f, x, sh);
  const int pd = facet_param_dim(f.shape);
  d.n_nodes = f.n_nodes;
  d.param_dim = pd;
  facet_node_derivatives(g, sh, pd, d);
  if (with_xi)
    for (int al = 0; al < pd; ++al) {
      d.x_xi[al] = g.a[al];
      std::array<double, 2> lo = xi, hi = xi;
      lo[al] -= kCorrectionXiStep;
      hi[al] += kCorrectionXiStep;
      const Vec3 nl = facet_geometry(f, x, lo[0], lo[1]).n, nh = facet_geometry(f, x, hi[0], hi[1]).n;
      d.n_xi[al] = scale(0.5 / kCorrectionXiStep, sub(nh, nl));
    }
  return {g.x, g.n, false};
}

}  // namespace inpact::contact
