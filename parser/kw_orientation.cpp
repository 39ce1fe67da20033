/// *ORIENTATION: the local material axes a *SOLID SECTION's ORIENTATION= names.
#include <cmath>

#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// Reads fields [first, first + 3) of `f` into `out` (empty fields are 0).
bool read_point(KeywordContext& ctx, const std::vector<Field>& f, std::size_t first, double out[3]) {
  for (std::size_t i = 0; i < 3; ++i) {
    out[i] = 0.0;
    if (first + i >= f.size() || f[first + i].empty()) continue;
    auto v = ctx.real(f[first + i], "coordinate");
    if (!v) return false;
    out[i] = *v;
  }
  return true;
}

double distance(const double p[3], const double q[3]) {
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

/// The points a, b (and the rectangular origin c) of the first data line, checked for a
/// well-defined system: a ≠ c and b off the line c–a (rectangular), a ≠ b (cylindrical).
bool read_points(KeywordContext& ctx, const Line& line, model::Orientation& o) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!f.empty() && !f[0].empty() && !parse_real(f[0].text)) {
    ctx.error(f[0].loc, fmt::format("orientation data from a distribution ('{}', *DISTRIBUTION) is not supported yet "
                                    "(expected the coordinates a1, a2, a3, b1, b2, b3[, c1, c2, c3])", f[0].text));
    return false;
  }
  if (!ctx.check_count(f, line, 6, 9, "a1, a2, a3, b1, b2, b3[, c1, c2, c3]")) return false;
  if (!read_point(ctx, f, 0, o.a) || !read_point(ctx, f, 3, o.b) || !read_point(ctx, f, 6, o.c)) return false;
  if (o.system == model::Orientation::System::Cylindrical) {
    if (distance(o.a, o.b) == 0.0) ctx.error(f[3].loc, "the two points a and b of the cylinder axis coincide");
    return distance(o.a, o.b) != 0.0;
  }
  const double u[3] = {o.a[0] - o.c[0], o.a[1] - o.c[1], o.a[2] - o.c[2]};
  const double v[3] = {o.b[0] - o.c[0], o.b[1] - o.c[1], o.b[2] - o.c[2]};
  const double w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double zero[3] = {0, 0, 0};
  if (distance(w, zero) <= 1e-12 * distance(u, zero) * distance(v, zero)) {
    ctx.error(f[0].loc, "the points a and b do not span a plane with the origin c (a = c, or b on the line through c and a)");
    return false;
  }
  return true;
}

/// The optional second line: the local axis (1, 2, 3; empty: 1) and the angle in degrees.
void read_rotation(KeywordContext& ctx, const Line& line, model::Orientation& o) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 0, 2, "local axis of the additional rotation (1, 2 or 3), angle in degrees")) return;
  if (!f.empty() && !f[0].empty()) {
    auto axis = ctx.integer(f[0], "local axis");
    if (!axis) return;
    if (*axis < 1 || *axis > 3) {
      ctx.error(f[0].loc, fmt::format("the local axis of the additional rotation must be 1, 2 or 3, found {}", *axis));
      return;
    }
    o.axis = static_cast<int>(*axis);
  }
  if (f.size() > 1 && !f[1].empty()) {
    auto angle = ctx.real(f[1], "angle");
    if (angle) o.angle = *angle;
  }
}

// *ORIENTATION, NAME=, SYSTEM=RECTANGULAR (default) | CYLINDRICAL, DEFINITION=COORDINATES
// (default): a, b[, c] on the first line; an additional rotation about a local axis on the
// optional second line.
void orientation(KeywordContext& ctx) {
  model::Orientation o;
  const std::string key = ctx.name_value("NAME");
  o.name = ctx.param("NAME")->value.value_or(key);
  o.loc = ctx.keyword.loc;
  const std::string system = ctx.choice_value("SYSTEM");
  if (system == "CYLINDRICAL") o.system = model::Orientation::System::Cylindrical;
  else if (!system.empty() && system != "RECTANGULAR")
    return ctx.error_param("SYSTEM", fmt::format("SYSTEM={} is not supported yet (RECTANGULAR or CYLINDRICAL)", system));
  const std::string definition = ctx.choice_value("DEFINITION");
  if (!definition.empty() && definition != "COORDINATES")
    return ctx.error_param("DEFINITION", fmt::format("DEFINITION={} is not supported yet (only COORDINATES)", definition));
  if (ctx.has("LOCAL DIRECTIONS"))
    return ctx.error_param("LOCAL DIRECTIONS", "LOCAL DIRECTIONS is not supported yet");
  if (!read_points(ctx, ctx.data[0], o)) return;
  if (ctx.data.size() > 1) read_rotation(ctx, ctx.data[1], o), o.rotation_given = true;
  if (ctx.data.size() > 2) ctx.error(ctx.data[2].loc, "expected at most two data lines (points; additional rotation)");
  if (!ctx.model().orientations.try_emplace(key, std::move(o)).second)
    ctx.error_param("NAME", fmt::format("orientation '{}' is defined twice", key));
}

}  // namespace

void add_orientation_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*ORIENTATION", kMeshScopes,
               {{"NAME", ValueKind::Required, ValueType::Text, {}, true},
                {"SYSTEM", ValueKind::Required, ValueType::Choice,
                 {"RECTANGULAR", "CYLINDRICAL", "SPHERICAL", "Z RECTANGULAR", "USER"}},
                {"DEFINITION", ValueKind::Required, ValueType::Choice, {"COORDINATES", "NODES", "OFFSET TO NODES"}},
                {"LOCAL DIRECTIONS", ValueKind::Required, ValueType::Int}},
               DataLines::Required, orientation});
}

}  // namespace inpact::parser
