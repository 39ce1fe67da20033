#pragma once
/// The motion of a node of a rigid body (model/rigid_body.hpp): u = u_R + (R(θ) − I) r, with r
/// the node's offset from the reference node and θ the rotation vector the rotation node holds.
/// Small rotations (the step without NLGEOM): R r ≈ r + θ × r, linear in θ. Finite rotations
/// (NLGEOM): R = exp([θ]×), Rodrigues' formula. In 2D only θ3 exists (in θ[0]).
#include <array>

namespace inpact::model {

using Vec3d = std::array<double, 3>;

struct RigidMotion {
  Vec3d offset{};                    ///< (R − I) r: what the rotation adds to u_R
  std::array<Vec3d, 3> d_dtheta{};   ///< d_dtheta[k] = ∂(R r)/∂θ_k (k < 1 in 2D)
};

/// `theta`: θ1..θ3 in 3D, θ3 in theta[0] in 2D; `dim` 2 or 3.
RigidMotion rigid_motion(const Vec3d& theta, const Vec3d& r, int dim, bool finite);

}  // namespace inpact::model
