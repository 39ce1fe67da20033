#include "analytical_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

namespace inpact::contact {

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec2 sub(const Vec2& a, const Vec2& b) { return {a[0] - b[0], a[1] - b[1]}; }
Vec2 add(const Vec2& a, const Vec2& b) { return {a[0] + b[0], a[1] + b[1]}; }
Vec2 scale(double s, const Vec2& a) { return {s * a[0], s * a[1]}; }
double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
double norm(const Vec2& a) { return std::hypot(a[0], a[1]); }
Vec2 unit(const Vec2& a) { return scale(1.0 / norm(a), a); }
/// a turned counter-clockwise by 90°.
Vec2 left(const Vec2& a) { return {-a[1], a[0]}; }

[[noreturn]] void fail(std::size_t segment, const std::string& what) { throw ProfileError(segment, what); }

/// The signed angle from u to v (both about the same centre), in (−π, π].
double angle_between(const Vec2& u, const Vec2& v) { return std::atan2(cross(u, v), dot(u, v)); }

ProfilePiece line_piece(const Vec2& a, const Vec2& b) { return {false, a, b, {}, 0.0, 0.0, 0.0}; }

ProfilePiece arc_piece(const Vec2& a, const Vec2& b, const Vec2& c) {
  ProfilePiece p{true, a, b, c, norm(sub(a, c)), 0.0, 0.0};
  p.angle_a = std::atan2(a[1] - c[1], a[0] - c[0]);
  p.sweep = angle_between(sub(a, c), sub(b, c));
  return p;
}

ProfilePiece raw_piece(const Vec2& a, const model::ProfileSegment& s, std::size_t index) {
  const double scale_length = std::max({norm(a), norm(s.end), 1e-300});
  if (norm(sub(s.end, a)) <= 1e-12 * scale_length) fail(index, "the segment has zero length");
  if (s.kind == model::ProfileSegment::Kind::Line) return line_piece(a, s.end);
  const double ra = norm(sub(a, s.center)), rb = norm(sub(s.end, s.center));
  if (std::abs(ra - rb) > 1e-6 * std::max(ra, rb))
    fail(index, fmt::format("CIRCL: the end point is {:.6g} from the centre and the start point {:.6g}; both must lie "
                            "on one circle", rb, ra));
  ProfilePiece p = arc_piece(a, s.end, s.center);
  if (std::abs(p.sweep) >= kPi - 1e-9) fail(index, "CIRCL: an arc must turn by less than 180°; split it in two");
  return p;
}

/// A curve a fillet's centre lies on: a line (point, unit direction) or a circle (centre, radius).
struct OffsetCurve {
  bool circle = false;
  Vec2 point{}, dir{};
  double radius = 0.0;
};

/// Piece p offset by r towards side s (+1: its left, −1: its right).
OffsetCurve offset(const ProfilePiece& p, double r, double s) {
  if (!p.arc) {
    const Vec2 t = unit(sub(p.b, p.a));
    return {false, add(p.a, scale(s * r, left(t))), t, 0.0};
  }
  // Travelling counter-clockwise, the left side is the centre's.
  return {true, p.center, {}, p.sweep > 0 ? p.radius - s * r : p.radius + s * r};
}

/// The intersections of two offset curves.
std::vector<Vec2> intersect(const OffsetCurve& c1, const OffsetCurve& c2) {
  std::vector<Vec2> out;
  if (!c1.circle && !c2.circle) {
    const double den = cross(c1.dir, c2.dir);
    if (std::abs(den) < 1e-14) return out;
    const double s = cross(sub(c2.point, c1.point), c2.dir) / den;
    out.push_back(add(c1.point, scale(s, c1.dir)));
    return out;
  }
  if (c1.circle && c2.circle) {
    const Vec2 d = sub(c2.point, c1.point);
    const double l = norm(d);
    if (l < 1e-14) return out;
    const double a = (l * l + c1.radius * c1.radius - c2.radius * c2.radius) / (2.0 * l);
    const double h2 = c1.radius * c1.radius - a * a;
    if (h2 < 0) return out;
    const Vec2 e = scale(1.0 / l, d), m = add(c1.point, scale(a, e));
    const double h = std::sqrt(h2);
    out.push_back(add(m, scale(h, left(e))));
    out.push_back(add(m, scale(-h, left(e))));
    return out;
  }
  const OffsetCurve& line = c1.circle ? c2 : c1;
  const OffsetCurve& circle = c1.circle ? c1 : c2;
  const Vec2 w = sub(line.point, circle.point);
  const double b = dot(w, line.dir), c = dot(w, w) - circle.radius * circle.radius, disc = b * b - c;
  if (disc < 0) return out;
  for (double s : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) out.push_back(add(line.point, scale(s, line.dir)));
  return out;
}

/// The foot of c on the full curve of piece p (its line, or its circle).
Vec2 foot(const ProfilePiece& p, const Vec2& c) {
  if (!p.arc) {
    const Vec2 t = unit(sub(p.b, p.a));
    return add(p.a, scale(dot(sub(c, p.a), t), t));
  }
  return add(p.center, scale(p.radius, unit(sub(c, p.center))));
}

/// Where x lies along piece p: 0 at a, 1 at b (x on the piece's curve).
double position_along(const ProfilePiece& p, const Vec2& x) {
  if (!p.arc) {
    const Vec2 ab = sub(p.b, p.a);
    return dot(sub(x, p.a), ab) / dot(ab, ab);
  }
  return angle_between(sub(p.a, p.center), sub(x, p.center)) / p.sweep;
}

void set_end(ProfilePiece& p, const Vec2& a, const Vec2& b) {
  p = p.arc ? arc_piece(a, b, p.center) : line_piece(a, b);
}

/// The closest point of piece p to q, and whether it is an end (−1: a, +1: b, 0: inside).
Vec2 closest_on_piece(const ProfilePiece& p, const Vec2& q, int& end) {
  const bool at_centre = p.arc && norm(sub(q, p.center)) == 0.0;
  const double s = at_centre ? 0.5 : position_along(p, p.arc ? foot(p, q) : q);
  if (s > 0.0 && s < 1.0) {
    end = 0;
    if (at_centre) {  // every point of the arc is as close: its middle
      const double mid = p.angle_a + 0.5 * p.sweep;
      return add(p.center, Vec2{p.radius * std::cos(mid), p.radius * std::sin(mid)});
    }
    return p.arc ? foot(p, q) : add(p.a, scale(s, sub(p.b, p.a)));
  }
  // Beyond the piece: the nearer end (an arc's angle alone does not say which).
  end = norm(sub(q, p.a)) <= norm(sub(q, p.b)) ? -1 : 1;
  return end < 0 ? p.a : p.b;
}

double piece_length(const ProfilePiece& p) { return p.arc ? p.radius * std::abs(p.sweep) : norm(sub(p.b, p.a)); }

/// Profile::closest's extension zone at free end `end` (−1: a, +1: b) of `piece`: when p lies
/// within `extension` × the piece's length beyond it along its tangent, pp (the end, with the
/// piece's t and n) moves onto the extended tangent line, with that line's gap; true then.
bool extended_beyond_end(const ProfilePiece& piece, int end, const Vec2& p, double extension, ProfilePoint& pp) {
  const Vec2 outward = end > 0 ? pp.t : scale(-1.0, pp.t);
  const double beyond = dot(sub(p, pp.x), outward);
  if (extension <= 0.0 || beyond > extension * piece_length(piece)) return false;
  pp.x = add(pp.x, scale(std::max(beyond, 0.0), outward));
  pp.gap = dot(sub(p, pp.x), pp.n);
  pp.distance = std::abs(pp.gap);
  return true;
}

}  // namespace

Vec2 piece_tangent(const ProfilePiece& p, const Vec2& x) {
  if (!p.arc) return unit(sub(p.b, p.a));
  const Vec2 radial = unit(sub(x, p.center));
  return p.sweep > 0 ? left(radial) : scale(-1.0, left(radial));
}

namespace {

/// The fillet of radius r between `prev` and `next` (turning by `turn`, the cross product of
/// their tangents there): trims both to its tangency points and returns it. `segment`: the
/// segment after the corner, for the error.
ProfilePiece round_corner(ProfilePiece& prev, ProfilePiece& next, double turn, double r, std::size_t segment) {
  // Its centre lies r from both on the inside of the turn: where their offset curves meet.
  const double side = turn > 0 ? 1.0 : -1.0;
  const OffsetCurve c1 = offset(prev, r, side), c2 = offset(next, r, side);
  std::optional<Vec2> center;
  for (const Vec2& c : intersect(c1, c2))
    if (!center || norm(sub(c, prev.b)) < norm(sub(*center, prev.b))) center = c;
  const bool offsets_exist = !(c1.circle && c1.radius <= 0) && !(c2.circle && c2.radius <= 0);
  const Vec2 t1 = center ? foot(prev, *center) : Vec2{}, t2 = center ? foot(next, *center) : Vec2{};
  const double s1 = center ? position_along(prev, t1) : -1, s2 = center ? position_along(next, t2) : 2;
  if (!center || !offsets_exist || s1 <= 0.0 || s1 > 1.0 || s2 < 0.0 || s2 >= 1.0)
    fail(segment, fmt::format("FILLET RADIUS = {:.6g} does not fit the corner at ({:.6g}, {:.6g})", r, prev.b[0],
                              prev.b[1]));
  set_end(prev, prev.a, t1);
  set_end(next, t2, next.b);
  return arc_piece(t1, t2, *center);
}

}  // namespace

Profile Profile::build(const Vec2& start, std::span<const model::ProfileSegment> segments, double fillet_radius) {
  if (segments.empty()) throw std::invalid_argument("the profile has no segments after START");
  Profile out;
  Vec2 a = start;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    ProfilePiece next = raw_piece(a, segments[i], i);
    a = segments[i].end;
    if (!out.pieces_.empty()) {
      // The joint: smooth already, a corner, or a corner rounded by the fillet.
      ProfilePiece& prev = out.pieces_.back();
      const Vec2 t_in = piece_tangent(prev, prev.b), t_out = piece_tangent(next, next.a);
      const double turn = cross(t_in, t_out);
      const bool tangent = std::abs(turn) < 1e-9 && dot(t_in, t_out) > 0;
      if (tangent || fillet_radius <= 0.0) {
        out.joint_smooth_.push_back(tangent);
      } else {
        const ProfilePiece round = round_corner(prev, next, turn, fillet_radius, i);
        out.pieces_.push_back(round);
        out.joint_smooth_.insert(out.joint_smooth_.end(), {1, 1});
      }
    }
    out.pieces_.push_back(next);
  }
  return out;
}

ProfilePoint Profile::closest(const Vec2& p, double extension) const {
  ProfilePoint best;
  best.distance = std::numeric_limits<double>::infinity();
  int best_end = 0;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    int end = 0;
    const Vec2 x = closest_on_piece(pieces_[i], p, end);
    const double d = norm(sub(p, x));
    if (d < best.distance) {
      best.distance = d;
      best.x = x;
      best.piece = static_cast<int>(i);
      best_end = end;
    }
  }
  const ProfilePiece& piece = pieces_[static_cast<std::size_t>(best.piece)];
  const std::size_t i = static_cast<std::size_t>(best.piece);
  // The piece sharing the end point, when the chain goes on there.
  const int neighbour = best_end < 0 && i > 0 ? static_cast<int>(i) - 1
                        : best_end > 0 && i + 1 < pieces_.size() ? static_cast<int>(i) + 1 : -1;
  const bool smooth_end = neighbour >= 0 && joint_smooth_[std::min<std::size_t>(i, static_cast<std::size_t>(neighbour))];
  best.t = piece_tangent(piece, best.x);
  best.n = best.surface_n = left(best.t);
  if (best_end == 0 || smooth_end) {
    best.gap = dot(sub(p, best.x), best.n);
    if (piece.arc && best_end == 0) best.kappa = piece.sweep > 0 ? -1.0 / piece.radius : 1.0 / piece.radius;
    return best;
  }
  if (neighbour < 0 && extended_beyond_end(piece, best_end, p, extension, best)) return best;
  // A corner or a free end: the gap is the distance to the point, signed by the side of the
  // normals that meet there.
  Vec2 mean = best.n;
  if (neighbour >= 0) mean = add(mean, left(piece_tangent(pieces_[static_cast<std::size_t>(neighbour)], best.x)));
  if (norm(mean) > 0.0) best.surface_n = unit(mean);
  const double scale_length = std::max(norm(best.x), 1.0);
  if (best.distance <= 1e-12 * scale_length || norm(mean) == 0.0) {
    if (norm(mean) > 0.0) best.n = unit(mean);
    best.t = {best.n[1], -best.n[0]};
    best.gap = dot(sub(p, best.x), best.n);
    return best;
  }
  const Vec2 u = scale(1.0 / best.distance, sub(p, best.x));
  const double sign = dot(u, mean) >= 0.0 ? 1.0 : -1.0;
  best.n = scale(sign, u);
  best.t = {best.n[1], -best.n[0]};
  best.gap = sign * best.distance;
  best.corner = true;
  return best;
}

}  // namespace inpact::contact
