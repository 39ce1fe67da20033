/// *BEAM SECTION, *BEAM GENERAL SECTION and their *TRANSVERSE SHEAR STIFFNESS [Abaqus Keywords].
///
/// *BEAM SECTION, ELSET=, MATERIAL=, SECTION=RECT | CIRC | PIPE | BOX | I: first data line the
/// shape's dimensions (RECT a, b; CIRC r; PIPE r, t; BOX a, b, t1..t4; I l, h, b1, b2, t1, t2,
/// t3), second the approximate n1 direction (default (0, 0, −1)); CalculiX's OFFSET1/OFFSET2 put
/// the node line off the section's centre. *BEAM GENERAL SECTION, SECTION=GENERAL: A, I11, I12,
/// I22, J; n1; E, G; its *SECTION POINTS, where S and E are output. The other library shapes (L, HEX, TRAPEZOID, ARBITRARY, ...) and the other
/// general forms (MESHED, NONLINEAR GENERAL) stop here with what is missing.
///
/// CalculiX reads CIRC's number as the diameter (its "thickness"); inpact reads it as Abaqus does,
/// the radius. Two numbers are CalculiX's ellipse, its full axes along n1 and n2 (a warning;
/// Abaqus has no such form). A RECT of one width is CalculiX's square.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using Shape = model::BeamSection::Shape;

struct ShapeSpec {
  std::string_view name;
  Shape shape;
  std::size_t n_dims;
  std::string_view layout;
};

constexpr ShapeSpec kShapes[] = {{"RECT", Shape::Rect, 2, "a (width along n1), b (along n2)"},
                                 {"CIRC", Shape::Circ, 1, "radius (or CalculiX's ellipse: its axes along n1, n2)"},
                                 {"PIPE", Shape::Pipe, 2, "outer radius, wall thickness"},
                                 {"BOX", Shape::Box, 6, "a, b (outer widths along n1, n2), t1, t2, t3, t4 (walls)"},
                                 {"I", Shape::I, 7, "l, h, b1, b2, t1, t2, t3"},
                                 {"GENERAL", Shape::General, 5, "A, I11, I12, I22, J"}};

bool box_walls_fit(KeywordContext& ctx, const std::vector<Field>& f, const std::vector<double>& d);
bool i_parts_fit(KeywordContext& ctx, const std::vector<Field>& f, const std::vector<double>& d);

/// The dimensions line: each a positive number (I12 of a general section may be any number).
bool read_dims(KeywordContext& ctx, const Line& line, const ShapeSpec& spec, model::BeamSection& sec) {
  std::vector<Field> f;
  split_fields(line, f);
  if (spec.shape == Shape::Rect && f.size() == 1) {  // CalculiX: a RECT of one width is a square
    ctx.warning(f[0].loc, fmt::format("RECT with one width {} is read as CalculiX's square (Abaqus needs a, b)",
                                      f[0].text));
    f.push_back(f[0]);
  }
  const bool ellipse = spec.shape == Shape::Circ && f.size() == 2;
  if (ellipse)
    ctx.warning(f[0].loc, fmt::format("CIRC with two numbers is read as CalculiX's ellipse: its full axes {} along n1 "
                                      "and {} along n2 (a one-number CIRC is Abaqus's radius)", f[0].text, f[1].text));
  const std::size_t n_dims = ellipse ? 2 : spec.n_dims;
  if (!ctx.check_count(f, line, n_dims, spec.shape == Shape::General ? 7 : n_dims, spec.layout)) return false;
  sec.dims_loc = line.loc;
  for (std::size_t i = 0; i < n_dims; ++i) {
    auto v = ctx.real(f[i], "section dimension");
    if (!v) return false;
    const bool signed_value = spec.shape == Shape::General && i == 2;  // I12
    const bool origin = spec.shape == Shape::I && i == 0;             // l: anywhere along the web's line
    if (!signed_value && !origin && *v <= 0) {
      ctx.error(f[i].loc, fmt::format("the section dimensions must be positive ({}), found {:g}", spec.layout, *v));
      return false;
    }
    if (signed_value && *v != 0) {
      ctx.error(f[i].loc, "a product of inertia I12 other than 0 is not supported yet (give the section in its "
                          "principal axes)");
      return false;
    }
    sec.dims.push_back(ellipse ? *v / 2 : *v);  // the model holds the ellipse's semi-axes
  }
  if (spec.shape == Shape::Pipe && sec.dims[1] > sec.dims[0]) {
    ctx.error(f[1].loc, fmt::format("the wall thickness {:g} exceeds the outer radius {:g}", sec.dims[1], sec.dims[0]));
    return false;
  }
  if (spec.shape == Shape::Box) return box_walls_fit(ctx, f, sec.dims);
  return spec.shape != Shape::I || i_parts_fit(ctx, f, sec.dims);
}

/// A BOX's walls fit inside it.
bool box_walls_fit(KeywordContext& ctx, const std::vector<Field>& f, const std::vector<double>& d) {
  if (d[2] + d[4] >= d[0] || d[3] + d[5] >= d[1]) {
    const std::size_t wall = d[2] + d[4] >= d[0] ? 2 : 3;
    ctx.error(f[wall].loc, fmt::format("the walls t1 + t3 = {:g} and t2 + t4 = {:g} must be thinner than a = {:g} and "
                                       "b = {:g}", d[2] + d[4], d[3] + d[5], d[0], d[1]));
    return false;
  }
  return true;
}

/// An I's flanges fit in its height and its web in its flanges.
bool i_parts_fit(KeywordContext& ctx, const std::vector<Field>& f, const std::vector<double>& d) {
  if (d[4] + d[5] >= d[1]) {
    ctx.error(f[4].loc, fmt::format("the flanges t1 + t2 = {:g} must be thinner than the height h = {:g}", d[4] + d[5],
                                    d[1]));
    return false;
  }
  if (d[6] > d[2] || d[6] > d[3]) {
    ctx.error(f[6].loc, fmt::format("the web t3 = {:g} must be no wider than the flanges b1 = {:g}, b2 = {:g}", d[6],
                                    d[2], d[3]));
    return false;
  }
  return true;
}

/// The n1 line (optional): three components, not all zero.
bool read_n1(KeywordContext& ctx, const Line& line, model::BeamSection& sec) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 3, 3, "n1x, n1y, n1z (the approximate n1 direction)")) return false;
  double norm = 0.0;
  for (int i = 0; i < 3; ++i) {
    auto v = ctx.real(f[static_cast<std::size_t>(i)], "n1 component");
    if (!v) return false;
    sec.n1[static_cast<std::size_t>(i)] = *v;
    norm += *v * *v;
  }
  if (norm == 0.0) {
    ctx.error(line.loc, "the n1 direction is the zero vector");
    return false;
  }
  sec.n1_loc = line.loc;
  return true;
}

/// GENERAL's third line: E, G (and a thermal expansion inpact does not take yet).
bool read_moduli(KeywordContext& ctx, const Line& line, model::BeamSection& sec) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 2, 3, "E, G[, thermal expansion]")) return false;
  auto e = ctx.real(f[0], "Young's modulus");
  auto g = ctx.real(f[1], "shear modulus");
  if (!e || !g) return false;
  if (*e <= 0 || *g <= 0) {
    ctx.error(line.loc, fmt::format("E and G must be positive, found {:g}, {:g}", *e, *g));
    return false;
  }
  if (f.size() > 2 && !f[2].empty()) {
    ctx.error(f[2].loc, "thermal expansion of a general beam section is not supported yet");
    return false;
  }
  sec.youngs_modulus = *e;
  sec.shear_modulus = *g;
  return true;
}

const ShapeSpec* find_shape(std::string_view name) {
  for (const ShapeSpec& s : kShapes)
    if (s.name == name) return &s;
  return nullptr;
}

void read_section(KeywordContext& ctx, bool general) {
  const std::string name = general ? (ctx.has("SECTION") ? ctx.name_value("SECTION") : "GENERAL")
                                   : ctx.name_value("SECTION");
  const ShapeSpec* spec = find_shape(name);
  if (!spec || (spec->shape == Shape::General) != general) {
    ctx.error_param("SECTION", fmt::format("SECTION={} is not supported yet (expected {})", name,
                                           general ? "GENERAL" : "RECT, CIRC, PIPE, BOX or I"));
    return;
  }
  model::BeamSection sec;
  sec.elset = ctx.name_value("ELSET");
  sec.material = general ? std::string() : ctx.name_value("MATERIAL");
  sec.shape = spec->shape;
  sec.loc = ctx.keyword.loc;
  sec.n1_loc = ctx.keyword.loc;
  if (!general) sec.offset = {ctx.real_value("OFFSET1").value_or(0.0), ctx.real_value("OFFSET2").value_or(0.0)};
  if (spec->shape == Shape::I && (ctx.has("OFFSET1") || ctx.has("OFFSET2"))) {
    ctx.error_param(ctx.has("OFFSET1") ? "OFFSET1" : "OFFSET2",
                    "an I section places its nodes by its own l (its first dimension); CalculiX's offsets are for "
                    "RECT, CIRC, PIPE and BOX");
    return;
  }
  const std::size_t n_lines = general ? 3 : 2;
  if (ctx.data.size() > n_lines) {
    ctx.error(ctx.data[n_lines].loc, fmt::format("expected at most {} data lines", n_lines));
    return;
  }
  if (!read_dims(ctx, ctx.data[0], *spec, sec)) return;
  if (ctx.data.size() > 1 && !read_n1(ctx, ctx.data[1], sec)) return;
  if (general) {
    if (ctx.data.size() < 3) {
      ctx.error(ctx.data.back().loc, "a general beam section needs a third data line: E, G");
      return;
    }
    if (!read_moduli(ctx, ctx.data[2], sec)) return;
  }
  ctx.mesh().beam_sections.push_back(std::move(sec));
  ctx.state.open_parent = general ? "*BEAM GENERAL SECTION" : "*BEAM SECTION";  // its *TRANSVERSE SHEAR STIFFNESS
}

void beam_section(KeywordContext& ctx) { read_section(ctx, false); }
void beam_general_section(KeywordContext& ctx) { read_section(ctx, true); }

// *TRANSVERSE SHEAR STIFFNESS under a beam section: K23, K13[, slenderness compensation]; under a
// shell section kw_shell_section.cpp reads it.
void transverse_shear_stiffness(KeywordContext& ctx) {
  if (ctx.state.open_parent.starts_with("*SHELL")) {
    shell_transverse_shear_stiffness(ctx);
    return;
  }
  auto& sections = ctx.mesh().beam_sections;
  if (sections.empty()) return;  // the section itself was refused
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (!ctx.check_count(f, ctx.data[0], 1, 3, "K23, K13[, slenderness compensation factor]")) return;
  model::BeamSection& sec = sections.back();
  const char* names[] = {"K23", "K13", "slenderness compensation factor"};
  std::optional<double>* slots[] = {&sec.k23, &sec.k13, &sec.slenderness_compensation};
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].empty()) continue;
    auto v = ctx.real(f[i], names[i]);
    if (!v) return;
    if (*v < 0 || (i < 2 && *v == 0)) {
      ctx.error(f[i].loc, fmt::format("{} must be positive, found {:g}", names[i], *v));
      return;
    }
    *slots[i] = *v;
  }
  if (ctx.data.size() > 1) ctx.error(ctx.data[1].loc, "expected one data line");
}

// *SECTION POINTS under *BEAM GENERAL SECTION: x1, x2 pairs, at most four a line; a (0, 0) ending a
// line is padding unless it is the only point given (Abaqus Keywords).
void section_points(KeywordContext& ctx) {
  auto& sections = ctx.mesh().beam_sections;
  if (sections.empty() || sections.back().shape != Shape::General) return;  // the section itself was refused
  std::vector<std::array<double, 2>> points;
  for (const Line& line : ctx.data) {
    std::vector<Field> f;
    split_fields(line, f);
    while (!f.empty() && f.back().empty()) f.pop_back();
    if (f.size() % 2 != 0 || f.size() > 8) {
      ctx.error(line.loc, fmt::format("expected x1, x2 pairs, at most four a line; found {} values", f.size()));
      return;
    }
    std::vector<std::array<double, 2>> on_line;
    for (std::size_t i = 0; i < f.size(); i += 2) {
      auto x1 = ctx.real(f[i], "section point x1");
      auto x2 = ctx.real(f[i + 1], "section point x2");
      if (!x1 || !x2) return;
      on_line.push_back({*x1, *x2});
    }
    if (!on_line.empty() && on_line.back() == std::array<double, 2>{0.0, 0.0} &&
        on_line.size() + points.size() > 1) on_line.pop_back();
    points.insert(points.end(), on_line.begin(), on_line.end());
  }
  sections.back().section_points = std::move(points);
}

}  // namespace

void add_beam_section_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*BEAM SECTION", kMeshScopes,
               {{"ELSET", ValueKind::Required, ValueType::Text, {}, true},
                {"MATERIAL", ValueKind::Required, ValueType::Text, {}, true},
                {"SECTION", ValueKind::Required, ValueType::Text, {}, true},
                {"POISSON", ValueKind::Required, ValueType::Real},
                {"TEMPERATURE", ValueKind::Required, ValueType::Choice, {"GRADIENTS", "VALUES"}},
                {"OFFSET1", ValueKind::Required, ValueType::Real}, {"OFFSET2", ValueKind::Required, ValueType::Real}},
               DataLines::Required, beam_section});
  t.back().numbers_from = 0;
  t.push_back({"*BEAM GENERAL SECTION", kMeshScopes,
               {{"ELSET", ValueKind::Required, ValueType::Text, {}, true},
                {"SECTION", ValueKind::Required, ValueType::Text},
                {"DENSITY", ValueKind::Required, ValueType::Real},
                {"POISSON", ValueKind::Required, ValueType::Real},
                {"ZERO", ValueKind::Required, ValueType::Real}},
               DataLines::Required, beam_general_section});
  t.back().numbers_from = 0;
  t.push_back({"*TRANSVERSE SHEAR STIFFNESS", kMeshScopes, {}, DataLines::Required, transverse_shear_stiffness,
               {"*BEAM SECTION", "*BEAM GENERAL SECTION", "*SHELL SECTION", "*SHELL GENERAL SECTION"}});
  t.back().numbers_from = 0;
  t.push_back({"*SECTION POINTS", kMeshScopes, {}, DataLines::Required, section_points, {"*BEAM GENERAL SECTION"}});
  t.back().numbers_from = 0;
}

}  // namespace inpact::parser
