/// *SURFACE, TYPE=SEGMENTS | CYLINDER | REVOLUTION: an analytical rigid surface's profile
/// [K16 *SURFACE] (model/analytical_surface.hpp). The profile's geometry (arcs under 180°, ends
/// on their circle, fillets that fit) is checked where it is built, before the analysis
/// (solver/contact_problem.cpp, check_contact_supported).
///
/// Data lines:
///   CYLINDER    a (3 coordinates), b on the local x axis (3); c on the generator, local z (3);
///   REVOLUTION  a (3), b on the symmetry axis, local z (3);
///   then, every type: START, x, y — then LINE, x, y or CIRCL, x, y, x_centre, y_centre.
/// The local coordinate lines may be left out (the profile's line first): the global axes then
/// (what Abaqus does for a surface defined in a part). PARAB is not supported yet.
#include <cmath>

#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross3(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::optional<Vec3> unit3(const Vec3& a) {
  const double l = std::sqrt(dot3(a, a));
  if (!(l > 0.0)) return std::nullopt;
  return Vec3{a[0] / l, a[1] / l, a[2] / l};
}

/// Reals from fields [from, from + n) of `f`.
template <std::size_t N>
std::optional<std::array<double, N>> reals(KeywordContext& ctx, const std::vector<Field>& f, std::size_t from,
                                           std::string_view what) {
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) {
    const auto v = ctx.real(f[from + i], what);
    if (!v) return std::nullopt;
    out[i] = *v;
  }
  return out;
}

/// The local axes of a CYLINDER (x towards b, z along c − a made normal to x) or a REVOLUTION
/// (z towards b). False after an error.
bool set_frame(KeywordContext& ctx, model::AnalyticalSurface& s, const Line& first, const Line* second) {
  std::vector<Field> f;
  split_fields(first, f);
  if (!ctx.check_count(f, first, 6, 6, "x, y, z of point a, x, y, z of point b")) return false;
  const auto ab = reals<6>(ctx, f, 0, "coordinate");
  if (!ab) return false;
  const Vec3 a{(*ab)[0], (*ab)[1], (*ab)[2]}, b{(*ab)[3], (*ab)[4], (*ab)[5]};
  s.origin = a;
  const auto along = unit3(minus(b, a));
  if (!along) {
    ctx.error(first.loc, "points a and b coincide: they must give the local axis");
    return false;
  }
  if (s.type == model::AnalyticalSurface::Type::Revolution) {
    const Vec3& z = *along;
    const Vec3 trial = std::abs(z[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 x = *unit3(cross3(cross3(z, trial), z));
    s.axes = {x, cross3(z, x), z};
    return true;
  }
  split_fields(*second, f);
  if (!ctx.check_count(f, *second, 3, 3, "x, y, z of point c on the generator")) return false;
  const auto c = reals<3>(ctx, f, 0, "coordinate");
  if (!c) return false;
  const Vec3& x = *along;
  const Vec3 gen = minus(*c, a);
  const double along_x = dot3(gen, x);
  const auto z = unit3({gen[0] - along_x * x[0], gen[1] - along_x * x[1], gen[2] - along_x * x[2]});
  if (!z) {
    ctx.error(second->loc, "point c lies on the local x axis (the line through a and b): it must give the generator");
    return false;
  }
  s.axes = {x, cross3(*z, x), *z};
  return true;
}

/// One profile line: START, LINE or CIRCL.
bool profile_line(KeywordContext& ctx, model::AnalyticalSurface& s, const Line& line, bool first) {
  std::vector<Field> f;
  split_fields(line, f);
  const std::string word = f.empty() ? "" : normalize_name(f[0].text);
  if (first != (word == "START")) {
    ctx.error(f.empty() ? line.loc : f[0].loc,
              first ? "the profile must begin with START, x, y" : "START may only begin the profile");
    return false;
  }
  if (word == "START" || word == "LINE") {
    if (!ctx.check_count(f, line, 3, 3, word + ", x, y")) return false;
    const auto p = reals<2>(ctx, f, 1, "coordinate");
    if (!p) return false;
    if (word == "START") s.start = *p;
    else s.segments.push_back({model::ProfileSegment::Kind::Line, *p, {}, f[0].loc});
    return true;
  }
  if (word == "CIRCL") {
    if (!ctx.check_count(f, line, 5, 5, "CIRCL, x, y of the end point, x, y of the centre")) return false;
    const auto p = reals<4>(ctx, f, 1, "coordinate");
    if (!p) return false;
    s.segments.push_back({model::ProfileSegment::Kind::Arc, {(*p)[0], (*p)[1]}, {(*p)[2], (*p)[3]}, f[0].loc});
    return true;
  }
  if (word == "PARAB") {
    ctx.error(f[0].loc, "PARAB segments are not supported yet; give the profile with LINE and CIRCL");
    return false;
  }
  ctx.error(f.empty() ? line.loc : f[0].loc,
            fmt::format("'{}' is not a profile segment: expected LINE or CIRCL", f.empty() ? "" : f[0].text));
  return false;
}

/// How many local-coordinate lines come before the profile: none when the first line is START.
std::size_t frame_lines(const KeywordContext& ctx, model::AnalyticalSurface::Type type) {
  if (type == model::AnalyticalSurface::Type::Segments || ctx.data.empty()) return 0;
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (!f.empty() && normalize_name(f[0].text) == "START") return 0;
  return type == model::AnalyticalSurface::Type::Cylinder ? 2 : 1;
}

}  // namespace

void analytical_surface(KeywordContext& ctx, model::Surface& surf, std::string_view type) {
  model::AnalyticalSurface s;
  s.name = surf.name;
  s.loc = ctx.keyword.loc;
  s.type = type == "SEGMENTS"   ? model::AnalyticalSurface::Type::Segments
           : type == "CYLINDER" ? model::AnalyticalSurface::Type::Cylinder
                                : model::AnalyticalSurface::Type::Revolution;
  if (const auto r = ctx.real_value("FILLET RADIUS")) {
    if (*r < 0.0) {
      ctx.error_param("FILLET RADIUS", "the fillet radius must not be negative");
      return;
    }
    s.fillet_radius = *r;
  }
  if (surf.kind == model::Surface::Kind::Analytical || !surf.faces.empty() || !surf.nodes.empty()) {
    ctx.error(ctx.keyword.loc, fmt::format("surface '{}' is defined twice; an analytical surface is one *SURFACE", surf.name));
    return;
  }
  const std::size_t skip = frame_lines(ctx, s.type);
  if (ctx.data.size() < skip + 2) {
    ctx.error(ctx.keyword.loc, "an analytical surface needs its profile: START, x, y, then LINE or CIRCL lines");
    return;
  }
  if (skip > 0 && !set_frame(ctx, s, ctx.data[0], skip > 1 ? &ctx.data[1] : nullptr)) return;
  for (std::size_t i = skip; i < ctx.data.size(); ++i)
    if (!profile_line(ctx, s, ctx.data[i], i == skip)) return;
  surf.kind = model::Surface::Kind::Analytical;
  surf.analytical = static_cast<std::int32_t>(ctx.model().analytical_surfaces.size());
  ctx.model().analytical_surfaces.push_back(std::move(s));
}

}  // namespace inpact::parser
