#include "hyperelastic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

constexpr int kVi[6] = {0, 1, 2, 0, 0, 1};
constexpr int kVj[6] = {0, 1, 2, 1, 2, 2};

/// Tensor components in Voigt order (no factor 2 on the shears: S and the rows of ℂ).
Vec6 voigt(const Eigen::Matrix3d& A) {
  Vec6 v;
  for (int k = 0; k < 6; ++k) v(k) = A(kVi[k], kVj[k]);
  return v;
}

/// 𝕀_A,ijkl = ½ (A_ik A_jl + A_il A_jk) in Voigt rows and columns.
Mat6 sym_product(const Eigen::Matrix3d& A) {
  Mat6 m;
  for (int I = 0; I < 6; ++I)
    for (int J = 0; J < 6; ++J) {
      const int i = kVi[I], j = kVj[I], k = kVi[J], l = kVj[J];
      m(I, J) = 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k));
    }
  return m;
}

Mat6 outer(const Vec6& a, const Vec6& b) { return a * b.transpose(); }

double ipow(double x, int n) {
  double r = 1.0;
  for (int k = 0; k < n; ++k) r *= x;
  return r;
}

// Arruda–Boyce: the coefficients of the inverse-Langevin series of its energy.
constexpr double kArrudaBoyce[5] = {0.5, 1.0 / 20, 11.0 / 1050, 19.0 / 7000, 519.0 / 673750};

}  // namespace

// --- volumetric part ---

double VolumetricEnergy::value(double J) const {
  if (form == Form::ArrudaBoyce) return d[0] == 0.0 ? 0.0 : ((J * J - 1) / 2 - std::log(J)) / d[0];
  double u = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d[i] != 0.0) u += ipow(J - 1, 2 * static_cast<int>(i + 1)) / d[i];
  return u;
}

double VolumetricEnergy::first(double J) const {
  if (form == Form::ArrudaBoyce) return d[0] == 0.0 ? 0.0 : (J - 1 / J) / d[0];
  double u = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const int n = 2 * static_cast<int>(i + 1);
    if (d[i] != 0.0) u += n * ipow(J - 1, n - 1) / d[i];
  }
  return u;
}

double VolumetricEnergy::second(double J) const {
  if (form == Form::ArrudaBoyce) return d[0] == 0.0 ? 0.0 : (1 + 1 / (J * J)) / d[0];
  double u = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const int n = 2 * static_cast<int>(i + 1);
    if (d[i] != 0.0) u += n * (n - 1) * ipow(J - 1, n - 2) / d[i];
  }
  return u;
}

// --- invariant energies ---

InvariantEnergy::InvariantEnergy(std::vector<InvariantTerm> terms, double offset_i1, VolumetricEnergy volumetric)
    : terms_(std::move(terms)), offset_i1_(offset_i1), volumetric_(std::move(volumetric)) {
  if (volumetric_.d.empty()) volumetric_.d.push_back(0.0);
}

InvariantEnergy InvariantEnergy::polynomial(const std::vector<double>& cij, int order, const std::vector<double>& d) {
  // Abaqus's order of the coefficients: C10 C01 (N = 1), then C20 C11 C02 (N = 2).
  static constexpr int kI[5] = {1, 0, 2, 1, 0}, kJ[5] = {0, 1, 0, 1, 2};
  const std::size_t n = order == 1 ? 2 : 5;
  if (cij.size() != n) throw std::invalid_argument("InvariantEnergy::polynomial: coefficient count");
  std::vector<InvariantTerm> t;
  for (std::size_t k = 0; k < n; ++k)
    if (cij[k] != 0.0) t.push_back({kI[k], kJ[k], cij[k]});
  return {std::move(t), 3.0, {VolumetricEnergy::Form::Polynomial, d}};
}

InvariantEnergy InvariantEnergy::reduced_polynomial(const std::vector<double>& ci0, const std::vector<double>& d) {
  std::vector<InvariantTerm> t;
  for (std::size_t k = 0; k < ci0.size(); ++k)
    if (ci0[k] != 0.0) t.push_back({static_cast<int>(k + 1), 0, ci0[k]});
  return {std::move(t), 3.0, {VolumetricEnergy::Form::Polynomial, d}};
}

InvariantEnergy InvariantEnergy::arruda_boyce(double mu, double lambda_m, double d) {
  std::vector<InvariantTerm> t;
  const double l2 = lambda_m * lambda_m;
  for (int k = 0; k < 5; ++k) t.push_back({k + 1, 0, mu * kArrudaBoyce[k] / ipow(l2, k)});
  return {std::move(t), 0.0, {VolumetricEnergy::Form::ArrudaBoyce, {d}}};
}

InvariantEnergy::Derivatives InvariantEnergy::isochoric(double i1b, double i2b) const {
  Derivatives r;
  const double x = i1b - offset_i1_, y = i2b - 3.0;
  for (const InvariantTerm& t : terms_) {
    const double xi = ipow(x, t.i), yj = ipow(y, t.j);
    const double xi1 = t.i >= 1 ? t.i * ipow(x, t.i - 1) : 0.0, yj1 = t.j >= 1 ? t.j * ipow(y, t.j - 1) : 0.0;
    const double xi2 = t.i >= 2 ? t.i * (t.i - 1) * ipow(x, t.i - 2) : 0.0;
    const double yj2 = t.j >= 2 ? t.j * (t.j - 1) * ipow(y, t.j - 2) : 0.0;
    r.w1 += t.c * xi1 * yj;
    r.w2 += t.c * xi * yj1;
    r.w11 += t.c * xi2 * yj;
    r.w12 += t.c * xi1 * yj1;
    r.w22 += t.c * xi * yj2;
  }
  return r;
}

double InvariantEnergy::energy(const Eigen::Matrix3d& C) const {
  const double J = std::sqrt(C.determinant());
  const double I1 = C.trace(), I2 = 0.5 * (I1 * I1 - (C * C).trace());
  const double x = std::pow(J, -2.0 / 3) * I1 - offset_i1_, y = std::pow(J, -4.0 / 3) * I2 - 3.0;
  double w = volumetric_.value(J);
  for (const InvariantTerm& t : terms_) w += t.c * ipow(x, t.i) * ipow(y, t.j);
  return w;
}

void InvariantEnergy::stress_tangent(const Eigen::Matrix3d& C, Vec6& S, Mat6& tangent) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d Ci = C.inverse();
  const double J = std::sqrt(C.determinant());
  const double I1 = C.trace(), I2 = 0.5 * (I1 * I1 - (C * C).trace());
  // Ī1 = a I1, Ī2 = b I2 with a = J^(−2/3), b = J^(−4/3), and their J-derivatives.
  const double a = std::pow(J, -2.0 / 3), b = a * a;
  const double a1 = -2.0 / 3 * a / J, b1 = -4.0 / 3 * b / J;
  const double a2 = 10.0 / 9 * a / (J * J), b2 = 28.0 / 9 * b / (J * J);
  const Derivatives d = isochoric(a * I1, b * I2);
  const double x = I1 * a1, y = I2 * b1;  // ∂Ī1/∂J, ∂Ī2/∂J
  // W(I1, I2, J) and its derivatives by the chain rule.
  const double W1 = d.w1 * a, W2 = d.w2 * b;
  const double WJ = d.w1 * x + d.w2 * y + volumetric_.first(J);
  const double W11 = d.w11 * a * a, W12 = d.w12 * a * b, W22 = d.w22 * b * b;
  const double W1J = a1 * d.w1 + a * (d.w11 * x + d.w12 * y);
  const double W2J = b1 * d.w2 + b * (d.w12 * x + d.w22 * y);
  const double WJJ = d.w1 * I1 * a2 + d.w2 * I2 * b2 + d.w11 * x * x + 2 * d.w12 * x * y + d.w22 * y * y +
                     volumetric_.second(J);
  const Vec6 dI1 = voigt(I), dI2 = voigt(I1 * I - C), dJ = voigt(0.5 * J * Ci);
  S = 2 * (W1 * dI1 + W2 * dI2 + WJ * dJ);
  tangent = W11 * outer(dI1, dI1) + W22 * outer(dI2, dI2) + W12 * (outer(dI1, dI2) + outer(dI2, dI1)) +
            WJJ * outer(dJ, dJ) + W1J * (outer(dI1, dJ) + outer(dJ, dI1)) + W2J * (outer(dI2, dJ) + outer(dJ, dI2)) +
            W2 * (outer(dI1, dI1) - sym_product(I)) +
            WJ * (0.25 * J * outer(voigt(Ci), voigt(Ci)) - 0.5 * J * sym_product(Ci));
  tangent *= 4.0;
}

double InvariantEnergy::initial_shear_modulus() const {
  const Derivatives d = isochoric(3.0, 3.0);
  return 2 * (d.w1 + d.w2);  // μ0 = 2 (∂W/∂Ī1 + ∂W/∂Ī2) at Ī1 = Ī2 = 3
}

double InvariantEnergy::initial_bulk_modulus() const {
  return volumetric_.d[0] == 0.0 ? std::numeric_limits<double>::infinity() : 2 / volumetric_.d[0];
}

// --- Ogden ---

OgdenEnergy::OgdenEnergy(std::vector<double> mu, std::vector<double> alpha, std::vector<double> d)
    : mu_(std::move(mu)), alpha_(std::move(alpha)), volumetric_{VolumetricEnergy::Form::Polynomial, std::move(d)} {
  if (volumetric_.d.empty()) volumetric_.d.push_back(0.0);
}

double OgdenEnergy::isochoric(const Eigen::Vector3d& c) const {
  const double P = c(0) * c(1) * c(2);
  double w = 0.0;
  for (std::size_t p = 0; p < mu_.size(); ++p) {
    const double beta = alpha_[p] / 2;
    const double f = std::pow(c(0), beta) + std::pow(c(1), beta) + std::pow(c(2), beta);
    w += 2 * mu_[p] / (alpha_[p] * alpha_[p]) * (std::pow(P, -beta / 3) * f - 3);
  }
  return w;
}

double OgdenEnergy::energy(const Eigen::Matrix3d& C) const {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  return isochoric(eig.eigenvalues()) + volumetric_.value(std::sqrt(C.determinant()));
}

void OgdenEnergy::stress_tangent(const Eigen::Matrix3d& C, Vec6& S, Mat6& tangent) const {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  const Eigen::Vector3d c = eig.eigenvalues();
  const double P = c.prod(), J = std::sqrt(P);
  // W(c1, c2, c3): first and second derivatives in the eigenvalues of C.
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ww = Eigen::Matrix3d::Zero();
  for (std::size_t p = 0; p < mu_.size(); ++p) {
    const double beta = alpha_[p] / 2, k = 2 * mu_[p] / (alpha_[p] * alpha_[p]) * std::pow(P, -beta / 3);
    const double f = std::pow(c(0), beta) + std::pow(c(1), beta) + std::pow(c(2), beta);
    Eigen::Vector3d g;  // ∂(P^(−β/3) f)/∂c_a / k-prefactor
    for (int q = 0; q < 3; ++q) g(q) = beta * std::pow(c(q), beta - 1) - beta / 3 * f / c(q);
    w += k * g;
    for (int q = 0; q < 3; ++q)
      for (int r = 0; r < 3; ++r) {
        double h = -beta / 3 / c(r) * g(q) - beta / 3 * beta * std::pow(c(r), beta - 1) / c(q);
        if (q == r) h += beta * (beta - 1) * std::pow(c(q), beta - 2) + beta / 3 * f / (c(q) * c(q));
        ww(q, r) += k * h;
      }
  }
  const double u1 = volumetric_.first(J), u2 = volumetric_.second(J);
  for (int q = 0; q < 3; ++q) {
    w(q) += u1 * J / (2 * c(q));
    for (int r = 0; r < 3; ++r)
      ww(q, r) += u2 * J * J / (4 * c(q) * c(r)) + u1 * (J / (4 * c(q) * c(r)) - (q == r ? J / (2 * c(q) * c(q)) : 0.0));
  }
  const Eigen::Matrix3d V = eig.eigenvectors();
  Vec6 M[3];
  for (int q = 0; q < 3; ++q) M[q] = voigt(V.col(q) * V.col(q).transpose());
  S = 2 * (w(0) * M[0] + w(1) * M[1] + w(2) * M[2]);
  tangent.setZero();
  for (int q = 0; q < 3; ++q)
    for (int r = 0; r < 3; ++r) tangent += 4 * ww(q, r) * outer(M[q], M[r]);
  // The rotation of the eigenvectors: 4 (S_a − S_b)/(c_a − c_b) Q_ab ⊗ Q_ab, with the limit
  // 4 · 2 (W_aa − W_ab) for (near) equal eigenvalues.
  for (int q = 0; q < 3; ++q)
    for (int r = q + 1; r < 3; ++r) {
      const Eigen::Matrix3d Q = 0.5 * (V.col(q) * V.col(r).transpose() + V.col(r) * V.col(q).transpose());
      const double gap = c(q) - c(r);
      const double ratio = std::abs(gap) > 1e-7 * std::max(c(q), c(r)) ? 2 * (w(q) - w(r)) / gap
                                                                         : 2 * (ww(q, q) - ww(q, r));
      tangent += 4 * ratio * outer(voigt(Q), voigt(Q));
    }
}

double OgdenEnergy::initial_shear_modulus() const {
  double mu0 = 0.0;
  for (double m : mu_) mu0 += m;
  return mu0;
}

double OgdenEnergy::initial_bulk_modulus() const {
  return volumetric_.d[0] == 0.0 ? std::numeric_limits<double>::infinity() : 2 / volumetric_.d[0];
}

// --- the material ---

Hyperelastic::Hyperelastic(std::shared_ptr<const StrainEnergy> energy, bool plane_stress)
    : energy_(std::move(energy)), plane_stress_(plane_stress) {
  const double mu = energy_->initial_shear_modulus(), K = energy_->initial_bulk_modulus();
  constants_.youngs_modulus = std::isfinite(K) ? 9 * K * mu / (3 * K + mu) : 3 * mu;
  constants_.poissons_ratio = std::isfinite(K) ? (3 * K - 2 * mu) / (2 * (3 * K + mu)) : 0.5;
}

const Mat6& Hyperelastic::update(const MaterialPointInput& in, const PointHistory&, Vec6& stress, Mat6& scratch) const {
  if (!(in.F.determinant() > 0.0)) {  // an inverted point: no energy there
    stress.setConstant(std::numeric_limits<double>::quiet_NaN());
    scratch.setConstant(std::numeric_limits<double>::quiet_NaN());
    return scratch;
  }
  if (!plane_stress_) {
    energy_->stress_tangent(in.F.transpose() * in.F, stress, scratch);
    return scratch;
  }
  Eigen::Matrix3d C = in.F.transpose() * in.F;
  C(2, 2) = 1 / std::max(C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0), 1e-12);  // the isochoric guess
  Mat6 full;
  if (!std::isfinite(thickness_stretch_squared(C, stress, full))) {
    stress.setConstant(std::numeric_limits<double>::quiet_NaN());  // the increment is cut back
    scratch.setConstant(std::numeric_limits<double>::quiet_NaN());
    return scratch;
  }
  scratch.setZero();  // condensed for S33 = 0: dS_ij = (D_ij − D_i3 D_3j / D_33) dE_j (i, j in 11, 22, 12)
  for (int i : {0, 1, 3})
    for (int j : {0, 1, 3}) scratch(i, j) = full(i, j) - full(i, 2) * full(2, j) / full(2, 2);
  stress(2) = stress(4) = stress(5) = 0.0;
  return scratch;
}

double Hyperelastic::thickness_stretch_squared(Eigen::Matrix3d C, Vec6& stress, Mat6& tangent) const {
  C(0, 2) = C(2, 0) = C(1, 2) = C(2, 1) = 0.0;
  for (int it = 0; it < 50; ++it) {
    energy_->stress_tangent(C, stress, tangent);
    const double scale = std::max(stress.cwiseAbs().maxCoeff(), energy_->initial_shear_modulus());
    if (std::abs(stress(2)) <= 1e-12 * scale) return C(2, 2);
    const double step = 2 * stress(2) / tangent(2, 2);  // dS33 = D33 dE33, dC33 = 2 dE33
    C(2, 2) = std::max(C(2, 2) - step, 0.25 * C(2, 2));  // stays positive
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double Hyperelastic::plane_stress_thickness_strain(const Vec3&, const Vec6& strain, const Vec6&, double, double,
                                                   std::span<const double>) const {
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity() + 2 * voigt_to_tensor(strain, true);
  C(2, 2) = 1 / std::max(C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0), 1e-12);
  Vec6 stress;
  Mat6 tangent;
  return 0.5 * (thickness_stretch_squared(C, stress, tangent) - 1);
}

}  // namespace inpact::solver::elements
