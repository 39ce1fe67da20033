// T(ψ) of rotation_moments.hpp: the spatial turn of the elements' R = exp([ψ]×) when ψ changes,
// R(ψ + ε e_j) R(ψ)ᵀ = I + ε [T e_j]× + O(ε²), checked by central differences at several ψ (up
// to 3 rad, beyond the series branch), and Tᵀ ψ = ψ (a moment about the turn's own axis is its
// own conjugate).
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/elements/corotation.hpp"
#include "solver/rotation_moments.hpp"

namespace inpact::solver {
namespace {

using Vec3 = std::array<double, 3>;

/// The elements' own exp([ψ]×) (corotation.hpp), as a row-major matrix.
Mat3 exp_map(const Vec3& psi) {
  const auto rows = elements::rotation_exp(psi);
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return r;
}

TEST(RotationMoments, TangentIsTheSpatialTurnOfTheRotationVector) {
  for (const Vec3& psi : {Vec3{0, 0, 0}, Vec3{1e-6, -2e-6, 3e-6}, Vec3{0.3, -0.2, 0.5}, Vec3{0, 0, 1.5707963},
                          Vec3{1.2, 2.0, -1.7}}) {
    const Mat3 t = rotation_tangent(psi);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      Vec3 plus = psi, minus = psi;
      plus[j] += h;
      minus[j] -= h;
      const Mat3 rp = exp_map(plus), rm = exp_map(minus), r = exp_map(psi);
      // dR Rᵀ / dψ_j = [T e_j]×: read the axial vector of the skew part.
      Mat3 d{};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int k = 0; k < 3; ++k) d[a][b] += (rp[a][k] - rm[a][k]) / (2 * h) * r[b][k];
      const Vec3 axial{0.5 * (d[2][1] - d[1][2]), 0.5 * (d[0][2] - d[2][0]), 0.5 * (d[1][0] - d[0][1])};
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(t[i][j], axial[i], 1e-8) << "psi " << psi[0] << " column " << j;
    }
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(t[0][i] * psi[0] + t[1][i] * psi[1] + t[2][i] * psi[2], psi[i], 1e-14) << "T^T psi";
  }
}

}  // namespace
}  // namespace inpact::solver
