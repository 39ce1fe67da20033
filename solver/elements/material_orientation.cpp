#include "material_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "voigt.hpp"

namespace inpact::solver::elements {

namespace {

Eigen::Vector3d vec(const double p[3]) { return {p[0], p[1], p[2]}; }

/// Rectangular axes: 1 along c→a, 3 normal to the plane of c, a, b, 2 = 3 × 1.
Eigen::Matrix3d rectangular_axes(const model::Orientation& o) {
  const Eigen::Vector3d c = vec(o.c);
  const Eigen::Vector3d e1 = (vec(o.a) - c).normalized();
  const Eigen::Vector3d e3 = e1.cross(vec(o.b) - c).normalized();
  Eigen::Matrix3d q;
  q.row(0) = e1;
  q.row(1) = e3.cross(e1);
  q.row(2) = e3;
  return q;
}

}  // namespace

MaterialOrientation::MaterialOrientation(const model::Orientation& o)
    : cylindrical_(o.system == model::Orientation::System::Cylindrical),
      a_(vec(o.a)),
      b_(vec(o.b)),
      fixed_(Eigen::Matrix3d::Identity()),
      axis_(o.axis - 1),
      angle_(o.angle * std::numbers::pi / 180.0),
      rotation_given_(o.rotation_given) {
  if (!cylindrical_) fixed_ = with_rotation(rectangular_axes(o));
}

// Cylindrical: 3 along the axis a→b, 1 radial from the axis through x, 2 = 3 × 1 (tangential).
// On the axis itself the radial direction is undefined; the global axis most normal to the
// cylinder axis stands in for it there.
Eigen::Matrix3d MaterialOrientation::axes_at(const Vec3& x) const {
  if (!cylindrical_) return fixed_;
  const Eigen::Vector3d e3 = (b_ - a_).normalized();
  const Eigen::Vector3d d = Eigen::Vector3d(x[0], x[1], x[2]) - a_;
  Eigen::Vector3d radial = d - d.dot(e3) * e3;
  if (radial.norm() <= 1e-12 * (d.norm() + (b_ - a_).norm())) {
    Eigen::Index k = 0;
    e3.cwiseAbs().minCoeff(&k);
    radial = Eigen::Vector3d::Unit(k) - e3(k) * e3;
  }
  const Eigen::Vector3d e1 = radial.normalized();
  Eigen::Matrix3d q;
  q.row(0) = e1;
  q.row(1) = e3.cross(e1);
  q.row(2) = e3;
  return with_rotation(q);
}

// A right-handed rotation by the angle about local axis k turns the other two, (i, j) in cyclic
// order after k: e_i' = cos e_i + sin e_j, e_j' = −sin e_i + cos e_j.
Eigen::Matrix3d MaterialOrientation::with_rotation(const Eigen::Matrix3d& axes) const {
  if (angle_ == 0.0) return axes;
  const int i = (axis_ + 1) % 3, j = (axis_ + 2) % 3;
  const double c = std::cos(angle_), s = std::sin(angle_);
  Eigen::Matrix3d q = axes;
  q.row(i) = c * axes.row(i) + s * axes.row(j);
  q.row(j) = -s * axes.row(i) + c * axes.row(j);
  return q;
}

// Column k: the local Voigt strain of the global unit strain k (tensor ε_local = Q ε Qᵀ).
Mat6 strain_rotation(const Eigen::Matrix3d& q) {
  static constexpr int vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};
  Mat6 t;
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
    const double v = k < 3 ? 1.0 : 0.5;  // engineering shear: γ = 2ε
    e(vi[k], vj[k]) = v;
    e(vj[k], vi[k]) = v;
    const Eigen::Matrix3d el = q * e * q.transpose();
    for (int r = 0; r < 6; ++r) t(r, k) = (r < 3 ? 1.0 : 2.0) * el(vi[r], vj[r]);
  }
  return t;
}

Mat6 rotate_stiffness(const Mat6& d_local, const Eigen::Matrix3d& q) {
  const Mat6 t = strain_rotation(q);
  const Mat6 d = t.transpose() * d_local * t;
  return 0.5 * (d + d.transpose());  // symmetric to round-off; exactly so for the assembly
}

void to_material_axes(const Eigen::Matrix3d& q, PointResult& point) {
  const auto turn = [&](Voigt6& v, bool engineering_shear) {
    const Vec6 global = Eigen::Map<const Vec6>(v.data());
    const Vec6 local = tensor_to_vec6(q * voigt_to_tensor(global, engineering_shear) * q.transpose(), engineering_shear);
    std::copy_n(local.data(), 6, v.begin());
  };
  turn(point.stress, false);
  turn(point.strain, true);
  turn(point.plastic_strain, true);
}

}  // namespace inpact::solver::elements
