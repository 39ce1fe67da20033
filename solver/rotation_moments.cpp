#include "rotation_moments.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::solver {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 at(std::span<const double> v, std::int32_t node) {
  const auto i = static_cast<std::size_t>(node) * 3;
  return {v[i], v[i + 1], v[i + 2]};
}

double determinant(const Mat3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// The solution x of A x = b by Cramer's rule (det A checked by the caller).
Vec3 solve(const Mat3& a, const Vec3& b) {
  const double d = determinant(a);
  Vec3 x{};
  for (int k = 0; k < 3; ++k) {
    Mat3 ak = a;
    for (int i = 0; i < 3; ++i) ak[i][k] = b[i];
    x[k] = determinant(ak) / d;
  }
  return x;
}

Mat3 transposed(const Mat3& m) {
  Mat3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = m[j][i];
  return t;
}

}  // namespace

Mat3 rotation_tangent(const std::array<double, 3>& psi) {
  const double phi2 = psi[0] * psi[0] + psi[1] * psi[1] + psi[2] * psi[2];
  const double phi = std::sqrt(phi2);
  // (1 − cos φ)/φ² and (φ − sin φ)/φ³, by their series below φ = 1e-4 (round-off otherwise).
  const double a = phi < 1e-4 ? 0.5 - phi2 / 24 : (1 - std::cos(phi)) / phi2;
  const double b = phi < 1e-4 ? 1.0 / 6 - phi2 / 120 : (phi - std::sin(phi)) / (phi2 * phi);
  const Mat3 w{{{0, -psi[2], psi[1]}, {psi[2], 0, -psi[0]}, {-psi[1], psi[0], 0}}};
  Mat3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double w2 = 0;
      for (int k = 0; k < 3; ++k) w2 += w[i][k] * w[k][j];
      t[i][j] = (i == j ? 1.0 : 0.0) + a * w[i][j] + b * w2;
    }
  return t;
}

std::vector<std::int32_t> rotation_nodes(const AnalysisModel& am) {
  std::vector<std::int32_t> out;
  for (std::int32_t r : am.rotation_node_of)
    if (r >= 0) out.push_back(r);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void moments_to_conjugate(std::span<const double> u, std::span<const std::int32_t> nodes, std::span<double> f) {
  for (std::int32_t node : nodes) {
    const Vec3 m = at(f, node);
    if (m[0] == 0 && m[1] == 0 && m[2] == 0) continue;
    const Mat3 t = rotation_tangent(at(u, node));
    for (int i = 0; i < 3; ++i)
      f[static_cast<std::size_t>(node) * 3 + i] = t[0][i] * m[0] + t[1][i] * m[1] + t[2][i] * m[2];
  }
}

void conjugate_to_moments(std::span<const double> u, std::span<const std::int32_t> nodes, std::span<double> f) {
  for (std::int32_t node : nodes) {
    const Mat3 tt = transposed(rotation_tangent(at(u, node)));
    if (std::abs(determinant(tt)) < 1e-12) continue;  // |ψ| at a whole turn 2πk: T is singular there
    const Vec3 m = solve(tt, at(f, node));
    for (int i = 0; i < 3; ++i) f[static_cast<std::size_t>(node) * 3 + i] = m[i];
  }
}

}  // namespace inpact::solver
