// The hyperelastic energies of solver/elements/hyperelastic.hpp, each alone:
//  - the stress is the derivative of the energy, S = ∂W/∂E (central differences, 1e-7 relative);
//  - the tangent is the derivative of the stress, ℂ = ∂S/∂E (central differences, 1e-6 of the
//    largest entry) at a general strain and at a strain with two equal principal stretches;
//  - objectivity: F and QF (Q a 90° rotation) give the same S, so σ rotates with Q (1e-12);
//  - uniaxial tension to stretch 2 and simple shear to γ = 1: the nominal stress of the
//    principal-stretch closed forms τ_a = λ_a ∂W/∂λ_a (within 1e-6 relative), the lateral
//    stretch of uniaxial tension solved from τ2 = 0 by bisection.
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "solver/elements/hyperelastic.hpp"

namespace inpact::solver::elements {
namespace {

using Eigen::Matrix3d;

Matrix3d strain_tensor(const Vec6& e) {  // engineering shears → tensor
  Matrix3d E;
  E << e(0), e(3) / 2, e(4) / 2, e(3) / 2, e(1), e(5) / 2, e(4) / 2, e(5) / 2, e(2);
  return E;
}

Matrix3d cauchy_green(const Vec6& e) { return Matrix3d::Identity() + 2 * strain_tensor(e); }

struct Law {
  const char* name;
  std::shared_ptr<const StrainEnergy> energy;
};

std::vector<Law> laws() {
  return {
      {"neo-Hooke", std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({0.5, 0.0}, 1, {0.1}))},
      {"Mooney-Rivlin", std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({0.4, 0.1}, 1, {0.05}))},
      {"polynomial N=2",
       std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({0.4, 0.1, 0.02, -0.01, 0.005}, 2, {0.05, 0.01}))},
      {"Yeoh", std::make_shared<InvariantEnergy>(InvariantEnergy::reduced_polynomial({0.5, -0.01, 0.002}, {0.1, 0.02, 0.01}))},
      {"Arruda-Boyce", std::make_shared<InvariantEnergy>(InvariantEnergy::arruda_boyce(1.0, 2.5, 0.1))},
      {"Ogden N=3", std::make_shared<OgdenEnergy>(std::vector<double>{0.6, 0.002, -0.01},
                                                  std::vector<double>{1.3, 5.0, -2.0}, std::vector<double>{0.05})},
  };
}

Vec6 stress_at(const StrainEnergy& w, const Vec6& e) {
  Vec6 S;
  Mat6 D;
  w.stress_tangent(cauchy_green(e), S, D);
  return S;
}

void check_derivatives(const Law& law, const Vec6& e) {
  SCOPED_TRACE(law.name);
  Vec6 S;
  Mat6 D;
  law.energy->stress_tangent(cauchy_green(e), S, D);
  const double h = 1e-5;
  Mat6 D_fd;
  Vec6 S_fd;
  for (int J = 0; J < 6; ++J) {
    Vec6 ep = e, em = e;
    ep(J) += h;
    em(J) -= h;
    D_fd.col(J) = (stress_at(*law.energy, ep) - stress_at(*law.energy, em)) / (2 * h);
    S_fd(J) = (law.energy->energy(cauchy_green(ep)) - law.energy->energy(cauchy_green(em))) / (2 * h);
  }
  EXPECT_LE((S - S_fd).cwiseAbs().maxCoeff(), 1e-7 * S.cwiseAbs().maxCoeff()) << S.transpose() << "\n" << S_fd.transpose();
  EXPECT_LE((D - D_fd).cwiseAbs().maxCoeff(), 1e-6 * D.cwiseAbs().maxCoeff()) << D << "\n\n" << D_fd;
  EXPECT_LE((D - D.transpose()).cwiseAbs().maxCoeff(), 1e-12 * D.cwiseAbs().maxCoeff());
}

TEST(Hyperelastic, StressAndTangentAreTheDerivativesOfTheEnergy) {
  Vec6 general;
  general << 0.3, -0.1, 0.15, 0.2, -0.12, 0.07;
  Vec6 two_equal;  // principal stretches (1.3, 0.9, 0.9): a repeated eigenvalue
  two_equal << 0.5 * (1.69 - 1), 0.5 * (0.81 - 1), 0.5 * (0.81 - 1), 0, 0, 0;
  for (const Law& law : laws()) {
    check_derivatives(law, general);
    check_derivatives(law, two_equal);
  }
}

TEST(Hyperelastic, ZeroStressAndTheInitialModuliInTheReferenceState) {
  for (const Law& law : laws()) {
    SCOPED_TRACE(law.name);
    Vec6 S;
    Mat6 D;
    law.energy->stress_tangent(Matrix3d::Identity(), S, D);
    EXPECT_LE(S.cwiseAbs().maxCoeff(), 1e-14);
    // Small strain: ℂ = K 1⊗1 + 2μ (𝕀 − ⅓ 1⊗1): D(3,3) = μ, D(0,1) = K − 2μ/3.
    const double mu = law.energy->initial_shear_modulus(), K = law.energy->initial_bulk_modulus();
    EXPECT_NEAR(D(3, 3), mu, 1e-12 * mu);
    EXPECT_NEAR(D(0, 1), K - 2 * mu / 3, 1e-12 * K);
  }
}

TEST(Hyperelastic, TheStressRotatesWithTheBody) {
  Matrix3d F;
  F << 1.4, 0.3, -0.1, 0.05, 0.8, 0.2, 0.1, -0.15, 1.1;
  Matrix3d Q;  // 90° about z
  Q << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  for (const Law& law : laws()) {
    SCOPED_TRACE(law.name);
    const Hyperelastic mat(law.energy);
    const Vec6 strain = Vec6::Zero();
    Vec6 S1, S2;
    Mat6 D1, D2;
    mat.update({F, strain, 0.0}, {}, S1, D1);
    const Matrix3d QF = Q * F;
    mat.update({QF, strain, 0.0}, {}, S2, D2);
    EXPECT_LE((S1 - S2).cwiseAbs().maxCoeff(), 1e-12 * S1.cwiseAbs().maxCoeff());
    EXPECT_LE((D1 - D2).cwiseAbs().maxCoeff(), 1e-12 * D1.cwiseAbs().maxCoeff());
  }
}

// --- closed forms in principal stretches ---

/// The principal Kirchhoff stresses τ_a = λ_a ∂W/∂λ_a of an energy given by its closed form.
using PrincipalTau = std::function<Eigen::Vector3d(const Eigen::Vector3d& stretch)>;

/// Invariant energies: τ_a = 2W1 (λ̄_a² − Ī1/3) + 2W2 (Ī1 λ̄_a² − λ̄_a⁴ − 2Ī2/3) + J U'(J),
/// with W1, W2 given as functions of (Ī1, Ī2) and U'(J).
PrincipalTau invariant_tau(std::function<std::pair<double, double>(double, double)> w12,
                           std::function<double(double)> du) {
  return [=](const Eigen::Vector3d& l) {
    const double J = l.prod();
    const Eigen::Vector3d lb2 = (l / std::cbrt(J)).array().square();
    const double I1 = lb2.sum(), I2 = lb2(0) * lb2(1) + lb2(1) * lb2(2) + lb2(0) * lb2(2);
    const auto [W1, W2] = w12(I1, I2);
    Eigen::Vector3d tau;
    for (int a = 0; a < 3; ++a)
      tau(a) = 2 * W1 * (lb2(a) - I1 / 3) + 2 * W2 * (I1 * lb2(a) - lb2(a) * lb2(a) - 2 * I2 / 3) + J * du(J);
    return tau;
  };
}

struct ClosedForm {
  Law law;
  PrincipalTau tau;
  std::function<double(double)> shear;  ///< simple shear: σ12(γ) (J = 1)
};

ClosedForm make_form(const char* name, std::shared_ptr<const StrainEnergy> energy, PrincipalTau tau,
                     std::function<double(double)> shear) {
  ClosedForm c;
  c.law.name = name;
  c.law.energy = std::move(energy);
  c.tau = std::move(tau);
  c.shear = std::move(shear);
  return c;
}

std::vector<ClosedForm> closed_forms() {
  const double c10 = 0.4, c01 = 0.1, d1 = 0.05;
  const double y1 = 0.5, y2 = -0.01, y3 = 0.002;
  const double mu = 1.0, lm = 2.5, dab = 0.1;
  const std::vector<double> om{0.6, 0.002, -0.01}, oa{1.3, 5.0, -2.0};
  const auto poly_du = [d1](double J) { return 2 * (J - 1) / d1; };
  std::vector<ClosedForm> out;
  out.push_back(make_form("neo-Hooke", std::make_shared<InvariantEnergy>(InvariantEnergy::reduced_polynomial({c10}, {d1})),
                          invariant_tau([=](double, double) { return std::pair{c10, 0.0}; }, poly_du),
                          [=](double g) { return 2 * c10 * g; }));
  const double p20 = 0.02, p11 = -0.01, p02 = 0.005;
  const auto poly_w = [=](double I1, double I2) {
    return std::pair{c10 + 2 * p20 * (I1 - 3) + p11 * (I2 - 3), c01 + p11 * (I1 - 3) + 2 * p02 * (I2 - 3)};
  };
  out.push_back(make_form("polynomial N=2",
                          std::make_shared<InvariantEnergy>(
                              InvariantEnergy::polynomial({c10, c01, p20, p11, p02}, 2, {d1, 0.01})),
                          invariant_tau(poly_w, [=](double J) { return 2 * (J - 1) / d1 + 4 * std::pow(J - 1, 3) / 0.01; }),
                          [=](double g) {
                            const auto [W1, W2] = poly_w(3 + g * g, 3 + g * g);
                            return 2 * (W1 + W2) * g;
                          }));
  out.push_back(make_form("Mooney-Rivlin", std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({c10, c01}, 1, {d1})),
                 invariant_tau([=](double, double) { return std::pair{c10, c01}; }, poly_du),
                 [=](double g) { return 2 * (c10 + c01) * g; }));
  const auto yeoh_w1 = [=](double I1) { return y1 + 2 * y2 * (I1 - 3) + 3 * y3 * (I1 - 3) * (I1 - 3); };
  out.push_back(make_form("Yeoh", std::make_shared<InvariantEnergy>(InvariantEnergy::reduced_polynomial({y1, y2, y3}, {d1})),
                 invariant_tau([=](double I1, double) { return std::pair{yeoh_w1(I1), 0.0}; }, poly_du),
                 [=](double g) { return 2 * yeoh_w1(3 + g * g) * g; }));
  const auto ab_w1 = [=](double I1) {
    const double c[5] = {0.5, 1.0 / 20, 11.0 / 1050, 19.0 / 7000, 519.0 / 673750};
    double w = 0;
    for (int k = 1; k <= 5; ++k) w += mu * c[k - 1] * k * std::pow(I1, k - 1) / std::pow(lm, 2 * k - 2);
    return w;
  };
  out.push_back(make_form("Arruda-Boyce", std::make_shared<InvariantEnergy>(InvariantEnergy::arruda_boyce(mu, lm, dab)),
                 invariant_tau([=](double I1, double) { return std::pair{ab_w1(I1), 0.0}; },
                               [=](double J) { return (J - 1 / J) / dab; }),
                 [=](double g) { return 2 * ab_w1(3 + g * g) * g; }));
  const auto ogden_tau = [=](const Eigen::Vector3d& l) {
    const double J = l.prod();
    const Eigen::Vector3d lb = l / std::cbrt(J);
    Eigen::Vector3d tau = Eigen::Vector3d::Constant(J * 2 * (J - 1) / d1);
    for (std::size_t p = 0; p < om.size(); ++p) {
      const Eigen::Vector3d la = lb.array().pow(oa[p]);
      for (int a = 0; a < 3; ++a) tau(a) += 2 * om[p] / oa[p] * (la(a) - la.sum() / 3);
    }
    return tau;
  };
  out.push_back(make_form("Ogden N=3", std::make_shared<OgdenEnergy>(om, oa, std::vector<double>{d1}), ogden_tau,
                 [=](double g) {  // σ12 = (τ1 − τ2) γ / (λ1² − λ2²), λ1 = γ/2 + √(1 + γ²/4), λ2 = 1/λ1
                   const double l = g / 2 + std::sqrt(1 + g * g / 4);
                   const Eigen::Vector3d t = ogden_tau(Eigen::Vector3d(l, 1 / l, 1));
                   return (t(0) - t(1)) * g / (l * l - 1 / (l * l));
                 }));
  return out;
}

/// The lateral stretch of uniaxial tension (τ2 = 0) by bisection.
double lateral_stretch(const PrincipalTau& tau, double stretch) {
  double lo = 0.2, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (tau(Eigen::Vector3d(stretch, mid, mid))(1) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The nominal stress P = F S of the kernel at F.
Matrix3d nominal(const StrainEnergy& w, const Matrix3d& F) {
  Vec6 S;
  Mat6 D;
  w.stress_tangent(F.transpose() * F, S, D);
  Matrix3d St;
  St << S(0), S(3), S(4), S(3), S(1), S(5), S(4), S(5), S(2);
  return F * St;
}

TEST(Hyperelastic, UniaxialTensionToStretchTwoMatchesTheClosedForm) {
  for (const ClosedForm& c : closed_forms()) {
    SCOPED_TRACE(c.law.name);
    const double l = 2.0, lt = lateral_stretch(c.tau, l);
    const double P_closed = c.tau(Eigen::Vector3d(l, lt, lt))(0) / l;  // P11 = τ1/λ1
    const Matrix3d P = nominal(*c.law.energy, Eigen::Vector3d(l, lt, lt).asDiagonal());
    EXPECT_NEAR(P(0, 0), P_closed, 1e-6 * std::abs(P_closed));
    EXPECT_NEAR(P(1, 1), 0.0, 1e-6 * std::abs(P_closed));  // the lateral faces are free
    std::printf("[hyperelastic] %-14s uniaxial lambda = 2: P11 = %.10g (closed form %.10g), lateral stretch %.8f\n",
                c.law.name, P(0, 0), P_closed, lt);
  }
}

TEST(Hyperelastic, SimpleShearMatchesTheClosedForm) {
  for (const ClosedForm& c : closed_forms()) {
    SCOPED_TRACE(c.law.name);
    const double g = 1.0;
    Matrix3d F = Matrix3d::Identity();
    F(0, 1) = g;
    const Matrix3d P = nominal(*c.law.energy, F);  // J = 1: P12 = σ12
    EXPECT_NEAR(P(0, 1), c.shear(g), 1e-6 * std::abs(c.shear(g)));
    std::printf("[hyperelastic] %-14s simple shear gamma = 1: P12 = %.10g (closed form %.10g)\n", c.law.name, P(0, 1),
                c.shear(g));
  }
}

TEST(Hyperelastic, AnInvertedPointHasNoStress) {
  const Hyperelastic mat(laws()[0].energy);
  Matrix3d F = Matrix3d::Identity();
  F(2, 2) = -0.5;
  Vec6 S;
  Mat6 D;
  mat.update({F, Vec6::Zero(), 0.0}, {}, S, D);
  EXPECT_TRUE(std::isnan(S(0)));
}

}  // namespace
}  // namespace inpact::solver::elements

namespace {

using inpact::solver::elements::Hyperelastic;
using inpact::solver::elements::InvariantEnergy;
using inpact::solver::elements::MaterialPointInput;

/// S and the tangent of a law at F (the element's Green–Lagrange strain from F).
std::pair<inpact::solver::elements::Vec6, inpact::solver::elements::Mat6> at(const Hyperelastic& law,
                                                                             const Eigen::Matrix3d& F) {
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  inpact::solver::elements::Vec6 strain, stress;
  strain << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(0, 2), 2 * E(1, 2);
  inpact::solver::elements::Mat6 scratch;
  const inpact::solver::elements::Mat6 D = law.update(MaterialPointInput{F, strain, 0.0, nullptr, true}, {}, stress, scratch);
  return {stress, D};
}

}  // namespace

// Plane stress: a neo-Hooke sheet pulled to λ1 = 2 with S22 = 0 (a Newton iteration on λ2 with
// the condensed tangent) is the 3D uniaxial state: the material's λ3 equals λ2 (isotropy) and S11
// is the 3D law's at diag(λ1, λ2, λ3); the condensed tangent is the central difference of the
// plane-stress stress.
TEST(HyperelasticPlaneStress, UniaxialSheetIsThe3DUniaxialStateAndTheTangentIsExact) {
  const auto energy = std::make_shared<InvariantEnergy>(InvariantEnergy::polynomial({0.5, 0.0}, 1, {0.1}));
  const Hyperelastic sheet(energy, true), solid(energy);
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 2.0;
  for (int it = 0; it < 30; ++it) {  // S22 = 0 by the in-plane Newton of an element
    const auto [S, D] = at(sheet, F);
    if (std::abs(S(1)) < 1e-13) break;
    const double E22 = 0.5 * (F(1, 1) * F(1, 1) - 1) - S(1) / D(1, 1);
    F(1, 1) = std::max(std::sqrt(std::max(1 + 2 * E22, 0.0)), 0.5 * F(1, 1));  // damped: stays positive
  }
  const auto [S, D] = at(sheet, F);
  ASSERT_LT(std::abs(S(1)), 1e-12);
  EXPECT_EQ(S(2), 0.0);
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  inpact::solver::elements::Vec6 strain;
  strain << E(0, 0), E(1, 1), 0, 0, 0, 0;
  const double lambda3 = std::sqrt(1 + 2 * sheet.plane_stress_thickness_strain({}, strain, S, 0.0, 0.0, {}));
  EXPECT_NEAR(lambda3, F(1, 1), 1e-10);
  Eigen::Matrix3d F3 = F;
  F3(2, 2) = lambda3;
  const auto [S3, D3] = at(solid, F3);
  EXPECT_NEAR(S(0), S3(0), 1e-10 * std::abs(S3(0)));
  EXPECT_NEAR(S3(2), 0.0, 1e-10 * std::abs(S3(0)));
  // The condensed tangent against central differences at a general in-plane F.
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  G(0, 0) = 1.3, G(0, 1) = 0.2, G(1, 0) = -0.05, G(1, 1) = 0.9;
  const auto [Sg, Dg] = at(sheet, G);
  const double h = 1e-7;
  double worst = 0;
  for (int j : {0, 1, 3}) {
    Eigen::Matrix3d Ep = 0.5 * (G.transpose() * G - Eigen::Matrix3d::Identity()), Em = Ep;
    const int p = j == 3 ? 0 : j, q = j == 3 ? 1 : j;
    const double dh = j == 3 ? h / 2 : h;  // a unit engineering shear is E12 = E21 = ½
    Ep(p, q) += dh, Em(p, q) -= dh;
    if (p != q) Ep(q, p) += dh, Em(q, p) -= dh;
    const auto stretch = [](const Eigen::Matrix3d& e) {
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(Eigen::Matrix3d::Identity() + 2 * e).operatorSqrt();
    };
    const inpact::solver::elements::Vec6 col = (at(sheet, stretch(Ep)).first - at(sheet, stretch(Em)).first) / (2 * h);
    for (int i : {0, 1, 3}) worst = std::max(worst, std::abs(col(i) - Dg(i, j)) / Dg.cwiseAbs().maxCoeff());
  }
  std::printf("[hyperelastic] plane-stress tangent vs central differences: %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);
}
