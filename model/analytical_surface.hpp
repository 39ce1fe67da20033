#pragma once
/// An analytical rigid surface (*SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION) [K16 *SURFACE]:
/// a profile of straight lines and circular arcs in a plane, taken as it is (SEGMENTS, in a 2D or
/// axisymmetric model), swept along a generator (CYLINDER) or turned about an axis (REVOLUTION).
/// It has no nodes: it moves with the reference node of the *RIGID BODY that names it, and is
/// only ever a contact master. The profile's outward normal is its direction of travel turned
/// counter-clockwise in the profile plane (the convention of Abaqus's 2D rigid elements, R2D2).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

struct ProfileSegment {
  enum class Kind : std::uint8_t { Line, Arc };
  Kind kind = Kind::Line;
  std::array<double, 2> end{};     ///< end point (the start is the previous segment's end)
  std::array<double, 2> center{};  ///< Arc: the circle's centre
  SourceLoc loc;
};

struct AnalyticalSurface {
  enum class Type : std::uint8_t { Segments, Cylinder, Revolution };
  Type type = Type::Segments;
  std::string name;
  /// CYLINDER: the profile's plane is (local x, local y) at `origin`, swept along local z;
  /// REVOLUTION: (r, z) with local z the axis through `origin`; SEGMENTS: the global (x, y) plane.
  /// Orthonormal, right-handed.
  std::array<double, 3> origin{0, 0, 0};
  std::array<std::array<double, 3>, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::array<double, 2> start{};
  std::vector<ProfileSegment> segments;
  double fillet_radius = 0.0;  ///< FILLET RADIUS: rounds every corner between two segments
  SourceLoc loc;
};

}  // namespace inpact::model
