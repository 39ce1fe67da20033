#include "shell_lamina.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace inpact::solver::elements {

ShellLamina isotropic_lamina(double youngs_modulus, double poissons_ratio, double expansion) {
  ShellLamina l;
  const double c = youngs_modulus / (1 - poissons_ratio * poissons_ratio);
  const double g = youngs_modulus / (2 * (1 + poissons_ratio));
  l.in_plane = {{{c, c * poissons_ratio, 0.0}, {c * poissons_ratio, c, 0.0}, {0.0, 0.0, g}}};
  l.shear = {{{g, 0.0}, {0.0, g}}};
  l.expansion = expansion;
  return l;
}

ShellLamina condensed_lamina(const model::Stiffness& d, bool lamina, double expansion) {
  constexpr int in_plane[3] = {0, 1, 3}, shear[2] = {4, 5};
  Eigen::Matrix<double, 6, 6> full;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) full(i, j) = d[static_cast<std::size_t>(6 * i + j)];
  Eigen::Matrix3d q;
  Eigen::Matrix2d g;
  if (lamina) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) q(a, b) = full(in_plane[a], in_plane[b]);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) g(a, b) = full(shear[a], shear[b]);
  } else {
    const Eigen::Matrix<double, 6, 6> compliance = full.inverse();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) q(a, b) = compliance(in_plane[a], in_plane[b]);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) g(a, b) = compliance(shear[a], shear[b]);
    q = q.inverse().eval();
    g = g.inverse().eval();
  }
  ShellLamina l;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) l.in_plane[a][b] = q(a, b);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) l.shear[a][b] = g(a, b);
  l.expansion = expansion;
  return l;
}

ShellLamina turned_lamina(const ShellLamina& l, double theta) {
  if (theta == 0.0) return l;
  const double c = std::cos(theta), s = std::sin(theta);
  const double t[3][3] = {{c * c, s * s, c * s}, {s * s, c * c, -c * s}, {-2 * c * s, 2 * c * s, c * c - s * s}};
  const double r[2][2] = {{c, s}, {-s, c}};
  ShellLamina out = l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum += t[a][i] * l.in_plane[a][b] * t[b][j];
      out.in_plane[i][j] = sum;
    }
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double sum = 0.0;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) sum += r[a][i] * l.shear[a][b] * r[b][j];
      out.shear[i][j] = sum;
    }
  return out;
}

std::array<double, 5> strains_in_material_axes(const std::array<double, 5>& e, double theta) {
  if (theta == 0.0) return e;
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * c * e[0] + s * s * e[1] + c * s * e[2], s * s * e[0] + c * c * e[1] - c * s * e[2],
          -2 * c * s * e[0] + 2 * c * s * e[1] + (c * c - s * s) * e[2], c * e[3] + s * e[4], -s * e[3] + c * e[4]};
}

std::array<double, 5> stresses_in_material_axes(const std::array<double, 5>& e, double theta) {
  if (theta == 0.0) return e;
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * c * e[0] + s * s * e[1] + 2 * c * s * e[2], s * s * e[0] + c * c * e[1] - 2 * c * s * e[2],
          -c * s * e[0] + c * s * e[1] + (c * c - s * s) * e[2], c * e[3] + s * e[4], -s * e[3] + c * e[4]};
}

double material_angle(const ShellLayerProperties& layer, const std::array<Vec3, 3>& axes, const Vec3& x) {
  return orientation_angle(layer.orientation, axes, x) + layer.angle;
}

double orientation_angle(const std::optional<MaterialOrientation>& orientation, const std::array<Vec3, 3>& axes,
                         const Vec3& x) {
  if (!orientation) return 0.0;
  const Eigen::Matrix3d q = orientation->axes_at(x);
  const Eigen::Vector3d n(axes[2][0], axes[2][1], axes[2][2]);
  const int first = orientation->shell_projected_axis(), second = (first + 1) % 3;
  Eigen::Vector3d m = q.row(first).transpose() - q.row(first).dot(n) * n;
  double back = 0.0;
  if (m.norm() < std::sin(0.1 * std::numbers::pi / 180)) {  // within 0.1° of the normal: the next
    m = q.row(second).transpose() - q.row(second).dot(n) * n;  // axis is direction 2
    back = -std::numbers::pi / 2;
  }
  const Eigen::Vector3d e1(axes[0][0], axes[0][1], axes[0][2]), e2(axes[1][0], axes[1][1], axes[1][2]);
  return std::atan2(m.dot(e2), m.dot(e1)) + back;
}

}  // namespace inpact::solver::elements
