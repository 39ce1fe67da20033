#pragma once
/// An analytical rigid surface placed in space (model/analytical_surface.hpp): its profile
/// (analytical_profile.hpp) as the surface itself (SEGMENTS, 2D models), swept along the local z
/// axis (CYLINDER, infinite along it) or turned about it (REVOLUTION). Evaluated in the body's
/// own frame, the reference configuration; the rigid body's motion is the caller's.
///
/// The gap of a point p is its signed distance to the surface, g = (p − x)·n, exact (no facets).
/// Its second derivative in p, the curvature of the distance field, is
///   ∇²g = Σ_i κ_i/(1 + κ_i g) t_i t_iᵀ
/// over the principal directions t_i at the closest point x with curvatures κ_i (signed as in
/// analytical_profile.hpp): the profile's own, and for REVOLUTION the hoop one, κ = n_r / r(x).
/// At a corner without fillet (the gap a distance to a point) it is (I − n nᵀ)/g.
#include <array>
#include <span>

#include "contact/analytical_profile.hpp"
#include "contact/vec3.hpp"
#include "model/analytical_surface.hpp"

namespace inpact::contact {

struct ShapePoint {
  Vec3 x{}, n{};
  Vec3 surface_n{};  ///< the surface's own normal at x (= n but at a corner: ProfilePoint::surface_n)
  double gap = 0.0, distance = 0.0;
  bool corner = false;                 ///< the closest point is a sharp corner or a free end
  std::array<double, 9> hessian{};     ///< ∇²g, row-major 3 × 3 (2D: the upper 2 × 2 block)
};

class AnalyticalShape {
 public:
  /// Throws std::invalid_argument for a profile that cannot be built (analytical_profile.hpp),
  /// or a type that does not fit the model's dimension `dim` (SEGMENTS: 2D; CYLINDER and
  /// REVOLUTION: 3D).
  static AnalyticalShape build(const model::AnalyticalSurface& s, int dim);

  /// The closest point of the surface to `p` (body frame); `extension`: the profile's extension
  /// zone beyond its free ends (Profile::closest).
  ShapePoint closest(const Vec3& p, double extension = 0.0) const;
  const Profile& profile() const { return profile_; }

  /// A point faces the surface across its gap: not a corner, or a corner seen within 45° of the
  /// surface's normal there (beyond a free end the distance turns tangential: the point is
  /// beside the surface, not behind it), as faceted surfaces judge it (projection.hpp).
  static bool faces(const ShapePoint& sp);

 private:
  ShapePoint on_segments(const Vec3& p, double extension) const;
  ShapePoint on_cylinder(const Vec3& p, double extension) const;
  ShapePoint on_revolution(const Vec3& p, double extension) const;

  model::AnalyticalSurface::Type type_ = model::AnalyticalSurface::Type::Segments;
  Vec3 origin_{};
  std::array<Vec3, 3> axes_{};
  Profile profile_;
};

}  // namespace inpact::contact
