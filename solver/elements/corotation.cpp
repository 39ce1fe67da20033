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

/// atan2(y, x) in S's own derivative type: Eigen's AutoDiff atan2 returns a dynamic-size one,
/// which allocates and does not nest.
template <class S>
S angle(const S& y, const S& x) {
  if constexpr (std::is_arithmetic_v<S>) {
    return std::atan2(y, x);
  } else {
    S r;
    r.value() = angle(y.value(), x.value());
    const auto hypot2 = y.value() * y.value() + x.value() * x.value();
    r.derivatives() = (y.derivatives() * x.value() - x.derivatives() * y.value()) / hypot2;
    return r;
  }
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
    scale = 2.0 * angle(s, w) / s;
  }
  theta = {scale * v[0], scale * v[1], scale * v[2]};
  return true;
}

/// The element's frame as its columns e1, e2, e3 (header) from its frame nodes (`FrameNodes`):
/// a beam's end nodes' positions and rotations, a shell's corner positions. False when the
/// element has no frame (a collapsed shell, a beam whose ends' n1 have turned against each other
/// by π).
template <class S>
bool element_frame(CorotationalFrame kind, const std::vector<V3<S>>& x, const std::vector<M3<S>>& rot, const Vec3& n1,
                   std::array<V3<S>, 3>& frame) {
  V3<S> e1, normal;
  if (kind == CorotationalFrame::Beam) {
    e1 = normalized(V3<S>{x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]});
    V3<S> q;  // (R_1 + R_2) n1⁰ of the end nodes
    for (int i = 0; i < 3; ++i)
      q[i] = (rot[0][i][0] + rot[1][i][0]) * n1[0] + (rot[0][i][1] + rot[1][i][1]) * n1[1] +
             (rot[0][i][2] + rot[1][i][2]) * n1[2];
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

/// The nodes whose motion turns the frame: a beam's end nodes (first and last; a B32's middle
/// node moves and turns against the frame like any other), a shell's corners (the first three or
/// four; an S8's midside nodes follow).
std::vector<int> frame_nodes(CorotationalFrame kind, int n) {
  if (kind == CorotationalFrame::Beam) return {0, n - 1};
  return n == 3 ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1, 2, 3};
}

/// The element's reference configuration: its frame E0 (columns) and centroid C, in doubles.
struct Reference {
  std::array<Vec3, 3> frame{};
  Vec3 centroid{};
};

bool reference_of(CorotationalFrame kind, std::span<const Vec3> coords, const Vec3& beam_n1, Reference& ref) {
  const int n = static_cast<int>(coords.size());
  std::vector<Vec3> x;
  for (int a : frame_nodes(kind, n)) x.push_back(coords[a]);
  const std::vector<M3<double>> identity(x.size(), M3<double>{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}});
  if (!element_frame(kind, x, identity, beam_n1, ref.frame)) return false;
  ref.centroid = {};
  for (const Vec3& p : coords)
    for (int i = 0; i < 3; ++i) ref.centroid[i] += p[i] / static_cast<double>(n);
  return true;
}

/// One node's deformation d_a = (ū_a, θ̄_a) depends on few of the element's unknowns: those that
/// turn the frame (12 at most: a beam's end translations and rotations, a shell's corner
/// translations), the node's own translation and rotation, and the mean translation (the
/// centroid). Differentiating d_a in these 21 local variables v and mapping them back through the
/// linear map v = P q costs far less than differentiating the whole element's d in its 6n
/// unknowns, and the second-order numbers stay small (22² doubles) for every element size.
constexpr int kFrameVars = 12, kOwnTranslation = 12, kOwnRotation = 15, kMeanTranslation = 18, kLocal = 21;

/// P: the local variable `local` takes `weight` × the element's unknown `global`.
struct LocalTerm {
  int local;
  int global;
  double weight;
};

std::vector<LocalTerm> local_map(CorotationalFrame kind, int n, int a) {
  std::vector<LocalTerm> p;
  const std::vector<int> framing = frame_nodes(kind, n);
  for (std::size_t k = 0; k < framing.size(); ++k)
    for (int i = 0; i < 3; ++i) p.push_back({static_cast<int>(3 * k) + i, 3 * framing[k] + i, 1.0});
  if (kind == CorotationalFrame::Beam)  // slots 6..11: the end nodes' rotations
    for (std::size_t k = 0; k < framing.size(); ++k)
      for (int i = 0; i < 3; ++i) p.push_back({6 + static_cast<int>(3 * k) + i, 3 * (n + framing[k]) + i, 1.0});
  for (int i = 0; i < 3; ++i) {
    p.push_back({kOwnTranslation + i, 3 * a + i, 1.0});
    p.push_back({kOwnRotation + i, 3 * (n + a) + i, 1.0});
    for (int b = 0; b < n; ++b) p.push_back({kMeanTranslation + i, 3 * b + i, 1.0 / n});
  }
  return p;
}

/// d_a (6 values) from the local variables v (local_map); false when the element has no frame or
/// the node has turned by π or more against it.
template <class S>
bool node_deformation(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref, int a,
                      const Vec3& beam_n1, const std::array<S, kLocal>& v, std::array<S, 6>& d) {
  const int n = static_cast<int>(coords.size());
  const std::vector<int> framing = frame_nodes(kind, n);
  std::vector<V3<S>> x(framing.size());
  std::vector<M3<S>> rot;
  for (std::size_t k = 0; k < framing.size(); ++k)
    for (int i = 0; i < 3; ++i) x[k][i] = v[3 * k + i] + coords[framing[k]][i];
  if (kind == CorotationalFrame::Beam)
    for (std::size_t k = 0; k < framing.size(); ++k)
      rot.push_back(exp_rotation(V3<S>{v[6 + 3 * k], v[7 + 3 * k], v[8 + 3 * k]}));
  std::array<V3<S>, 3> now;
  if (!element_frame(kind, x, rot, beam_n1, now)) return false;
  const std::array<Vec3, 3>& then = ref.frame;
  M3<S> back;  // A = E0 R_rᵀ
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) back[i][j] = then[0][i] * now[0][j] + then[1][i] * now[1][j] + then[2][i] * now[2][j];
  V3<S> relative;  // x_a − c
  for (int i = 0; i < 3; ++i)
    relative[i] = v[kOwnTranslation + i] + coords[a][i] - v[kMeanTranslation + i] - ref.centroid[i];
  const V3<S> turned = times(back, relative);
  for (int i = 0; i < 3; ++i) d[i] = turned[i] - (coords[a][i] - ref.centroid[i]);
  const M3<S> own = exp_rotation(V3<S>{v[kOwnRotation], v[kOwnRotation + 1], v[kOwnRotation + 2]});
  V3<S> theta;
  if (!log_rotation(times(back, own), theta)) return false;
  for (int i = 0; i < 3; ++i) d[3 + i] = theta[i];
  return true;
}

/// The rows of d and J = ∂d/∂q that belong to node a's ū and θ̄.
std::array<int, 6> node_rows(int n, int a) { return {3 * a, 3 * a + 1, 3 * a + 2, 3 * (n + a), 3 * (n + a) + 1, 3 * (n + a) + 2}; }

/// d(q), J = ∂d/∂q (row-major, N × N) and, for a g handed in, ∇²(g·d) (N × N): node by node,
/// first-order forward differentiation in the node's local variables for d and J, second-order
/// (forward over forward) for the Hessian.
class DeformationDerivatives {
 public:
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, kLocal, 1>>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, kLocal, 1>>;

  DeformationDerivatives(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref,
                         std::span<const double> q, const Vec3& beam_n1)
      : kind_(kind), coords_(coords), ref_(ref), q_(q), n1_(beam_n1), n_(static_cast<int>(coords.size())) {}

  /// d and J at q; false when the element has no frame or a node no log.
  bool first() {
    const std::size_t size = q_.size();
    value.assign(size, 0.0);
    jacobian.assign(size * size, 0.0);
    for (int a = 0; a < n_; ++a) {
      const std::vector<LocalTerm> p = local_map(kind_, n_, a);
      const std::array<double, kLocal> v0 = local_values(p);
      std::array<Inner, kLocal> v;
      for (int l = 0; l < kLocal; ++l) v[l] = Inner(v0[l], kLocal, l);
      std::array<Inner, 6> d;
      if (!node_deformation(kind_, coords_, ref_, a, n1_, v, d)) return false;
      const std::array<int, 6> rows = node_rows(n_, a);
      for (int r = 0; r < 6; ++r) {
        value[rows[r]] = d[r].value();
        for (const LocalTerm& t : p) jacobian[rows[r] * size + t.global] += t.weight * d[r].derivatives()(t.local);
      }
    }
    return true;
  }

  /// ∇²(g·d) at q (after first() succeeded): Σ_a Pᵀ ∇²_v(g_a·d_a) P.
  void second(std::span<const double> g, std::vector<double>& hessian) const {
    const std::size_t size = q_.size();
    hessian.assign(size * size, 0.0);
    for (int a = 0; a < n_; ++a) {
      const std::vector<LocalTerm> p = local_map(kind_, n_, a);
      const std::array<double, kLocal> v0 = local_values(p);
      std::array<Outer, kLocal> v;
      for (int l = 0; l < kLocal; ++l) {
        v[l].value() = Inner(v0[l], kLocal, l);
        v[l].derivatives() =
            Eigen::Matrix<Inner, kLocal, 1>::Constant(Inner(0.0, Eigen::Matrix<double, kLocal, 1>::Zero()));
        v[l].derivatives()(l) = Inner(1.0, Eigen::Matrix<double, kLocal, 1>::Zero());
      }
      std::array<Outer, 6> d;
      node_deformation(kind_, coords_, ref_, a, n1_, v, d);  // succeeded in first()
      const std::array<int, 6> rows = node_rows(n_, a);
      Outer work = g[rows[0]] * d[0];
      for (int r = 1; r < 6; ++r) work += g[rows[r]] * d[r];
      for (const LocalTerm& s : p)
        for (const LocalTerm& t : p)
          hessian[s.global * size + t.global] +=
              s.weight * t.weight * work.derivatives()(s.local).derivatives()(t.local);
    }
  }

  std::vector<double> value, jacobian;

 private:
  std::array<double, kLocal> local_values(const std::vector<LocalTerm>& p) const {
    std::array<double, kLocal> v{};
    for (const LocalTerm& t : p) v[t.local] += t.weight * q_[t.global];
    return v;
  }

  CorotationalFrame kind_;
  std::span<const Vec3> coords_;
  const Reference& ref_;
  std::span<const double> q_;
  Vec3 n1_;
  int n_;
};

/// Internal force Jᵀg and tangent Jᵀ K J + ∇²(g·d), J = ∂d/∂q, with g and K the small-strain
/// kernel's force and tangent at d (for an elastic kernel, the gradient and Hessian of its
/// energy; for a path-dependent one the same expressions with its consistent tangent). The
/// force alone needs only J. False when the element has no frame or log (header).
bool corotated_system(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref,
                      std::span<const double> q, const Vec3& beam_n1, const SmallStrainKernel& kernel,
                      const ElementRequest& request, ElementSystem& out) {
  const int size = static_cast<int>(q.size());
  DeformationDerivatives dd(kind, coords, ref, q, beam_n1);
  if (!dd.first()) return false;
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
    for (int i = 0; i < size; ++i)
      for (int r = 0; r < size; ++r) out.internal_force[i] += jac[r * size + i] * g[r];
  if (!request.stiffness) return true;
  std::vector<double> hessian;
  dd.second(g, hessian);
  const std::vector<double>& k = local.stiffness;
  std::vector<double> kj(static_cast<std::size_t>(size * size), 0.0);  // K J
  for (int r = 0; r < size; ++r)
    for (int s = 0; s < size; ++s)
      if (k[r * size + s] != 0.0)
        for (int j = 0; j < size; ++j) kj[r * size + j] += k[r * size + s] * jac[s * size + j];
  for (int i = 0; i < size; ++i)
    for (int j = 0; j < size; ++j) {
      double kij = hessian[i * size + j];
      for (int r = 0; r < size; ++r) kij += jac[r * size + i] * kj[r * size + j];
      out.stiffness[static_cast<std::size_t>(i * size + j)] = kij;
    }
  return true;
}

}  // namespace

bool takes_finite_rotations(const model::ElementTypeInfo& type) {
  if (model::is_beam(type)) return type.n_nodes == 2 || type.n_nodes == 3;
  return model::is_shell(type) && (type.n_nodes == 3 || type.n_nodes == 4 || type.n_nodes == 8);
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
  const std::size_t nodes = coords.size();
  const bool known = frame == CorotationalFrame::Beam ? nodes == 2 || nodes == 3 : nodes == 3 || nodes == 4 || nodes == 8;
  if (!known) throw std::invalid_argument("compute_corotational: beams and three-, four- or eight-node shells only");
  begin_element_system(out, n_dof, request);
  out.min_jacobian = 0.0;
  Reference ref;
  if (!reference_of(frame, coords, beam_n1, ref)) return;  // degenerate: min_jacobian 0, reported by the caller
  const bool framed = corotated_system(frame, coords, ref, q, beam_n1, kernel, request, out);
  if (!framed) {
    out.min_jacobian = 1.0;  // the reference is sound; the motion is not
    out.min_volume_ratio = 0.0;
  }
}

}  // namespace inpact::solver::elements
