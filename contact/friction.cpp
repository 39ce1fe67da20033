#include "friction.hpp"

#include <cmath>

#include <fmt/format.h>

namespace inpact::contact {

namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// P_T = t1 t1ᵀ + t2 t2ᵀ, the projection onto the tangent plane.
struct Mat3 {
  double m[3][3] = {};
};
Mat3 tangent_projector(const Projection& p) {
  Mat3 PT;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) PT.m[r][c] = p.t1[r] * p.t1[c] + p.t2[r] * p.t2[c];
  return PT;
}

/// Δx = x_s − x_anchor(ξ₀) on the current coordinates.
Vec3 motion_from_anchor(const Facet& anchor_facet, const FrictionAnchor& anchor, const Vec3& xs,
                        std::span<const Vec3> x) {
  const FacetGeometry g0 = facet_geometry(anchor_facet, x, anchor.xi[0], anchor.xi[1]);
  Vec3 dx{};
  for (int c = 0; c < 3; ++c) dx[c] = xs[c] - g0.x[c];
  return dx;
}

/// D = ∂Δx/∂u (3 × n, row-major), the anchor taken as the material point at the current ξ of
/// the current facet: slave block I, facet node a block −N_a(ξ) I.
std::vector<double> motion_jacobian(const Facet& facet, const Projection& p, int dim, std::size_t n) {
  const ShapeEval s = eval_shape(facet.shape, p.xi[0], p.xi[1]);
  std::vector<double> D(3 * n, 0.0);
  for (int c = 0; c < dim; ++c) D[c * n + static_cast<std::size_t>(c)] = 1.0;
  for (int a = 0; a < s.n; ++a)
    for (int c = 0; c < dim; ++c) D[c * n + static_cast<std::size_t>((a + 1) * dim + c)] = -s.N[a];
  return D;
}

/// Δs = P_T Δx, the elastic predictor e_tr = P_T e₀ + Δs, and B = P_T D (3 × n, row-major).
struct TangentialMotion {
  Vec3 slip_increment{}, e_tr{};
  std::vector<double> B;
};
TangentialMotion tangential_motion(const Mat3& PT, const Vec3& dx, const Vec3& e0, const std::vector<double>& D,
                                   std::size_t n) {
  TangentialMotion t;
  t.B.assign(3 * n, 0.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      t.slip_increment[r] += PT.m[r][c] * dx[c];
      t.e_tr[r] += PT.m[r][c] * e0[c];
      for (std::size_t j = 0; j < n; ++j) t.B[r * n + j] += PT.m[r][c] * D[c * n + j];
    }
  }
  for (int r = 0; r < 3; ++r) t.e_tr[r] += t.slip_increment[r];
  return t;
}

/// The derivatives of τ from the return mapping at fixed pressure, M = ∂τ/∂e_tr (stick k I, slip
/// μ p/|e_tr| (I − m mᵀ): e_tr's normal part, which the turn of the tangent plane gives it, counts),
/// and ∂τ/∂p.
struct TractionDerivatives {
  Mat3 M;
  Vec3 dtau_dp{};
};

/// Stick: e = e_tr, τ = k e, M = k I, ∂τ/∂p = (dk/dp) e.
TractionDerivatives stick(const FrictionLaw& law, double k, const Vec3& e_tr, FrictionPoint& out) {
  TractionDerivatives d;
  out.elastic_slip = e_tr;
  for (int r = 0; r < 3; ++r) {
    out.traction[r] = k * e_tr[r];
    d.dtau_dp[r] = law.dstiffness_dp() * e_tr[r];
    d.M.m[r][r] = k;
  }
  return d;
}

/// Slip: m = e_tr/|e_tr|, τ = μ p m, e = (μ p / k) m, M = μ p/|e_tr| (I − m mᵀ), ∂τ/∂p = μ m.
TractionDerivatives slip(const FrictionLaw& law, double k, double limit, const Vec3& e_tr, double e_norm,
                         FrictionPoint& out) {
  TractionDerivatives d;
  Vec3 m{};
  for (int r = 0; r < 3; ++r) m[r] = e_tr[r] / e_norm;
  for (int r = 0; r < 3; ++r) {
    out.traction[r] = limit * m[r];
    out.elastic_slip[r] = (k > 0.0 ? limit / k : 0.0) * m[r];
    d.dtau_dp[r] = law.mu * m[r];
    for (int c = 0; c < 3; ++c) d.M.m[r][c] = limit / e_norm * ((r == c ? 1.0 : 0.0) - m[r] * m[c]);
  }
  return d;
}

/// The return mapping: sets out.slipping, out.elastic_slip and out.traction.
TractionDerivatives return_mapping(const FrictionLaw& law, double pressure, const Vec3& e_tr, FrictionPoint& out) {
  const double k = law.stiffness(pressure);
  const double e_norm = std::sqrt(dot(e_tr, e_tr));
  const double limit = law.mu * pressure;
  out.slipping = !law.rough && k * e_norm > limit * (1.0 + 1e-12) && e_norm > 0.0;
  return out.slipping ? slip(law, k, limit, e_tr, e_norm, out) : stick(law, k, e_tr, out);
}

/// force = Bᵀ τ, coupling = Bᵀ ∂τ/∂p (B = P_T D), tangent = Dᵀ M E + (∂D)ᵀ τ, E = ∂e_tr/∂u
/// (3 × n): with τ tangential, ∂(Bᵀ τ) = ∂(Dᵀ τ).
void assemble_friction(const std::vector<double>& B, const std::vector<double>& D, const std::vector<double>& E,
                       const std::vector<double>& dD_tau, const TractionDerivatives& d, std::size_t n,
                       FrictionPoint& out) {
  out.force.assign(n, 0.0);
  out.coupling.assign(n, 0.0);
  std::vector<double> ME(3 * n, 0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (d.M.m[r][c] != 0.0)
        for (std::size_t j = 0; j < n; ++j) ME[r * n + j] += d.M.m[r][c] * E[c * n + j];
  out.tangent = dD_tau;
  for (std::size_t i = 0; i < n; ++i) {
    for (int r = 0; r < 3; ++r) {
      const double bri = B[r * n + i];
      out.force[i] += bri * out.traction[r];
      out.coupling[i] += bri * d.dtau_dp[r];
      const double dri = D[r * n + i];
      if (dri == 0.0) continue;
      for (std::size_t j = 0; j < n; ++j) out.tangent[i * n + j] += dri * ME[r * n + j];
    }
  }
}

/// ∂n/∂u (3 × n, row-major) of the facet's unit normal at the projection's ξ: through the facet's
/// nodes at fixed ξ and through ξ's change (lin.dxi; its slide over a curved facet). Zero where
/// the contact normal is not the facet's own (an edge or vertex, or `facet_normal` false).
std::vector<double> normal_jacobian(const Facet& facet, const Projection& p, const GapLinearization& lin,
                                    std::span<const Vec3> x, bool facet_normal) {
  const std::size_t n = static_cast<std::size_t>(lin.n_dof), dim = static_cast<std::size_t>(lin.dim);
  std::vector<double> dn(3 * n, 0.0);
  if (!facet_normal || p.region != ProjectionRegion::Interior) return dn;
  const ShapeEval s = eval_shape(facet.shape, p.xi[0], p.xi[1]);
  const FacetGeometry g = facet_geometry(facet, x, s);
  if (!(g.jacobian > 0)) return dn;
  const bool edge = facet_param_dim(facet.shape) == 1;
  for (int a = 0; a < s.n; ++a)
    for (std::size_t j = 0; j < dim; ++j) {
      Vec3 v{};  // ∂n for x_aj: 2D n = (t1_y, −t1_x), 3D n = c/|c|, c = a_2 × a_1
      if (edge) {
        Vec3 da{};
        da[j] = s.dN[a][0];
        const double l = g.jacobian;
        Vec3 dt{};
        for (int r = 0; r < 3; ++r) dt[r] = da[r] / l - g.a[0][r] * dot(g.a[0], da) / (l * l * l);
        v = {dt[1], -dt[0], 0.0};
      } else {
        Vec3 d1{}, d2{};
        d1[j] = s.dN[a][0];
        d2[j] = s.dN[a][1];
        const Vec3 a1 = g.a[0], a2 = g.a[1];
        Vec3 dc{d2[1] * a1[2] - d2[2] * a1[1] + a2[1] * d1[2] - a2[2] * d1[1],
                d2[2] * a1[0] - d2[0] * a1[2] + a2[2] * d1[0] - a2[0] * d1[2],
                d2[0] * a1[1] - d2[1] * a1[0] + a2[0] * d1[1] - a2[1] * d1[0]};
        const double nd = dot(g.n, dc);
        for (int r = 0; r < 3; ++r) v[r] = (dc[r] - g.n[r] * nd) / g.jacobian;
      }
      const std::size_t col = (static_cast<std::size_t>(a) + 1) * dim + j;
      for (int r = 0; r < 3; ++r) dn[r * n + col] = v[r];
    }
  // The slide: n_,α dξ_α (central differences of the normal in ξ; zero on a flat facet).
  const int pd = facet_param_dim(facet.shape);
  for (int al = 0; al < pd; ++al) {
    if (lin.dxi[al].size() != n) continue;
    constexpr double h = 1e-6;
    std::array<double, 2> lo = p.xi, hi = p.xi;
    lo[al] -= h;
    hi[al] += h;
    const Vec3 nl = facet_geometry(facet, x, lo[0], lo[1]).n, nh = facet_geometry(facet, x, hi[0], hi[1]).n;
    for (int r = 0; r < 3; ++r) {
      const double dnr = (nh[r] - nl[r]) / (2 * h);
      if (dnr != 0.0)
        for (std::size_t j = 0; j < n; ++j) dn[r * n + j] += dnr * lin.dxi[al][j];
    }
  }
  return dn;
}

/// (∂D)ᵀ τ (n × n): the master's share −N_a(ξ) τ moves with ξ, −τ ⊗ N_a,α ∂ξ_α/∂u (lin.dxi; none
/// without it).
std::vector<double> distribution_change(const Facet& facet, const Projection& p, const GapLinearization& lin,
                                        const Vec3& tau) {
  const std::size_t n = static_cast<std::size_t>(lin.n_dof), dim = static_cast<std::size_t>(lin.dim);
  std::vector<double> out(n * n, 0.0);
  const ShapeEval s = eval_shape(facet.shape, p.xi[0], p.xi[1]);
  const int pd = facet_param_dim(facet.shape);
  for (int al = 0; al < pd; ++al) {
    if (lin.dxi[al].size() != n) continue;
    for (int a = 0; a < s.n; ++a)
      for (std::size_t c = 0; c < dim; ++c) {
        const std::size_t row = (static_cast<std::size_t>(a) + 1) * dim + c;
        const double f = -tau[c] * s.dN[a][al];
        if (f != 0.0)
          for (std::size_t j = 0; j < n; ++j) out[row * n + j] += f * lin.dxi[al][j];
      }
  }
  return out;
}

}  // namespace

std::optional<FrictionLaw> resolve_friction(const model::Friction* friction, double l_char, double ke) {
  if (!friction || (!friction->rough && !(friction->mu > 0.0))) return std::nullopt;
  FrictionLaw law;
  law.rough = friction->rough;
  law.mu = friction->mu;
  if (friction->lagrange) {
    // LAGRANGE: Abaqus enforces sticking exactly, with multipliers. inpact keeps the elastic-slip
    // method with an allowable slip of kLagrangeSlipFraction × the characteristic length
    // (5000 times smaller than the default SLIP TOLERANCE): stick to that, not to round-off.
    law.gamma_crit = kLagrangeSlipFraction * l_char;
    law.lagrange = true;
  } else if (friction->elastic_slip) {  // ELASTIC SLIP overrides SLIP TOLERANCE [K16 *FRICTION]
    law.gamma_crit = *friction->elastic_slip;
    law.gamma_is_absolute = true;
  } else {
    law.gamma_crit = friction->slip_tolerance.value_or(0.005) * l_char;
  }
  if (law.rough) law.fixed_stiffness = kRoughStiffnessFactor * ke;
  // CalculiX's stick slope λ (its *FRICTION's second field) is a fixed stick stiffness; an
  // Abaqus SLIP TOLERANCE or ELASTIC SLIP given with it wins.
  else if (friction->stick_slope && !friction->elastic_slip && !friction->slip_tolerance)
    law.fixed_stiffness = *friction->stick_slope;
  return law;
}

std::string describe(const FrictionLaw& law) {
  if (law.rough) return fmt::format("ROUGH friction (no slip), stick stiffness {:.4g} = {:g} k_e", law.fixed_stiffness,
                                    kRoughStiffnessFactor);
  if (law.fixed_stiffness > 0.0)
    return fmt::format("Coulomb friction mu = {:g}, stick slope {:.4g} (CalculiX)", law.mu, law.fixed_stiffness);
  if (law.lagrange)
    return fmt::format("Coulomb friction mu = {:g}, LAGRANGE: sticking to an elastic slip of {:.4g} ({:g} of the "
                       "characteristic length; inpact's approximation of exact sticking)", law.mu, law.gamma_crit,
                       kLagrangeSlipFraction);
  return fmt::format("Coulomb friction mu = {:g}, penalty (elastic slip), allowable elastic slip {:.4g}{}", law.mu,
                     law.gamma_crit, law.gamma_is_absolute ? " (ELASTIC SLIP)" : "");
}

FrictionPoint friction_point(const FrictionLaw& law, const Facet& facet, const Projection& p,
                             const GapLinearization& lin, const Facet& anchor_facet, const FrictionAnchor& anchor,
                             const Vec3& e0, double pressure, std::span<const Vec3> x, bool facet_normal) {
  const std::size_t n = static_cast<std::size_t>(lin.n_dof);
  FrictionPoint out;
  out.n_dof = lin.n_dof;

  // Δx = x_s − x_anchor(ξ₀) on the current coordinates (its tangential part equals the motion
  // of the projected point, x_s − x_m(ξ) being normal), and D = ∂Δx/∂u with the anchor taken as
  // the material point at the current ξ of the current facet. The same D distributes the force:
  // the master's share acts at the contact point, whichever facet the anchor lies on.
  const Vec3& xs = x[static_cast<std::size_t>(lin.nodes[0])];
  const Vec3 dx = motion_from_anchor(anchor_facet, anchor, xs, x);
  const std::vector<double> D = motion_jacobian(facet, p, lin.dim, n);

  const Mat3 PT = tangent_projector(p);
  const TangentialMotion t = tangential_motion(PT, dx, e0, D, n);
  out.slip_increment = t.slip_increment;
  out.trial_slip = t.e_tr;
  const TractionDerivatives d = return_mapping(law, pressure, t.e_tr, out);
  // E = ∂e_tr/∂u = P_T ∂Δx/∂u + ∂P_T (e₀ + Δx), ∂P_T v = −(∂n (n·v) + n (∂n·v)); on the anchor's
  // own facet ∂Δx/∂x_a = −N_a(ξ₀) (elsewhere the current facet's −N_a(ξ) stands for it).
  const bool same_facet = &anchor_facet == &facet || anchor_facet.nodes == facet.nodes;
  const Projection at_anchor = [&] { Projection q = p; q.xi = anchor.xi; return q; }();
  const std::vector<double> Dkin = same_facet ? motion_jacobian(facet, at_anchor, lin.dim, n) : D;
  std::vector<double> E(3 * n, 0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (PT.m[r][c] != 0.0)
        for (std::size_t j = 0; j < n; ++j) E[r * n + j] += PT.m[r][c] * Dkin[c * n + j];
  const std::vector<double> dn = normal_jacobian(facet, p, lin, x, facet_normal);
  Vec3 v{};
  for (int c = 0; c < 3; ++c) v[c] = e0[c] + dx[c];
  const double nv = dot(p.normal, v);
  for (std::size_t j = 0; j < n; ++j) {
    const Vec3 dnj{dn[j], dn[n + j], dn[2 * n + j]};
    const double dnv = dot(dnj, v);
    for (int r = 0; r < 3; ++r) E[r * n + j] -= dnj[r] * nv + p.normal[r] * dnv;
  }
  assemble_friction(t.B, D, E, distribution_change(facet, p, lin, out.traction), d, n, out);
  return out;
}

FrictionPoint friction_point(const FrictionLaw& law, const Projection& p, const Vec3& dx, std::span<const double> D,
                             const Vec3& e0, double pressure) {
  const std::size_t n = D.size() / 3;
  FrictionPoint out;
  out.n_dof = static_cast<int>(n);
  const std::vector<double> jacobian(D.begin(), D.end());
  const TangentialMotion t = tangential_motion(tangent_projector(p), dx, e0, jacobian, n);
  out.slip_increment = t.slip_increment;
  out.trial_slip = t.e_tr;
  const TractionDerivatives d = return_mapping(law, pressure, t.e_tr, out);
  assemble_friction(t.B, jacobian, t.B, std::vector<double>(n * n, 0.0), d, n, out);
  return out;
}

}  // namespace inpact::contact
