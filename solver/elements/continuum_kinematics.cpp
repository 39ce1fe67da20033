#include "continuum_kinematics.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "voigt.hpp"

namespace inpact::solver::elements {

using model::ElementFamily;

namespace {

// Voigt index pairs in Abaqus order.
constexpr int kVi[6] = {0, 1, 2, 0, 0, 1};
constexpr int kVj[6] = {0, 1, 2, 1, 2, 2};

Voigt6 tensor_to_voigt(const Eigen::Matrix3d& t, bool engineering_shear) {
  const double s = engineering_shear ? 2.0 : 1.0;
  return {t(0, 0), t(1, 1), t(2, 2), s * t(0, 1), s * t(0, 2), s * t(1, 2)};
}

}  // namespace

PointState point_kinematics(ElementFamily family, int dim, bool nlgeom, const PointData& pd,
                            const Eigen::Ref<const Eigen::VectorXd>& u) {
  PointState st;
  const int n = static_cast<int>(pd.N.size());
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();  // ∇₀u
  double ur = 0.0;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) {
      const double ua = u(a * dim + i);
      H.row(i) += ua * pd.grad.row(a);
      if (i == 0) ur += pd.N(a) * ua;
    }
  if (family == ElementFamily::Axisymmetric) H(2, 2) = ur / pd.radius;
  st.F += H;
  if (nlgeom) {
    const Eigen::Matrix3d E = 0.5 * (st.F.transpose() * st.F - Eigen::Matrix3d::Identity());
    st.strain << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2);
  } else {
    st.strain << H(0, 0), H(1, 1), H(2, 2), H(0, 1) + H(1, 0), H(0, 2) + H(2, 0), H(1, 2) + H(2, 1);
  }
  return st;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> strain_operator(ElementFamily family, int dim, const Eigen::Matrix3d& F,
                                                         const PointData& pd) {
  const int n = static_cast<int>(pd.N.size());
  // B(k, a·dim + i) = ∂E_k/∂u_ai: for E_pq = ½(F_ip ∂N_a/∂X_q + F_iq ∂N_a/∂X_p) (×2 for shear).
  Eigen::Matrix<double, 6, Eigen::Dynamic> B(6, n * dim);
  B.setZero();
  for (int a = 0; a < n; ++a) {
    const Eigen::RowVector3d g = pd.grad.row(a);
    for (int i = 0; i < dim; ++i) {
      auto col = B.col(a * dim + i);
      for (int k = 0; k < 3; ++k) col(k) = F(i, k) * g(k);
      for (int k = 3; k < 6; ++k) col(k) = F(i, kVi[k]) * g(kVj[k]) + F(i, kVj[k]) * g(kVi[k]);
    }
    if (family == ElementFamily::Axisymmetric) B(2, a * dim) += F(2, 2) * pd.N(a) / pd.radius;  // δE33 = F33 δu_r / R
  }
  return B;
}

void add_geometric_stiffness(ElementFamily family, int dim, const PointData& pd, const Vec6& stress, double scale,
                             Eigen::MatrixXd& K) {
  const int n = static_cast<int>(pd.N.size());
  const bool axi = family == ElementFamily::Axisymmetric;
  const Eigen::Matrix3d S = voigt_to_tensor(stress, false);
  const Eigen::MatrixXd G = pd.grad * S * pd.grad.transpose() * scale;  // n × n
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      for (int i = 0; i < dim; ++i) K(a * dim + i, b * dim + i) += G(a, b);
      if (axi) K(a * dim, b * dim) += stress(2) * pd.N(a) * pd.N(b) / (pd.radius * pd.radius) * scale;
    }
}

void add_point_contribution(ElementFamily family, int dim, const Mat6& D, bool nlgeom, const PointData& pd,
                            const PointState& st, Eigen::VectorXd* f, Eigen::MatrixXd* K) {
  const Eigen::Matrix3d F = nlgeom ? st.F : Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, 6, Eigen::Dynamic> B = strain_operator(family, dim, F, pd);
  if (f) f->noalias() += (B.transpose() * st.stress) * pd.dv;
  if (!K) return;
  K->noalias() += (B.transpose() * (D * pd.dv) * B);
  if (nlgeom) add_geometric_stiffness(family, dim, pd, st.stress, pd.dv, *K);  // initial-stress stiffness
}

void point_output(ElementFamily family, const Material& m, bool nlgeom, const PointData& pd,
                  const PointState& st, PointResult& out, std::span<const double> state) {
  Vec6 strain = st.strain;
  if (family == ElementFamily::PlaneStress)
    strain(2) = m.plane_stress_thickness_strain(pd.x, strain, st.stress, pd.thermal_strain, pd.temperature, state);
  out.volume = pd.dv;
  if (!nlgeom) {
    for (int k = 0; k < 6; ++k) {
      out.stress[k] = st.stress(k);
      out.strain[k] = strain(k);
    }
    return;
  }
  Eigen::Matrix3d F = st.F;
  if (family == ElementFamily::PlaneStress) F(2, 2) = std::sqrt(1 + 2 * strain(2));  // E33 → stretch
  const double J = F.determinant();
  const Eigen::Matrix3d S = voigt_to_tensor(st.stress, false);
  out.stress = tensor_to_voigt(F * S * F.transpose() / J, false);
  // LE = ½ ln(V²), V² = F Fᵀ (left Cauchy–Green).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F * F.transpose());
  const Eigen::Vector3d logl = eig.eigenvalues().array().log() * 0.5;
  const Eigen::Matrix3d LE = eig.eigenvectors() * logl.asDiagonal() * eig.eigenvectors().transpose();
  out.strain = tensor_to_voigt(LE, true);
}

}  // namespace inpact::solver::elements
