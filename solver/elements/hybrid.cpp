#include "hybrid.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace inpact::solver::elements {

using model::ElementFamily;

namespace {

using Row = Eigen::RowVectorXd;
using B6 = Eigen::Matrix<double, 6, Eigen::Dynamic>;

/// The projection onto the pressure functions N (m × n): Θ_q = Σ_r P(q, r) J_r, with
/// P = Nᵀ M⁻¹ N diag(dV), M = N diag(dV) Nᵀ; `coeff` (n × m) = Nᵀ M⁻¹, the functions' weights
/// of a point.
Eigen::MatrixXd projection(const Eigen::MatrixXd& N, const std::vector<PointData>& pts, Eigen::MatrixXd& coeff) {
  const auto n = static_cast<Eigen::Index>(pts.size());
  Eigen::VectorXd dv(n);
  for (Eigen::Index q = 0; q < n; ++q) dv(q) = pts[static_cast<std::size_t>(q)].dv;
  const Eigen::MatrixXd M = N * dv.asDiagonal() * N.transpose();
  coeff = M.ldlt().solve(N).transpose();
  return coeff * N * dv.asDiagonal();
}

/// ∂vec(F)/∂u (9 × n_dof, row 3i + k: F_ik), F linear in u.
Eigen::MatrixXd deformation_operator(ElementFamily family, int dim, const PointData& pd) {
  const int n = static_cast<int>(pd.N.size());
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(9, n * dim);
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < dim; ++i)
      for (int k = 0; k < 3; ++k) G(3 * i + k, a * dim + i) = pd.grad(a, k);
    if (family == ElementFamily::Axisymmetric) G(8, a * dim) += pd.N(a) / pd.radius;  // F33 = 1 + u_r/R
  }
  return G;
}

/// B-bar: ε̄ = ε + ⅓ (θ̄ − tr ε) 1 with θ̄ = P tr ε.
HybridSystem small_strain(const model::ElementTypeInfo& type, const Material& law, const std::vector<PointData>& pts,
                          const Eigen::MatrixXd& P, const Eigen::VectorXd& u, bool want_k,
                          const ElementHistory& history) {
  const std::size_t n = pts.size();
  const Eigen::Index nd = u.size();
  std::vector<B6> B(n);
  std::vector<Row> div(n);
  for (std::size_t q = 0; q < n; ++q) {
    B[q] = strain_operator(type.family, type.dim, Eigen::Matrix3d::Identity(), pts[q]);
    div[q] = B[q].row(0) + B[q].row(1) + B[q].row(2);
  }
  HybridSystem r;
  r.f = Eigen::VectorXd::Zero(nd);
  if (want_k) r.K = Eigen::MatrixXd::Zero(nd, nd);
  Mat6 scratch;
  for (std::size_t q = 0; q < n; ++q) {
    Row div_bar = Row::Zero(nd);
    for (std::size_t s = 0; s < n; ++s) div_bar += P(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(s)) * div[s];
    B6 Bb = B[q];
    for (int k = 0; k < 3; ++k) Bb.row(k) += (div_bar - div[q]) / 3.0;
    PointState& st = r.states.emplace_back(point_kinematics(type.family, type.dim, false, pts[q], u));
    st.strain = Bb * u;
    const Mat6& D = law.update({st.F, st.strain, pts[q].thermal_strain, &pts[q].x, false, pts[q].temperature}, history.at(q),
                                st.stress, scratch);
    r.f.noalias() += Bb.transpose() * st.stress * pts[q].dv;
    if (want_k) r.K.noalias() += Bb.transpose() * (D * pts[q].dv) * Bb;
  }
  return r;
}

/// J, ∂J/∂u and (want_k) ∂²J/∂u² at a point: ∂J = J F⁻ᵀ : ∂F,
/// ∂²J = ∂Jᵀ∂J / J − J tr(F⁻¹ ∂F F⁻¹ ∂F).
struct Dilatation {
  double J = 1.0;
  Row dJ;
  Eigen::MatrixXd d2J;
};

Dilatation dilatation(const Eigen::Matrix3d& F, const Eigen::MatrixXd& G, bool want_k) {
  Dilatation d;
  d.J = F.determinant();
  const Eigen::Matrix3d Fi = F.inverse();
  Eigen::Matrix<double, 1, 9> cof;  // ∂J/∂F_ik = J F⁻¹_ki
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) cof(3 * i + k) = d.J * Fi(k, i);
  d.dJ = cof * G;
  if (!want_k) return d;
  Eigen::Matrix<double, 9, 9> T;  // tr(F⁻¹ X F⁻¹ Y) = vec(X)ᵀ T vec(Y), T(3b + c, 3e + a) = F⁻¹_ab F⁻¹_ce
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        for (int e = 0; e < 3; ++e) T(3 * b + c, 3 * e + a) = Fi(a, b) * Fi(c, e);
  d.d2J = d.dJ.transpose() * d.dJ / d.J - d.J * (G.transpose() * T * G);
  return d;
}

/// One point's share with F̄ = φF, φ = (Θ/J)^(1/3): Ē = ½(φ² C − I), ∂Ē = φ² ∂E + φ C ∂φ,
/// S̄ : ∂²Ē = φ² S̄ : ∂²E + 2φ (S̄:∂E ⊗ ∂φ + ∂φ ⊗ S̄:∂E) + (S̄ : C)(∂φ ⊗ ∂φ + φ ∂²φ).
void finite_strain_point(const model::ElementTypeInfo& type, const Material& law, const PointData& pd,
                         const PointHistory& history, const Eigen::Matrix3d& F, const Dilatation& d, double theta,
                         const Row& dtheta, const Eigen::MatrixXd* d2theta, HybridSystem& r) {
  const double phi = std::cbrt(theta / d.J);
  const Eigen::Matrix3d C = F.transpose() * F;
  PointState& st = r.states.emplace_back();
  st.F = phi * F;
  const Eigen::Matrix3d Eb = 0.5 * (phi * phi * C - Eigen::Matrix3d::Identity());
  st.strain << Eb(0, 0), Eb(1, 1), Eb(2, 2), 2 * Eb(0, 1), 2 * Eb(0, 2), 2 * Eb(1, 2);
  Mat6 scratch;
  const Mat6& D = law.update({st.F, st.strain, pd.thermal_strain, &pd.x, true, pd.temperature}, history, st.stress, scratch);
  const B6 B = strain_operator(type.family, type.dim, F, pd);
  const Row dphi = phi / 3 * (dtheta / theta - d.dJ / d.J);
  Vec6 c;
  c << C(0, 0), C(1, 1), C(2, 2), 2 * C(0, 1), 2 * C(0, 2), 2 * C(1, 2);
  const B6 Bb = phi * phi * B + phi * c * dphi;
  r.f.noalias() += Bb.transpose() * st.stress * pd.dv;
  if (!d2theta) return;
  r.K.noalias() += Bb.transpose() * (D * pd.dv) * Bb;
  add_geometric_stiffness(type.family, type.dim, pd, st.stress, pd.dv * phi * phi, r.K);
  const Row sB = st.stress.transpose() * B;
  r.K.noalias() += (2 * phi * pd.dv) * (sB.transpose() * dphi + dphi.transpose() * sB);
  const Eigen::MatrixXd d2phi = dphi.transpose() * dphi / phi +
                                phi / 3 * (*d2theta / theta - dtheta.transpose() * dtheta / (theta * theta) -
                                           d.d2J / d.J + d.dJ.transpose() * d.dJ / (d.J * d.J));
  r.K.noalias() += (st.stress.dot(c) * pd.dv) * (dphi.transpose() * dphi + phi * d2phi);
}

/// Total Lagrangian with F̄ = (Θ/J)^(1/3) F, Θ = P J.
HybridSystem finite_strain(const model::ElementTypeInfo& type, const Material& law, const std::vector<PointData>& pts,
                           const Eigen::MatrixXd& basis, const Eigen::MatrixXd& P, const Eigen::MatrixXd& coeff,
                           const Eigen::VectorXd& u, bool want_k, const ElementHistory& history) {
  const std::size_t n = pts.size();
  const Eigen::Index nd = u.size(), m = basis.rows();
  std::vector<Eigen::Matrix3d> F(n);
  std::vector<Dilatation> dil(n);
  for (std::size_t q = 0; q < n; ++q) {
    F[q] = point_kinematics(type.family, type.dim, true, pts[q], u).F;
    dil[q] = dilatation(F[q], deformation_operator(type.family, type.dim, pts[q]), want_k);
  }
  // Σ_r N_k(r) dV_r ∂²J_r per pressure function: ∂²Θ_q = Σ_k coeff(q, k) H_k.
  std::vector<Eigen::MatrixXd> H(want_k ? static_cast<std::size_t>(m) : 0, Eigen::MatrixXd::Zero(nd, nd));
  for (std::size_t k = 0; k < H.size(); ++k)
    for (std::size_t s = 0; s < n; ++s)
      H[k] += basis(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(s)) * pts[s].dv * dil[s].d2J;
  HybridSystem r;
  r.f = Eigen::VectorXd::Zero(nd);
  if (want_k) r.K = Eigen::MatrixXd::Zero(nd, nd);
  Eigen::MatrixXd d2theta;
  for (std::size_t q = 0; q < n; ++q) {
    const auto qi = static_cast<Eigen::Index>(q);
    double theta = 0.0;
    Row dtheta = Row::Zero(nd);
    for (std::size_t s = 0; s < n; ++s) {
      theta += P(qi, static_cast<Eigen::Index>(s)) * dil[s].J;
      dtheta += P(qi, static_cast<Eigen::Index>(s)) * dil[s].dJ;
    }
    if (want_k) {
      d2theta = Eigen::MatrixXd::Zero(nd, nd);
      for (std::size_t k = 0; k < H.size(); ++k) d2theta += coeff(qi, static_cast<Eigen::Index>(k)) * H[k];
    }
    finite_strain_point(type, law, pts[q], history.at(q), F[q], dil[q], theta, dtheta, want_k ? &d2theta : nullptr, r);
  }
  return r;
}

}  // namespace

Eigen::MatrixXd pressure_basis(const model::ElementTypeInfo& type, const std::vector<std::array<double, 3>>& xi) {
  const auto n = static_cast<Eigen::Index>(xi.size());
  const int m = type.order == 1 ? 1 : 1 + type.dim;
  Eigen::MatrixXd N(m, n);
  for (Eigen::Index q = 0; q < n; ++q) {
    N(0, q) = 1.0;
    for (int k = 1; k < m; ++k) N(k, q) = xi[static_cast<std::size_t>(q)][static_cast<std::size_t>(k - 1)];
  }
  return N;
}

HybridSystem assemble_hybrid(const model::ElementTypeInfo& type, const Material& law, bool nlgeom,
                             const std::vector<PointData>& pts, const Eigen::MatrixXd& basis,
                             const Eigen::VectorXd& u, bool want_k, const ElementHistory& history) {
  Eigen::MatrixXd coeff;
  const Eigen::MatrixXd P = projection(basis, pts, coeff);
  if (!nlgeom) return small_strain(type, law, pts, P, u, want_k, history);
  return finite_strain(type, law, pts, basis, P, coeff, u, want_k, history);
}

}  // namespace inpact::solver::elements
