/// General contact (*CONTACT with *CONTACT INCLUSIONS / EXCLUSIONS / PROPERTY ASSIGNMENT and
/// *SURFACE PROPERTY ASSIGNMENT) and *SURFACE SMOOTHING, which share the geometric-correction
/// data lines of [AX] §38.1.3.
#include <cmath>

#include <fmt/format.h>

#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser::contact_kw {

namespace {

using Kind = model::GeometricCorrection::Kind;

/// General contact in a step would (de)activate interactions: *CONTACT reported it already.
bool in_step(const KeywordContext& ctx) { return ctx.state.step != nullptr; }

/// Reads `count` coordinates starting at field `first` into `out`.
bool read_point(KeywordContext& ctx, const std::vector<Field>& f, std::size_t first, std::size_t count,
                std::array<double, 3>& out, const char* what) {
  bool ok = true;
  for (std::size_t i = 0; i < count; ++i) {
    auto v = ctx.real(f[first + i], fmt::format("{} {}", what, "XYZ"[i]));
    if (v) out[i] = *v;
    else ok = false;
  }
  return ok;
}

/// One geometric-correction line [AX p.789]:
///   surface, CIRCUMFERENTIAL, Xa, Ya, Za, Xb, Yb, Zb   axis of revolution through a and b
///   surface, SPHERICAL, Xa, Ya, Za                     sphere centre
///   surface, TOROIDAL, Xa, Ya, Za, Xb, Yb, Zb, R       axis a-b, arc centre at R from it
///   surface, CIRCUMFERENTIAL, Xc, Yc                   2D circular arc about (Xc, Yc); its layout
///     is UNCONFIRMED (KEYWORDS.md Part D 3). It is stored as the axis through (Xc, Yc, 0) along
///     z, which is the same geometry: a circle in the x-y plane is a section of that cylinder.
std::optional<model::GeometricCorrection> read_correction(KeywordContext& ctx, const Line& line) {
  std::vector<Field> f;
  split_fields(line, f);
  constexpr const char* layout = "surface, CIRCUMFERENTIAL|SPHERICAL|TOROIDAL, axis point a[, axis point b][, R]";
  if (!ctx.check_count(f, line, 2, 9, layout)) return std::nullopt;
  model::GeometricCorrection c;
  c.loc = line_start(line);
  c.surface = normalize_label(f[0].text);
  if (c.surface.empty()) {
    ctx.error(f[0].loc, "the surface name is missing");
    return std::nullopt;
  }
  const std::string method = normalize_name(f[1].text);
  std::size_t n_fields = 0;
  if (method == "CIRCUMFERENTIAL") {
    c.kind = Kind::Circumferential;
    n_fields = f.size() == 4 ? 4 : 8;
  } else if (method == "SPHERICAL") {
    c.kind = Kind::Spherical;
    n_fields = 5;
  } else if (method == "TOROIDAL") {
    c.kind = Kind::Toroidal;
    n_fields = 9;
  } else {
    ctx.error(f[1].loc, fmt::format("unknown smoothing method '{}' (expected CIRCUMFERENTIAL, SPHERICAL or TOROIDAL)", f[1].text));
    return std::nullopt;
  }
  if (!ctx.check_count(f, line, n_fields, n_fields, layout)) return std::nullopt;
  if (n_fields == 4) {
    if (!read_point(ctx, f, 2, 2, c.a, "centre")) return std::nullopt;
    c.b = {c.a[0], c.a[1], 1.0};
    return c;
  }
  if (!read_point(ctx, f, 2, 3, c.a, c.kind == Kind::Spherical ? "centre" : "axis point a")) return std::nullopt;
  if (c.kind == Kind::Spherical) return c;
  if (!read_point(ctx, f, 5, 3, c.b, "axis point b")) return std::nullopt;
  const double len = std::hypot(c.b[0] - c.a[0], c.b[1] - c.a[1], c.b[2] - c.a[2]);
  if (len == 0) {
    ctx.error(f[5].loc, "the axis has zero length: point b coincides with point a");
    return std::nullopt;
  }
  if (c.kind == Kind::Toroidal) {
    auto r = ctx.real(f[8], "torus radius R");
    if (!r) return std::nullopt;
    if (*r <= 0) {
      ctx.error(f[8].loc, fmt::format("the distance R of the arc centre from the axis must be positive, found {}", *r));
      return std::nullopt;
    }
    c.radius = *r;
  }
  return c;
}

/// *CONTACT INCLUSIONS / EXCLUSIONS lines `surf1, surf2` [K16], [IG]: blank surf1 = the
/// all-inclusive exterior surface; blank surf2 (or surf2 = surf1) = self-contact of surf1; both
/// blank = ALL EXTERIOR. Kept as model/contact.hpp documents: self-contact has second == first.
void read_inclusions(KeywordContext& ctx, std::vector<model::GeneralContact::Inclusion>& out) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 2, "first surface, second surface")) continue;
    model::GeneralContact::Inclusion inc;
    inc.first = normalize_label(f[0].text);
    inc.second = f.size() == 2 && !f[1].empty() ? normalize_label(f[1].text) : inc.first;
    inc.loc = line_start(line);
    out.push_back(std::move(inc));
  }
}

}  // namespace

// *CONTACT: opens general contact [K16 §3.54]. Its only parameter, OP, changes general contact
// in a step (Abaqus/Explicit); in the model data OP=NEW (what Abaqus/CAE writes) is the one
// definition there is, and OP=MOD has nothing to modify.
void contact(KeywordContext& ctx) {
  ctx.state.open_parent = kContact;
  if (in_step(ctx)) {
    ctx.error(ctx.keyword.loc, "general contact in a step (activating or changing it) is not supported yet; define it in the model data");
    return;
  }
  if (ctx.choice_value("OP") == "MOD") warn_ignored(ctx, "OP", "it applies to Abaqus/Explicit only");
  model::GeneralContact& gc = ctx.model().general_contact;
  if (gc.defined) {
    ctx.error(ctx.keyword.loc, "general contact is defined twice (one *CONTACT block per model)");
    return;
  }
  gc.defined = true;
  gc.loc = ctx.keyword.loc;
}

// *CONTACT INCLUSIONS [, ALL EXTERIOR]: with ALL EXTERIOR no data lines; without it, at least one.
void contact_inclusions(KeywordContext& ctx) {
  if (in_step(ctx)) return;
  auto& inclusions = ctx.model().general_contact.inclusions;
  if (ctx.has("ALL EXTERIOR")) {
    if (!ctx.data.empty()) ctx.error(line_start(ctx.data[0]), "ALL EXTERIOR takes no data lines");
    inclusions.push_back({"", "", ctx.keyword.loc});
    return;
  }
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, "data lines are missing (or give ALL EXTERIOR)");
    return;
  }
  read_inclusions(ctx, inclusions);
}

void contact_exclusions(KeywordContext& ctx) {
  if (in_step(ctx)) return;
  read_inclusions(ctx, ctx.model().general_contact.exclusions);
}

// *CONTACT PROPERTY ASSIGNMENT: `surf1, surf2, interaction`; `, , NAME` is the global
// assignment [AX p.790]; where assignments overlap the last one applies (kept in order).
void contact_property_assignment(KeywordContext& ctx) {
  if (in_step(ctx)) return;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 3, "first surface, second surface, surface interaction")) continue;
    if (f[2].empty()) {
      ctx.error(f[2].loc, "the surface interaction name is missing");
      continue;
    }
    model::GeneralContact::PropertyAssignment pa;
    pa.first = normalize_label(f[0].text);
    pa.second = f[1].empty() ? pa.first : normalize_label(f[1].text);
    pa.interaction = normalize_label(f[2].text);
    pa.loc = line_start(line);
    pa.interaction_loc = f[2].loc;
    ctx.model().general_contact.property_assignments.push_back(std::move(pa));
  }
}

// *SURFACE PROPERTY ASSIGNMENT, PROPERTY= [K16 §18.53], [AX p.789]. Only GEOMETRIC CORRECTION
// (smoothing) is honoured; the others change contact thickness or edge treatment.
void surface_property_assignment(KeywordContext& ctx) {
  if (in_step(ctx)) return;
  const std::string property = ctx.choice_value("PROPERTY");
  if (property != "GEOMETRICCORRECTION") {
    if (!property.empty())
      ctx.error_param("PROPERTY", fmt::format("PROPERTY={} is not supported yet (only GEOMETRIC CORRECTION)",
                                              ctx.param("PROPERTY")->value.value_or(property)));
    return;
  }
  for (const Line& line : ctx.data)
    if (auto c = read_correction(ctx, line)) ctx.model().general_contact.geometric_corrections.push_back(std::move(*c));
}

// *SURFACE SMOOTHING, NAME=: the smoothing a surface-to-surface pair names with GEOMETRIC
// CORRECTION=; data lines as *SURFACE PROPERTY ASSIGNMENT's (the [K16] layout was stripped;
// assumed the same, KEYWORDS.md Part D 3).
void surface_smoothing(KeywordContext& ctx) {
  const std::string key = ctx.name_value("NAME");
  auto [it, inserted] = ctx.model().surface_smoothings.try_emplace(key);
  if (!inserted) {
    ctx.error_param("NAME", fmt::format("surface smoothing '{}' is defined twice", key));
    return;
  }
  it->second.name = ctx.param("NAME")->value.value_or(key);
  it->second.loc = ctx.keyword.loc;
  for (const Line& line : ctx.data)
    if (auto c = read_correction(ctx, line)) it->second.corrections.push_back(std::move(*c));
}

}  // namespace inpact::parser::contact_kw
