#include "rigid_motion.hpp"

#include <cmath>

namespace inpact::model {

namespace {

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

RigidMotion planar(double theta, const Vec3d& r, bool finite) {
  RigidMotion m;
  const double c = finite ? std::cos(theta) : 1.0, s = finite ? std::sin(theta) : theta;
  m.offset = {(c - 1.0) * r[0] - s * r[1], s * r[0] + (c - 1.0) * r[1], 0.0};
  // ∂(R r)/∂θ = e3 × (R r); small rotations linearise about θ = 0: e3 × r.
  const double ds = finite ? c : 1.0, dc = finite ? -s : 0.0;
  m.d_dtheta[0] = {dc * r[0] - ds * r[1], ds * r[0] + dc * r[1], 0.0};
  return m;
}

/// sin t / t, (1 − cos t)/t², (t − sin t)/t³, by their series near t = 0 (where the quotients
/// lose every digit).
void rodrigues_coefficients(double t, double& a, double& b, double& c) {
  if (t < 1e-4) {
    const double t2 = t * t;
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
    c = 1.0 / 6.0 - t2 / 120.0;
    return;
  }
  a = std::sin(t) / t;
  b = (1.0 - std::cos(t)) / (t * t);
  c = (t - std::sin(t)) / (t * t * t);
}

}  // namespace

RigidMotion rigid_motion(const Vec3d& theta, const Vec3d& r, int dim, bool finite) {
  if (dim == 2) return planar(theta[0], r, finite);
  RigidMotion m;
  if (!finite) {
    m.offset = cross(theta, r);
    for (int k = 0; k < 3; ++k) {
      Vec3d e{0, 0, 0};
      e[k] = 1.0;
      m.d_dtheta[k] = cross(e, r);
    }
    return m;
  }
  // R r = r + a θ×r + b θ×(θ×r); δ(R r) = (T δθ) × (R r) with T = I + b[θ]× + c[θ]×², the
  // rotation's left Jacobian.
  const double t = std::sqrt(theta[0] * theta[0] + theta[1] * theta[1] + theta[2] * theta[2]);
  double a, b, c;
  rodrigues_coefficients(t, a, b, c);
  const Vec3d tr = cross(theta, r), ttr = cross(theta, tr);
  Vec3d Rr;
  for (int i = 0; i < 3; ++i) {
    m.offset[i] = a * tr[i] + b * ttr[i];
    Rr[i] = r[i] + m.offset[i];
  }
  for (int k = 0; k < 3; ++k) {
    Vec3d e{0, 0, 0};
    e[k] = 1.0;
    const Vec3d te = cross(theta, e), tte = cross(theta, te);
    Vec3d w;
    for (int i = 0; i < 3; ++i) w[i] = e[i] + b * te[i] + c * tte[i];
    m.d_dtheta[k] = cross(w, Rr);
  }
  return m;
}

}  // namespace inpact::model
