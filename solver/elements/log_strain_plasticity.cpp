#include "log_strain_plasticity.hpp"

#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include "log_divided_difference.hpp"
#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

using Mat3 = Eigen::Matrix3d;

/// C = FᵀF in its eigenbasis, with the divided differences of ln the derivatives need.
struct LogStrain {
  Mat3 basis;            ///< eigenvectors of C (columns)
  Eigen::Vector3d c;     ///< its eigenvalues
  Mat3 first;            ///< ln[c_a, c_b]
  Mat3 strain;           ///< E_log = ½ ln C

  explicit LogStrain(const Mat3& C) {
    Eigen::SelfAdjointEigenSolver<Mat3> eig(C);
    basis = eig.eigenvectors();
    c = eig.eigenvalues();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) first(a, b) = log_divided_difference(c(a), c(b));
    strain = basis * (0.5 * c.array().log()).matrix().asDiagonal() * basis.transpose();
  }
  /// Dln(C)[X]: X's components in the eigenbasis times ln[c_a, c_b].
  Mat3 first_derivative(const Mat3& X) const {
    return basis * first.cwiseProduct(basis.transpose() * X * basis) * basis.transpose();
  }
  /// D²ln(C)[X, Y]: component ab = Σ_k ln[c_a, c_k, c_b] (X_ak Y_kb + Y_ak X_kb) in the eigenbasis.
  Mat3 second_derivative(const Mat3& X, const Mat3& Y) const {
    const Mat3 x = basis.transpose() * X * basis, y = basis.transpose() * Y * basis;
    Mat3 d = Mat3::Zero();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int k = 0; k < 3; ++k)
          d(a, b) += log_second_divided_difference(c(a), c(k), c(b)) * (x(a, k) * y(k, b) + y(a, k) * x(k, b));
    return basis * d * basis.transpose();
  }
};

}  // namespace

LogStrainPlasticity::LogStrainPlasticity(std::shared_ptr<const Material> small_strain_law)
    : small_(std::move(small_strain_law)) {
  if (!small_) throw std::invalid_argument("LogStrainPlasticity: no small-strain law");
}

const Mat6& LogStrainPlasticity::update(const MaterialPointInput& in, const PointHistory& point, Vec6& stress,
                                        Mat6& scratch) const {
  if (!in.nlgeom) return small_->update(in, point, stress, scratch);
  const Mat3 E = voigt_to_tensor(in.strain, true);
  const LogStrain log(Mat3::Identity() + 2.0 * E);
  const Vec6 strain = tensor_to_vec6(log.strain, true);
  Vec6 t;
  const Mat6 D = small_->update({in.F, strain, in.thermal_strain, in.position, false, in.temperature}, point, t, scratch);
  const Mat3 T = voigt_to_tensor(t, false);
  stress = tensor_to_vec6(log.first_derivative(T), false);  // S = P : T (P is self-adjoint)
  for (int j = 0; j < 6; ++j) {  // a unit engineering shear γ is E_pq = E_qp = ½
    const Mat3 dE = voigt_to_tensor(Vec6::Unit(j), true);
    const Mat3 dT = voigt_to_tensor(D * tensor_to_vec6(log.first_derivative(dE), true), false);
    scratch.col(j) = tensor_to_vec6(log.first_derivative(dT) + log.second_derivative(T, 2.0 * dE), false);
  }
  return scratch;
}

}  // namespace inpact::solver::elements
