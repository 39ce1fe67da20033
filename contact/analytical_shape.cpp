#include "analytical_shape.hpp"

#include <cmath>
#include <stdexcept>

namespace inpact::contact {

namespace {

/// H += c t tᵀ.
void add_term(std::array<double, 9>& h, double c, const Vec3& t) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) h[3 * i + j] += c * t[i] * t[j];
}

/// κ/(1 + κ g): the distance field's curvature at gap g off a curve of curvature κ. Beyond the
/// centre of curvature (1 + κ g → 0, a point deep inside a concave arc's circle) the field is
/// singular; it is left flat there.
double field_curvature(double kappa, double gap) {
  const double d = 1.0 + kappa * gap;
  return d > 1e-3 ? kappa / d : 0.0;
}

Vec3 in_plane(const Vec2& v, const Vec3& e1, const Vec3& e2) { return add(scale(v[0], e1), scale(v[1], e2)); }

/// The profile point's own curvature in the profile plane spanned by e1, e2: along its tangent,
/// or (a corner) every direction across the distance.
void add_profile_curvature(const ProfilePoint& pp, const Vec3& e1, const Vec3& e2, std::array<double, 9>& h) {
  const Vec3 t = in_plane(pp.t, e1, e2);
  if (pp.corner) {
    if (pp.gap != 0.0) add_term(h, 1.0 / pp.gap, t);
    return;
  }
  add_term(h, field_curvature(pp.kappa, pp.gap), t);
}

}  // namespace

bool AnalyticalShape::faces(const ShapePoint& sp) {
  constexpr double kCos45 = 0.7071;
  return !sp.corner || std::abs(dot(sp.n, sp.surface_n)) >= kCos45;
}

AnalyticalShape AnalyticalShape::build(const model::AnalyticalSurface& s, int dim) {
  using T = model::AnalyticalSurface::Type;
  if (s.type == T::Segments && dim != 2)
    throw std::invalid_argument("TYPE=SEGMENTS is a surface of a two-dimensional or axisymmetric model; use TYPE=CYLINDER "
                                "or TYPE=REVOLUTION in three dimensions");
  if (s.type != T::Segments && dim != 3)
    throw std::invalid_argument("TYPE=CYLINDER and TYPE=REVOLUTION are surfaces of a three-dimensional model; use "
                                "TYPE=SEGMENTS in two dimensions");
  AnalyticalShape shape;
  shape.type_ = s.type;
  shape.origin_ = s.origin;
  shape.axes_ = s.axes;
  shape.profile_ = Profile::build(s.start, s.segments, s.fillet_radius);
  return shape;
}

ShapePoint AnalyticalShape::closest(const Vec3& p, double extension) const {
  switch (type_) {
    case model::AnalyticalSurface::Type::Segments: return on_segments(p, extension);
    case model::AnalyticalSurface::Type::Cylinder: return on_cylinder(p, extension);
    case model::AnalyticalSurface::Type::Revolution: return on_revolution(p, extension);
  }
  return {};
}

ShapePoint AnalyticalShape::on_segments(const Vec3& p, double extension) const {
  const ProfilePoint pp = profile_.closest({p[0], p[1]}, extension);
  ShapePoint s;
  s.x = {pp.x[0], pp.x[1], p[2]};
  s.n = {pp.n[0], pp.n[1], 0.0};
  s.surface_n = {pp.surface_n[0], pp.surface_n[1], 0.0};
  s.gap = pp.gap;
  s.distance = pp.distance;
  s.corner = pp.corner;
  add_profile_curvature(pp, {1, 0, 0}, {0, 1, 0}, s.hessian);
  return s;
}

ShapePoint AnalyticalShape::on_cylinder(const Vec3& p, double extension) const {
  const Vec3 v = sub(p, origin_);
  const ProfilePoint pp = profile_.closest({dot(v, axes_[0]), dot(v, axes_[1])}, extension);
  ShapePoint s;
  s.x = add(origin_, add(in_plane(pp.x, axes_[0], axes_[1]), scale(dot(v, axes_[2]), axes_[2])));
  s.n = in_plane(pp.n, axes_[0], axes_[1]);
  s.surface_n = in_plane(pp.surface_n, axes_[0], axes_[1]);
  s.gap = pp.gap;
  s.distance = pp.distance;
  s.corner = pp.corner;
  add_profile_curvature(pp, axes_[0], axes_[1], s.hessian);  // straight along the generator
  return s;
}

ShapePoint AnalyticalShape::on_revolution(const Vec3& p, double extension) const {
  const Vec3 v = sub(p, origin_);
  const Vec3& ez = axes_[2];
  const double z = dot(v, ez);
  const Vec3 w = axpy(-z, ez, v);
  const double r = norm(w);
  const double scale_length = std::max(norm(v), 1.0);
  const bool on_axis = r <= 1e-12 * scale_length;
  const Vec3 er = on_axis ? axes_[0] : scale(1.0 / r, w);
  const ProfilePoint pp = profile_.closest({r, z}, extension);
  ShapePoint s;
  s.x = add(origin_, in_plane(pp.x, er, ez));
  s.n = in_plane(pp.n, er, ez);
  s.surface_n = in_plane(pp.surface_n, er, ez);
  s.gap = pp.gap;
  s.distance = pp.distance;
  s.corner = pp.corner;
  add_profile_curvature(pp, er, ez, s.hessian);
  // Around the axis: the distance to the hoop circle through x curves with n_r / r (r the
  // point's own radius); on the axis every direction is a meridian.
  const Vec3 hoop = cross(ez, er);
  if (!on_axis) add_term(s.hessian, pp.n[0] / r, hoop);
  return s;
}

}  // namespace inpact::contact
