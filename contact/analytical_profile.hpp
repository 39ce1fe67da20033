#pragma once
/// The plane profile of an analytical rigid surface (model/analytical_surface.hpp) as a chain of
/// pieces, straight or circular, with FILLET RADIUS arcs put into its corners, and the closest
/// point of the chain to a point of its plane.
///
/// Conventions: a piece runs from `a` to `b`; its tangent t is the direction of travel and its
/// normal n = t turned counter-clockwise (the profile's outward normal). Curvature κ is signed
/// against n: κ > 0 where the profile bends away from n (convex seen from where n points: an arc
/// travelled clockwise about its centre), κ < 0 where it bends towards n, 0 on lines.
#include <array>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/analytical_surface.hpp"

namespace inpact::contact {

using Vec2 = std::array<double, 2>;

/// A profile that cannot be built: what is wrong with which segment.
struct ProfileError : std::invalid_argument {
  ProfileError(std::size_t segment_index, const std::string& what) : std::invalid_argument(what), segment(segment_index) {}
  std::size_t segment;  ///< 0-based, into model::AnalyticalSurface::segments
};

struct ProfilePiece {
  bool arc = false;
  Vec2 a{}, b{};
  Vec2 center{};         ///< arc only
  double radius = 0.0;   ///< arc only
  double angle_a = 0.0;  ///< arc: polar angle of `a` about the centre
  double sweep = 0.0;    ///< arc: signed angle from a to b (> 0 counter-clockwise), |sweep| < π
};

/// The closest point of a profile to a point p.
struct ProfilePoint {
  Vec2 x{};           ///< the closest point
  Vec2 t{}, n{};      ///< tangent and outward normal there (n: the distance's direction at a kink)
  Vec2 surface_n{};   ///< the profile's own normal there (at a kink: the mean of its pieces')
  double gap = 0.0;   ///< (p − x)·n: positive on the normal's side
  double distance = 0.0;
  double kappa = 0.0;  ///< curvature at x (signed as above); 0 at a kink or end, see `corner`
  int piece = -1;
  /// x is an end of its piece that is not a smooth joint (a corner without fillet, or a free end
  /// of the profile) and p is off it: the gap is the distance to that point.
  bool corner = false;
};

class Profile {
 public:
  /// The chain from `start` through `segments`, with every corner rounded by `fillet_radius`
  /// (0: sharp). Throws ProfileError for an arc of 180° or more, an arc end not on its circle, a
  /// zero-length segment, or a fillet that does not fit; std::invalid_argument for no segments.
  static Profile build(const Vec2& start, std::span<const model::ProfileSegment> segments, double fillet_radius);

  std::span<const ProfilePiece> pieces() const { return pieces_; }
  /// `extension`: Abaqus's EXTENSION ZONE (node to surface), a fraction of the end piece's
  /// length. A point beyond a free end of the profile, within that distance along the end's
  /// tangent, meets the end piece's tangent line extended (no corner): a node that bulges just
  /// past the end of a punch keeps the punch's normal instead of a tilted one. 0: none.
  ProfilePoint closest(const Vec2& p, double extension = 0.0) const;

 private:
  std::vector<ProfilePiece> pieces_;
  /// joint_smooth_[i]: pieces i and i+1 meet tangentially (a fillet or an already smooth joint).
  std::vector<char> joint_smooth_;
};

/// The unit tangent (direction of travel) of a piece at its point x.
Vec2 piece_tangent(const ProfilePiece& p, const Vec2& x);

}  // namespace inpact::contact
