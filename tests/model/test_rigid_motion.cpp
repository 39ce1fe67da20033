// model/rigid_motion.hpp: the motion of a rigid body's node and its derivatives in θ.
#include <gtest/gtest.h>

#include <cmath>

#include "model/rigid_motion.hpp"

using inpact::model::rigid_motion;
using inpact::model::Vec3d;

namespace {

/// Worst |∂(R r)/∂θ_k − central difference| over k and the components, h = 1e-6.
double worst_derivative_error(const Vec3d& theta, const Vec3d& r, int dim) {
  const auto m = rigid_motion(theta, r, dim, true);
  const double h = 1e-6;
  double worst = 0.0;
  for (int k = 0; k < (dim == 3 ? 3 : 1); ++k) {
    Vec3d p = theta, q = theta;
    p[k] += h;
    q[k] -= h;
    const auto mp = rigid_motion(p, r, dim, true), mq = rigid_motion(q, r, dim, true);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs((mp.offset[c] - mq.offset[c]) / (2 * h) - m.d_dtheta[k][c]));
  }
  return worst;
}

}  // namespace

TEST(RigidMotion, FiniteRotationDerivativesMatchCentralDifferences) {
  const Vec3d r{0.3, -1.2, 0.7};
  for (const Vec3d& theta : {Vec3d{0.4, -0.9, 1.3}, Vec3d{1e-6, 2e-6, -1e-6}, Vec3d{0, 0, 0}, Vec3d{2.5, 0.1, 0.2}})
    EXPECT_LE(worst_derivative_error(theta, r, 3), 1e-8) << theta[0];
  EXPECT_LE(worst_derivative_error({0.8, 0, 0}, {0.3, -1.2, 0}, 2), 1e-8);
}

TEST(RigidMotion, RotationByAQuarterTurnAndTheSmallRotationLaw) {
  // π/2 about z takes r = (1, 0, 0) to (0, 1, 0): the offset (R − I) r = (−1, 1, 0).
  const auto m = rigid_motion({0, 0, M_PI / 2}, {1, 0, 0}, 3, true);
  EXPECT_NEAR(m.offset[0], -1.0, 1e-15);
  EXPECT_NEAR(m.offset[1], 1.0, 1e-15);
  EXPECT_NEAR(m.offset[2], 0.0, 1e-15);
  // |R r| = |r| for any θ.
  const Vec3d r{0.3, -1.2, 0.7};
  const auto g = rigid_motion({0.4, -0.9, 1.3}, r, 3, true);
  double n0 = 0, n1 = 0;
  for (int c = 0; c < 3; ++c) n0 += r[c] * r[c], n1 += (r[c] + g.offset[c]) * (r[c] + g.offset[c]);
  EXPECT_NEAR(n1, n0, 1e-14);
  // Small rotations: θ × r, linear in θ with the derivative e_k × r.
  const auto s = rigid_motion({0.1, 0.2, 0.3}, {1, 2, 3}, 3, false);
  EXPECT_DOUBLE_EQ(s.offset[0], 0.2 * 3 - 0.3 * 2);
  EXPECT_DOUBLE_EQ(s.offset[1], 0.3 * 1 - 0.1 * 3);
  EXPECT_DOUBLE_EQ(s.offset[2], 0.1 * 2 - 0.2 * 1);
  // 2D: θ3 in theta[0]; R(π) r = −r.
  const auto p = rigid_motion({M_PI, 0, 0}, {1, 2, 0}, 2, true);
  EXPECT_NEAR(p.offset[0], -2.0, 1e-15);
  EXPECT_NEAR(p.offset[1], -4.0, 1e-15);
}
