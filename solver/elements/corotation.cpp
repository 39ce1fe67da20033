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

/// The element's frame as its columns e1, e2, e3 (header) from its frame nodes (frame_nodes):
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
/// four; an S8's or S6's midside nodes follow).
std::vector<int> frame_nodes(CorotationalFrame kind, int n) {
  if (kind == CorotationalFrame::Beam) return {0, n - 1};
  return n == 3 || n == 6 ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1, 2, 3};
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

/// The derivatives by the chain rule through the frame. d depends on q through
///  - A = E0 R_rᵀ, a function of the 12 frame variables f (the frame nodes' translations; a beam's
///    end rotations too), differentiated once per element;
///  - ū_a = A y_a − Y_a with y_a = x_a − c linear in q (bilinear in A and y: by hand);
///  - θ̄_a = log(A exp([ψ_a]×)), a function of A's 9 entries and ψ_a, differentiated per node.
/// Every AutoDiff number is 12 wide (13 doubles; 13² nested), whatever the element's size.
constexpr int kVars = 12;
using First = Eigen::AutoDiffScalar<Eigen::Matrix<double, kVars, 1>>;
using Second = Eigen::AutoDiffScalar<Eigen::Matrix<First, kVars, 1>>;

/// A value with its gradient and (for Second) Hessian in the 12 variables.
struct Expansion {
  double value = 0.0;
  std::array<double, kVars> gradient{};
  std::array<double, kVars * kVars> hessian{};
};

template <class S>
std::array<S, kVars> seeded(const std::array<double, kVars>& v) {
  std::array<S, kVars> x;
  for (int l = 0; l < kVars; ++l) {
    if constexpr (std::is_same_v<S, First>) {
      x[l] = First(v[l], kVars, l);
    } else {
      x[l].value() = First(v[l], kVars, l);
      x[l].derivatives() = Eigen::Matrix<First, kVars, 1>::Constant(First(0.0, Eigen::Matrix<double, kVars, 1>::Zero()));
      x[l].derivatives()(l) = First(1.0, Eigen::Matrix<double, kVars, 1>::Zero());
    }
  }
  return x;
}

template <class S>
Expansion expand(const S& s) {
  Expansion e;
  if constexpr (std::is_same_v<S, First>) {
    e.value = s.value();
    for (int k = 0; k < kVars; ++k) e.gradient[k] = s.derivatives()(k);
  } else {
    e.value = s.value().value();
    for (int k = 0; k < kVars; ++k) {
      e.gradient[k] = s.value().derivatives()(k);
      for (int l = 0; l < kVars; ++l) e.hessian[k * kVars + l] = s.derivatives()(k).derivatives()(l);
    }
  }
  return e;
}

/// A = E0 R_rᵀ (row-major) from the frame variables f: the frame nodes' translations (3 per
/// node), then a beam's end rotations; false when the element has no frame.
template <class S>
bool frame_back(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref, const Vec3& beam_n1,
                const std::array<S, kVars>& f, std::array<S, 9>& back) {
  const std::vector<int> framing = frame_nodes(kind, static_cast<int>(coords.size()));
  std::vector<V3<S>> x(framing.size());
  std::vector<M3<S>> rot;
  for (std::size_t k = 0; k < framing.size(); ++k)
    for (int i = 0; i < 3; ++i) x[k][i] = f[3 * k + i] + coords[framing[k]][i];
  if (kind == CorotationalFrame::Beam)
    for (std::size_t k = 0; k < framing.size(); ++k)
      rot.push_back(exp_rotation(V3<S>{f[6 + 3 * k], f[7 + 3 * k], f[8 + 3 * k]}));
  std::array<V3<S>, 3> now;
  if (!element_frame(kind, x, rot, beam_n1, now)) return false;
  const std::array<Vec3, 3>& then = ref.frame;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      back[3 * i + j] = then[0][i] * now[0][j] + then[1][i] * now[1][j] + then[2][i] * now[2][j];
  return true;
}

/// θ̄ = log(A exp([ψ]×)) from z = (A row-major, ψ); false when the node has turned by π or more
/// against its element.
template <class S>
bool relative_rotation(const std::array<S, kVars>& z, V3<S>& theta) {
  const M3<S> back{V3<S>{z[0], z[1], z[2]}, V3<S>{z[3], z[4], z[5]}, V3<S>{z[6], z[7], z[8]}};
  return log_rotation(times(back, exp_rotation(V3<S>{z[9], z[10], z[11]})), theta);
}

/// d(q), J = ∂d/∂q (row-major, N × N) and ∇²(g·d) (N × N) by the chain rule above.
class DeformationDerivatives {
 public:
  DeformationDerivatives(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref,
                         std::span<const double> q, const Vec3& beam_n1)
      : kind_(kind), coords_(coords), ref_(ref), q_(q), n1_(beam_n1), n_(static_cast<int>(coords.size())),
        size_(q.size()) {}

  /// d and J at q, and with `second` what hessian() needs; false when the element has no frame
  /// or a node no log.
  bool compute(bool second) { return second ? expand_all<Second>() : expand_all<First>(); }

  /// ∇²(g·d) at q, after compute(true).
  std::vector<double> hessian(std::span<const double> g) const;

  std::vector<double> value, jacobian;

 private:
  template <class S>
  bool expand_all();
  void assemble_jacobian();
  int frame_slot(int k) const { return frame_q_[static_cast<std::size_t>(k)]; }
  void add(std::vector<double>& h, int i, int j, double v) const { h[static_cast<std::size_t>(i) * size_ + j] += v; }

  CorotationalFrame kind_;
  std::span<const Vec3> coords_;
  const Reference& ref_;
  std::span<const double> q_;
  Vec3 n1_;
  int n_;
  std::size_t size_;
  std::array<int, kVars> frame_q_{};              // the unknown each frame variable is (−1: none)
  std::array<Expansion, 9> back_;                 // A and its derivatives in f
  std::vector<Vec3> y_;                           // y_a = x_a − c
  std::vector<std::array<Expansion, 3>> theta_;  // θ̄_a and its derivatives in (A, ψ_a)
};

template <class S>
bool DeformationDerivatives::expand_all() {
  frame_q_.fill(-1);
  const std::vector<int> framing = frame_nodes(kind_, n_);
  for (std::size_t k = 0; k < framing.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      frame_q_[3 * k + i] = 3 * framing[k] + i;
      if (kind_ == CorotationalFrame::Beam) frame_q_[6 + 3 * k + i] = 3 * (n_ + framing[k]) + i;
    }
  std::array<double, kVars> f{};
  for (int k = 0; k < kVars; ++k) f[k] = frame_slot(k) < 0 ? 0.0 : q_[frame_slot(k)];
  std::array<S, 9> back;
  if (!frame_back(kind_, coords_, ref_, n1_, seeded<S>(f), back)) return false;
  for (int p = 0; p < 9; ++p) back_[p] = expand(back[p]);
  Vec3 mean{};
  for (int b = 0; b < n_; ++b)
    for (int i = 0; i < 3; ++i) mean[i] += q_[3 * b + i] / n_;
  value.assign(size_, 0.0);
  y_.assign(n_, Vec3{});
  theta_.assign(n_, {});
  for (int a = 0; a < n_; ++a) {
    for (int i = 0; i < 3; ++i) y_[a][i] = coords_[a][i] + q_[3 * a + i] - ref_.centroid[i] - mean[i];
    for (int i = 0; i < 3; ++i) {
      double turned = 0.0;
      for (int j = 0; j < 3; ++j) turned += back_[3 * i + j].value * y_[a][j];
      value[3 * a + i] = turned - (coords_[a][i] - ref_.centroid[i]);
    }
    std::array<double, kVars> z{};
    for (int p = 0; p < 9; ++p) z[p] = back_[p].value;
    for (int j = 0; j < 3; ++j) z[9 + j] = q_[3 * (n_ + a) + j];
    V3<S> theta;
    if (!relative_rotation(seeded<S>(z), theta)) return false;
    for (int i = 0; i < 3; ++i) {
      theta_[a][i] = expand(theta[i]);
      value[3 * (n_ + a) + i] = theta_[a][i].value;
    }
  }
  assemble_jacobian();
  return true;
}

void DeformationDerivatives::assemble_jacobian() {
  jacobian.assign(size_ * size_, 0.0);
  for (int a = 0; a < n_; ++a)
    for (int i = 0; i < 3; ++i) {
      const int u_row = 3 * a + i, t_row = 3 * (n_ + a) + i;
      for (int k = 0; k < kVars; ++k) {
        if (frame_slot(k) < 0) continue;
        double du = 0.0, dt = 0.0;
        for (int j = 0; j < 3; ++j) du += back_[3 * i + j].gradient[k] * y_[a][j];
        for (int p = 0; p < 9; ++p) dt += theta_[a][i].gradient[p] * back_[p].gradient[k];
        add(jacobian, u_row, frame_slot(k), du);
        add(jacobian, t_row, frame_slot(k), dt);
      }
      for (int b = 0; b < n_; ++b)
        for (int j = 0; j < 3; ++j)
          add(jacobian, u_row, 3 * b + j, back_[3 * i + j].value * ((a == b ? 1.0 : 0.0) - 1.0 / n_));
      for (int j = 0; j < 3; ++j) add(jacobian, t_row, 3 * (n_ + a) + j, theta_[a][i].gradient[9 + j]);
    }
}

std::vector<double> DeformationDerivatives::hessian(std::span<const double> g) const {
  std::vector<double> h(size_ * size_, 0.0);
  // ∂W/∂A_p, the weight of A's own Hessian in f: from the translations Σ_a g_a,i y_a,j and the
  // rotations Σ_a g_θa · ∂θ̄_a/∂A_p.
  std::array<double, 9> weight{};
  Vec3 mean_g{};
  for (int a = 0; a < n_; ++a)
    for (int i = 0; i < 3; ++i) mean_g[i] += g[3 * a + i] / n_;
  std::array<double, kVars * kVars> frame_frame{};  // ∂²W/∂f∂f
  for (int a = 0; a < n_; ++a) {
    std::array<double, kVars * kVars> k_a{};  // ∇²_z(g_θa · θ̄_a)
    for (int i = 0; i < 3; ++i) {
      const double gu = g[3 * a + i], gt = g[3 * (n_ + a) + i];
      for (int j = 0; j < 3; ++j) weight[3 * i + j] += gu * y_[a][j];
      for (int p = 0; p < 9; ++p) weight[p] += gt * theta_[a][i].gradient[p];
      for (int m = 0; m < kVars * kVars; ++m) k_a[m] += gt * theta_[a][i].hessian[m];
    }
    // Through A twice: Gᵀ K_AA G; A and ψ_a: Gᵀ K_Aψ; ψ_a twice: K_ψψ.
    for (int k = 0; k < kVars; ++k)
      for (int p = 0; p < 9; ++p) {
        const double gpk = back_[p].gradient[k];
        if (gpk == 0.0) continue;
        for (int r = 0; r < 9; ++r)
          for (int l = 0; l < kVars; ++l) frame_frame[k * kVars + l] += gpk * k_a[p * kVars + r] * back_[r].gradient[l];
      }
    for (int k = 0; k < kVars; ++k) {
      if (frame_slot(k) < 0) continue;
      for (int j = 0; j < 3; ++j) {
        double v = 0.0;
        for (int p = 0; p < 9; ++p) v += back_[p].gradient[k] * k_a[p * kVars + 9 + j];
        add(h, frame_slot(k), 3 * (n_ + a) + j, v);
        add(h, 3 * (n_ + a) + j, frame_slot(k), v);
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(h, 3 * (n_ + a) + i, 3 * (n_ + a) + j, k_a[(9 + i) * kVars + 9 + j]);
    // A and the translations: ∂²(g_a · A y_a)/∂f_k ∂u_b,j = Σ_i ∂A_ij/∂f_k (g_b,i − ḡ_i).
    for (int k = 0; k < kVars; ++k) {
      if (frame_slot(k) < 0) continue;
      for (int j = 0; j < 3; ++j) {
        double v = 0.0;
        for (int i = 0; i < 3; ++i) v += back_[3 * i + j].gradient[k] * (g[3 * a + i] - mean_g[i]);
        add(h, frame_slot(k), 3 * a + j, v);
        add(h, 3 * a + j, frame_slot(k), v);
      }
    }
  }
  for (int p = 0; p < 9; ++p)
    for (int m = 0; m < kVars * kVars; ++m) frame_frame[m] += weight[p] * back_[p].hessian[m];
  for (int k = 0; k < kVars; ++k)
    for (int l = 0; l < kVars; ++l)
      if (frame_slot(k) >= 0 && frame_slot(l) >= 0) add(h, frame_slot(k), frame_slot(l), frame_frame[k * kVars + l]);
  return h;
}

/// Internal force Jᵀg and tangent Jᵀ K J + ∇²(g·d), J = ∂d/∂q, with g and K the small-strain
/// kernel's force and tangent at d (for an elastic kernel, the gradient and Hessian of its
/// energy; for a path-dependent one the same expressions with its consistent tangent). The
/// force alone needs only J. False when the element has no frame or log (header).
bool corotated_system(CorotationalFrame kind, std::span<const Vec3> coords, const Reference& ref,
                      std::span<const double> q, const Vec3& beam_n1, const SmallStrainKernel& kernel,
                      const ElementRequest& request, ElementSystem& out) {
  const int size = static_cast<int>(q.size());
  DeformationDerivatives dd(kind, coords, ref, q, beam_n1);
  if (!dd.compute(request.stiffness)) return false;
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
  const std::vector<double> hessian = dd.hessian(g);
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
  return model::is_shell(type);
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
  const bool known = frame == CorotationalFrame::Beam ? nodes == 2 || nodes == 3 : nodes == 3 || nodes == 4 || nodes == 6 || nodes == 8;
  if (!known) throw std::invalid_argument("compute_corotational: beams and three-, four-, six- or eight-node shells only");
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
