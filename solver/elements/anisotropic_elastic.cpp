#include "anisotropic_elastic.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace inpact::solver::elements {

using model::ElementFamily;

namespace {

constexpr int kInPlane[3] = {0, 1, 3};  // 11, 22, 12

ElasticConstants voigt_average(const Mat6& d, double expansion) {
  const double k = d.topLeftCorner<3, 3>().sum() / 9;
  const double g = (d(0, 0) + d(1, 1) + d(2, 2) - d(0, 1) - d(0, 2) - d(1, 2) + 3 * (d(3, 3) + d(4, 4) + d(5, 5))) / 15;
  ElasticConstants c;
  c.youngs_modulus = 9 * k * g / (3 * k + g);
  c.poissons_ratio = (3 * k - 2 * g) / (2 * (3 * k + g));
  c.expansion = expansion;
  return c;
}

}  // namespace

AnisotropicElastic::AnisotropicElastic(ElementFamily family, const Mat6& d_material, double expansion,
                                       std::optional<MaterialOrientation> orientation, bool lamina)
    : family_(family),
      d_material_(d_material),
      orientation_(std::move(orientation)),
      lamina_(lamina),
      constants_(voigt_average(d_material, expansion)) {
  if (lamina_ && family_ != ElementFamily::PlaneStress)
    throw std::invalid_argument("AnisotropicElastic: a lamina needs plane-stress elements");
  d_fixed_ = stiffness_at({0, 0, 0});
}

Mat6 AnisotropicElastic::family_stiffness(const Mat6& d) const {
  if (family_ != ElementFamily::PlaneStress) return d;
  Eigen::Matrix3d pp;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pp(i, j) = d(kInPlane[i], kInPlane[j]);
  if (!lamina_) {  // the in-plane block of the compliance, inverted
    const Mat6 s = d.inverse();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) pp(i, j) = s(kInPlane[i], kInPlane[j]);
    pp = pp.inverse().eval();
  }
  Mat6 out = Mat6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(kInPlane[i], kInPlane[j]) = pp(i, j);
  return out;
}

Mat6 AnisotropicElastic::stiffness_at(const Vec3& x) const {
  if (!orientation_) return family_stiffness(d_material_);
  const Eigen::Matrix3d q = orientation_->axes_at(x);
  if (lamina_ && std::abs(q(2, 2)) < 1 - 1e-12)
    throw std::invalid_argument("AnisotropicElastic: a lamina's orientation must keep its axis 3 along the thickness (z)");
  return family_stiffness(rotate_stiffness(d_material_, q));
}

const Mat6& AnisotropicElastic::update(const MaterialPointInput& in, const PointHistory&, Vec6& stress,
                                       Mat6& scratch) const {
  const Mat6* d = &d_fixed_;
  if (orientation_ && orientation_->varies()) {
    if (!in.position) throw std::logic_error("AnisotropicElastic: a cylindrical orientation needs the point's position");
    scratch = stiffness_at(*in.position);
    d = &scratch;
  }
  Vec6 eth = Vec6::Zero();
  eth.head<3>().setConstant(in.thermal_strain);
  stress = *d * (in.strain - eth);
  return *d;
}

double AnisotropicElastic::plane_stress_thickness_strain(const Vec3& x, const Vec6&, const Vec6& stress,
                                                         double thermal_strain, double, std::span<const double>) const {
  if (lamina_) return thermal_strain;
  const Mat6 d = orientation_ ? rotate_stiffness(d_material_, orientation_->axes_at(x)) : d_material_;
  const Mat6 s = d.inverse();
  return s(2, 0) * stress(0) + s(2, 1) * stress(1) + s(2, 3) * stress(3) + thermal_strain;
}

}  // namespace inpact::solver::elements
