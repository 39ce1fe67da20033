#include "corotation.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace inpact::solver::elements {

namespace {

template <class S>
using V3 = std::array<S, 3>;
template <class S>
using M3 = std::array<V3<S>, 3>;  // rows

template <class S>
double value_of(const S& s) {
  if constexpr (std::is_arithmetic_v<S>)
    return s;
  else
    return value_of(s.value());
}

template <class S>
S dot(const V3<S>& a, const V3<S>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class S>
V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class S>
V3<S> normalized(const V3<S>& a) {
  using std::sqrt;
  const S length = sqrt(dot(a, a));
  return {a[0] / length, a[1] / length, a[2] / length};
}
template <class S>
V3<S> times(const M3<S>& m, const V3<S>& v) {
  return {dot(m[0], v), dot(m[1], v), dot(m[2], v)};
}
template <class S>
M3<S> times(const M3<S>& a, const M3<S>& b) {
  M3<S> c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return c;
}

/// Rodrigues: R = I + a K + b K², K = [ψ]×, a = sin φ/φ, b = (1 − cos φ)/φ², φ = |ψ|; by their
/// series near φ = 0, where the derivatives of φ itself do not exist.
template <class S>
M3<S> exp_rotation(const V3<S>& psi) {
  using std::sin;
  using std::sqrt;
  const S phi2 = dot(psi, psi);
  S a, b;
  if (value_of(phi2) < 1e-6) {
    a = 1.0 - phi2 / 6.0 + phi2 * phi2 / 120.0;
    b = 0.5 - phi2 / 24.0 + phi2 * phi2 / 720.0;
  } else {
    const S phi = sqrt(phi2), half = 0.5 * phi;
    const S sinc_half = sin(half) / half;  // (1 − cos φ)/φ² = ½ (sin(φ/2)/(φ/2))², free of cancellation
    a = sin(phi) / phi;
    b = 0.5 * sinc_half * sinc_half;
  }
  const M3<S> k{V3<S>{0.0 * psi[0], -psi[2], psi[1]}, V3<S>{psi[2], 0.0 * psi[0], -psi[0]},
                V3<S>{-psi[1], psi[0], 0.0 * psi[0]}};
  const M3<S> k2 = times(k, k);
  M3<S> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a * k[i][j] + b * k2[i][j] + (i == j ? 1.0 : 0.0);
  return r;
}

/// The rotation vector of R through its quaternion (w, v): θ = 2 atan2(|v|, w) v/|v|, by the
/// series of atan(t)/t in t² = |v|²/w² near the identity. False when R turns by π or nearly so.
template <class S>
bool log_rotation(const M3<S>& r, V3<S>& theta) {
  using std::atan2;
  using std::sqrt;
  const S trace = r[0][0] + r[1][1] + r[2][2];
  if (value_of(trace) <= -1.0 + 1e-6) return false;
  const S w = 0.5 * sqrt(1.0 + trace);
  const V3<S> v{(r[2][1] - r[1][2]) / (4.0 * w), (r[0][2] - r[2][0]) / (4.0 * w), (r[1][0] - r[0][1]) / (4.0 * w)};
  const S s2 = dot(v, v);
  const S t2 = s2 / (w * w);
  S scale;  // θ = scale · v
  if (value_of(t2) < 1e-4) {
    scale = 2.0 / w * (1.0 - t2 / 3.0 + t2 * t2 / 5.0 - t2 * t2 * t2 / 7.0 + t2 * t2 * t2 * t2 / 9.0);
  } else {
    const S s = sqrt(s2);
    scale = 2.0 * atan2(s, w) / s;
  }
  theta = {scale * v[0], scale * v[1], scale * v[2]};
  return true;
}

/// The element's frame as its columns e1, e2, e3 (header); false when the element has no frame
/// (a collapsed shell, a beam whose nodes' n1 have turned against each other by π).
template <class S>
bool element_frame(CorotationalFrame kind, const std::vector<V3<S>>& x, const std::vector<M3<S>>& rot, const Vec3& n1,
                   std::array<V3<S>, 3>& frame) {
  V3<S> e1, normal;
  if (kind == CorotationalFrame::Beam) {
    const std::size_t end = x.size() - 1;  // the end nodes: first and last (B32: end, middle, end)
    e1 = normalized(V3<S>{x[end][0] - x[0][0], x[end][1] - x[0][1], x[end][2] - x[0][2]});
    V3<S> q;  // (R_1 + R_2) n1⁰ of the end nodes
    for (int i = 0; i < 3; ++i)
      q[i] = (rot[0][i][0] + rot[end][i][0]) * n1[0] + (rot[0][i][1] + rot[end][i][1]) * n1[1] +
             (rot[0][i][2] + rot[end][i][2]) * n1[2];
    normal = cross(e1, q);
    if (!(value_of(dot(normal, normal)) > 1e-12)) return false;  // e1 unit, |q| ≤ 2
  } else {
    V3<S> g1, g2;
    if (x.size() == 3) {
      for (int i = 0; i < 3; ++i) g1[i] = x[1][i] - x[0][i], g2[i] = x[2][i] - x[0][i];
    } else {
      for (int i = 0; i < 3; ++i)
        g1[i] = x[1][i] + x[2][i] - x[0][i] - x[3][i], g2[i] = x[2][i] + x[3][i] - x[0][i] - x[1][i];
    }
    normal = cross(g1, g2);
    e1 = g1;
    if (!(value_of(dot(normal, normal)) > 1e-12 * value_of(dot(g1, g1)) * value_of(dot(g2, g2)))) return false;
  }
  const V3<S> e3 = normalized(normal);
  const S along = dot(e1, e3);
  e1 = normalized(V3<S>{e1[0] - along * e3[0], e1[1] - along * e3[1], e1[2] - along * e3[2]});
  frame = {e1, cross(e3, e1), e3};
  return true;
}

/// The element's reference configuration: its frame E0 (columns) and centroid C, in doubles.
struct Reference {
  std::array<Vec3, 3> frame{};
  Vec3 centroid{};
};

bool reference_of(CorotationalFrame kind, std::span<const Vec3> coords, const Vec3& beam_n1, Reference& ref) {
  const std::size_t n = coords.size();
  const std::vector<Vec3> x(coords.begin(), coords.end());
  const std::vector<M3<double>> identity(n, M3<double>{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}});
  if (!element_frame(kind, x, identity, beam_n1, ref.frame)) return false;
  ref.centroid = {};
  for (const Vec3& p : coords)
    for (int i = 0; i < 3; ++i) ref.centroid[i] += p[i] / static_cast<double>(n);
  return true;
}

/// The deformation d(q) the small-strain kernel sees (header), N = 6 × nodes values; false when
/// the element has no frame or a node has turned by π or more against it.
template <class S>
bool deformation(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref, const std::vector<S>& q,
                 const Vec3& beam_n1, std::vector<S>& d) {
  const std::size_t n = coords.size();
  std::vector<V3<S>> x(n);
  std::vector<M3<S>> rot(n);
  for (std::size_t a = 0; a < n; ++a) {
    rot[a] = exp_rotation(V3<S>{q[3 * (n + a)], q[3 * (n + a) + 1], q[3 * (n + a) + 2]});
    for (int i = 0; i < 3; ++i) x[a][i] = q[3 * a + i] + coords[a][i];
  }
  std::array<V3<S>, 3> now;
  if (!element_frame(kind, x, rot, beam_n1, now)) return false;
  const std::array<Vec3, 3>& then = ref.frame;
  M3<S> back;  // A = E0 R_rᵀ
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) back[i][j] = then[0][i] * now[0][j] + then[1][i] * now[1][j] + then[2][i] * now[2][j];
  V3<S> c = x[0];
  for (std::size_t a = 1; a < n; ++a)
    for (int i = 0; i < 3; ++i) c[i] += x[a][i];
  for (int i = 0; i < 3; ++i) c[i] /= static_cast<double>(n);
  d.resize(6 * n);
  for (std::size_t a = 0; a < n; ++a) {
    const V3<S> turned = times(back, V3<S>{x[a][0] - c[0], x[a][1] - c[1], x[a][2] - c[2]});
    for (int i = 0; i < 3; ++i) d[3 * a + i] = turned[i] - (coords[a][i] - ref.centroid[i]);
    V3<S> theta;
    if (!log_rotation(times(back, rot[a]), theta)) return false;
    for (int i = 0; i < 3; ++i) d[3 * (n + a) + i] = theta[i];
  }
  return true;
}

/// d(q), J = ∂d/∂q (row-major, N × N) and, for a g handed in, ∇²(g·d): first-order forward
/// differentiation for d and J, second-order (forward over forward) for the Hessian.
template <int N>
struct DeformationDerivatives {
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, N, 1>>;

  /// d and J at q.
  bool first(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref, std::span<const double> q,
             const Vec3& beam_n1) {
    std::vector<Inner> qs(N), d;
    for (int j = 0; j < N; ++j) qs[j] = Inner(q[j], N, j);
    if (!deformation(kind, coords, ref, qs, beam_n1, d)) return false;
    for (int r = 0; r < N; ++r) {
      value[r] = d[r].value();
      for (int j = 0; j < N; ++j) jacobian[r * N + j] = d[r].derivatives()(j);
    }
    return true;
  }

  /// ∇²(g·d) at q into `hessian` (N × N).
  void second(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref, std::span<const double> q,
              const Vec3& beam_n1, std::span<const double> g, std::vector<double>& hessian) const {
    std::vector<Outer> qs(N), d;
    for (int j = 0; j < N; ++j) {
      qs[j].value() = Inner(q[j], N, j);
      qs[j].derivatives() = Eigen::Matrix<Inner, N, 1>::Constant(Inner(0.0, Eigen::Matrix<double, N, 1>::Zero()));
      qs[j].derivatives()(j) = Inner(1.0, Eigen::Matrix<double, N, 1>::Zero());
    }
    deformation(kind, coords, ref, qs, beam_n1, d);  // succeeded in first()
    Outer work = g[0] * d[0];
    for (int r = 1; r < N; ++r) work += g[r] * d[r];
    hessian.resize(N * N);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) hessian[i * N + j] = work.derivatives()(i).derivatives()(j);
  }

  std::vector<double> value = std::vector<double>(N), jacobian = std::vector<double>(N * N);
};

/// Internal force Jᵀg and tangent Jᵀ K J + ∇²(g·d), J = ∂d/∂q, with g and K the small-strain
/// kernel's force and tangent at d (for an elastic kernel, the gradient and Hessian of its
/// energy; for a path-dependent one the same expressions with its consistent tangent). The
/// force alone needs only J. False when the element has no frame or log (header).
template <int N>
bool corotated_system(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref,
                      std::span<const double> q, const Vec3& beam_n1, const SmallStrainKernel& kernel,
                      const ElementRequest& request, ElementSystem& out) {
  DeformationDerivatives<N> dd;
  if (!dd.first(kind, coords, ref, q, beam_n1)) return false;
  ElementSystem local;
  ElementRequest at_d = request;
  at_d.nlgeom = false;
  at_d.internal_force = true;
  kernel(dd.value, at_d, local);
  out.min_jacobian = local.min_jacobian;
  out.points = std::move(local.points);
  if (local.min_jacobian <= 0.0) return true;  // the caller reports the degenerate element
  const std::vector<double>& jac = dd.jacobian;
  const std::vector<double>& g = local.internal_force;
  if (request.internal_force)
    for (int i = 0; i < N; ++i)
      for (int r = 0; r < N; ++r) out.internal_force[i] += jac[r * N + i] * g[r];
  if (!request.stiffness) return true;
  std::vector<double> hessian;
  dd.second(kind, coords, ref, q, beam_n1, g, hessian);
  const std::vector<double>& k = local.stiffness;
  std::vector<double> kj(N * N, 0.0);  // K J
  for (int r = 0; r < N; ++r)
    for (int s = 0; s < N; ++s)
      if (k[r * N + s] != 0.0)
        for (int j = 0; j < N; ++j) kj[r * N + j] += k[r * N + s] * jac[s * N + j];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      double kij = hessian[i * N + j];
      for (int r = 0; r < N; ++r) kij += jac[r * N + i] * kj[r * N + j];
      out.stiffness[static_cast<std::size_t>(i * N + j)] = kij;
    }
  return true;
}

}  // namespace

bool takes_finite_rotations(const model::ElementTypeInfo& type) {
  if (model::is_beam(type)) return type.n_nodes == 2 || type.n_nodes == 3;
  return model::is_shell(type) && (type.n_nodes == 3 || type.n_nodes == 4);
}

std::array<Vec3, 3> rotation_exp(const Vec3& psi) { return exp_rotation(psi); }

Vec3 rotation_log(const std::array<Vec3, 3>& rotation) {
  Vec3 theta{};
  if (!log_rotation(rotation, theta)) throw std::domain_error("rotation_log: a rotation by π has no unique vector");
  return theta;
}

void compute_corotational(CorotationalFrame frame, std::span<const Vec3> coords, std::span<const double> q,
                          const Vec3& beam_n1, const SmallStrainKernel& kernel, const ElementRequest& request,
                          ElementSystem& out) {
  const int n_dof = static_cast<int>(q.size());
  if (n_dof != 6 * static_cast<int>(coords.size())) throw std::invalid_argument("compute_corotational: size mismatch");
  if (n_dof != 12 && n_dof != 18 && n_dof != 24)
    throw std::invalid_argument("compute_corotational: beams and three- or four-node shells only");
  begin_element_system(out, n_dof, request);
  out.min_jacobian = 0.0;
  Reference ref;
  if (!reference_of(frame, coords, beam_n1, ref)) return;  // degenerate: min_jacobian 0, reported by the caller
  bool framed = false;
  switch (n_dof) {
    case 12: framed = corotated_system<12>(frame, coords, ref, q, beam_n1, kernel, request, out); break;
    case 18: framed = corotated_system<18>(frame, coords, ref, q, beam_n1, kernel, request, out); break;
    case 24: framed = corotated_system<24>(frame, coords, ref, q, beam_n1, kernel, request, out); break;
    default: break;  // checked above
  }
  if (!framed) {
    out.min_jacobian = 1.0;  // the reference is sound; the motion is not
    out.min_volume_ratio = 0.0;
  }
}

}  // namespace inpact::solver::elements
