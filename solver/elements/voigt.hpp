#pragma once
/// Symmetric 3×3 tensors in Voigt form, order 11, 22, 33, 12, 13, 23: stresses with tensor
/// components, strains with engineering shears (γ12 = 2ε12), as everywhere in the kernels.
#include <Eigen/Core>

namespace inpact::solver::elements {

inline Eigen::Matrix3d voigt_to_tensor(const Eigen::Matrix<double, 6, 1>& v, bool engineering_shear) {
  const double s = engineering_shear ? 0.5 : 1.0;
  Eigen::Matrix3d t;
  t << v(0), s * v(3), s * v(4), s * v(3), v(1), s * v(5), s * v(4), s * v(5), v(2);
  return t;
}

inline Eigen::Matrix<double, 6, 1> tensor_to_vec6(const Eigen::Matrix3d& t, bool engineering_shear) {
  const double s = engineering_shear ? 2.0 : 1.0;
  Eigen::Matrix<double, 6, 1> v;
  v << t(0, 0), t(1, 1), t(2, 2), s * t(0, 1), s * t(0, 2), s * t(1, 2);
  return v;
}

/// The deviator of a stress-like Voigt vector (tensor components, no factor on the shears).
inline Eigen::Matrix<double, 6, 1> voigt_deviator(const Eigen::Matrix<double, 6, 1>& s) {
  Eigen::Matrix<double, 6, 1> d = s;
  const double mean = (s(0) + s(1) + s(2)) / 3.0;
  d.head<3>().array() -= mean;
  return d;
}

/// a : b of two symmetric tensors in Voigt form with tensor components: the shears count twice.
inline double voigt_contract(const Eigen::Matrix<double, 6, 1>& a, const Eigen::Matrix<double, 6, 1>& b) {
  return a.head<3>().dot(b.head<3>()) + 2.0 * a.tail<3>().dot(b.tail<3>());
}

}  // namespace inpact::solver::elements
