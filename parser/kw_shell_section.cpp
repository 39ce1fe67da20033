/// *SHELL SECTION, *SHELL GENERAL SECTION, their *TRANSVERSE SHEAR STIFFNESS, *NODAL THICKNESS
/// and *NORMAL [Abaqus Keywords].
///
/// *SHELL SECTION, ELSET=, MATERIAL=[, ORIENTATION=][, OFFSET=SPOS | SNEG | MIDDLE | value][,
/// NODAL THICKNESS]: one data line, the thickness and the number of section points (Simpson, odd;
/// default 5). With COMPOSITE (no MATERIAL=): a line a layer from SNEG up, `thickness, section
/// points (default 3), material, orientation name or angle, ply name`.
/// *SHELL GENERAL SECTION, ELSET=, MATERIAL= (or COMPOSITE): the thickness (a section given by its
/// stiffness matrix, without MATERIAL, is not supported yet). Gauss integration through the
/// thickness and shells of a *DENSITY-less general section stop here with what is missing.
#include <fmt/format.h>

#include <algorithm>

#include "finalize.hpp"
#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// OFFSET=: SPOS, SNEG, MIDDLE or a fraction of the thickness (the reader checked it is one).
double read_offset(KeywordContext& ctx) {
  if (!ctx.has("OFFSET")) return 0.0;
  if (auto value = ctx.real_value("OFFSET")) return *value;
  const std::string v = ctx.choice_value("OFFSET");
  return v == "SPOS" ? 0.5 : v == "SNEG" ? -0.5 : 0.0;
}

/// A number of Simpson section points (odd, at least 3); false after reporting one that is not.
bool read_section_points(KeywordContext& ctx, const Field& f, int& points) {
  auto n = ctx.integer(f, "number of section points");
  if (!n) return false;
  if (*n < 3 || *n % 2 == 0) {
    ctx.error(f.loc, fmt::format("Simpson's rule through the thickness takes an odd number of section points, at "
                                 "least 3; found {}", *n));
    return false;
  }
  points = static_cast<int>(*n);
  return true;
}

/// A layer's thickness: positive, or (NODAL THICKNESS) positive relative to the others.
bool read_layer_thickness(KeywordContext& ctx, const Field& f, double& thickness) {
  auto t = ctx.real(f, "layer thickness");
  if (!t) return false;
  if (!(*t > 0)) {
    ctx.error(f.loc, fmt::format("a layer's thickness must be positive, found {:g}", *t));
    return false;
  }
  thickness = *t;
  return true;
}

/// COMPOSITE's data lines: `thickness, section points, material, orientation, ply name`, a layer
/// each from SNEG up; the section's thickness is their sum.
bool read_layers(KeywordContext& ctx, model::ShellSection& sec) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 5, "thickness, number of section points, material[, orientation][, ply name]"))
      return false;
    model::ShellLayer layer;
    layer.loc = f[2].loc;
    if (!read_layer_thickness(ctx, f[0], layer.thickness)) return false;
    // A general section integrates each layer exactly: its number of points is not used.
    if (!sec.general && !f[1].empty() && !read_section_points(ctx, f[1], layer.section_points)) return false;
    layer.material = normalize_label(f[2].text);
    if (layer.material.empty()) {
      ctx.error(f[2].loc, "a layer needs its material's name");
      return false;
    }
    if (f.size() > 3 && !f[3].empty()) {
      if (auto angle = parse_real(f[3].text)) layer.angle = *angle;
      else layer.orientation = normalize_label(f[3].text), layer.orientation_loc = f[3].loc;
    }
    if (f.size() > 4) layer.ply = std::string(trim(f[4].text));
    sec.thickness += layer.thickness;
    sec.layers.push_back(std::move(layer));
  }
  return true;
}

/// The data line: thickness[, number of section points].
bool read_thickness_line(KeywordContext& ctx, model::ShellSection& sec) {
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  const std::size_t max = sec.general ? 1 : 2;
  if (!ctx.check_count(f, ctx.data[0], 1, max, sec.general ? "thickness" : "thickness[, number of section points]"))
    return false;
  if (!(f[0].empty() && sec.nodal_thickness)) {
    auto t = ctx.real(f[0], "thickness");
    if (!t) return false;
    if (*t <= 0 && !sec.nodal_thickness) {
      ctx.error(f[0].loc, fmt::format("the shell thickness must be positive, found {:g}", *t));
      return false;
    }
    sec.thickness = *t;
  }
  if (f.size() > 1 && !f[1].empty() && !read_section_points(ctx, f[1], sec.section_points)) return false;
  if (ctx.data.size() > 1) {
    split_fields(ctx.data[1], f);
    ctx.error(f.empty() ? ctx.data[1].loc : f[0].loc,
              "expected one data line (a section of layers, one a line, takes COMPOSITE)");
    return false;
  }
  return true;
}

void read_section(KeywordContext& ctx, bool general) {
  const char* unsupported[] = {"SECTION INTEGRATION", "DENSITY"};
  for (const char* p : unsupported)
    if (ctx.has(p) && !(std::string_view(p) == "SECTION INTEGRATION" && ctx.choice_value(p) == "SIMPSON")) {
      ctx.error_param(p, fmt::format("{} on a shell section is not supported yet", p));
      return;
    }
  const bool composite = ctx.has("COMPOSITE");
  if (composite && ctx.has("MATERIAL")) {
    ctx.error_param("MATERIAL", "a COMPOSITE section names a material on each layer's line, not MATERIAL=");
    return;
  }
  if (!composite && !ctx.has("MATERIAL")) {
    if (!general) {
      ctx.error(ctx.keyword.loc, "missing parameter MATERIAL (or COMPOSITE with a material on each layer's line)");
      return;
    }
    ctx.error(ctx.keyword.loc, "a *SHELL GENERAL SECTION given by its stiffness matrix (no MATERIAL=) is not supported "
                               "yet: give MATERIAL=");
    return;
  }
  model::ShellSection sec;
  sec.elset = ctx.name_value("ELSET");
  if (!composite) sec.material = ctx.name_value("MATERIAL");
  if (ctx.has("ORIENTATION")) sec.orientation = ctx.name_value("ORIENTATION"), sec.orientation_loc = ctx.param_loc("ORIENTATION");
  sec.general = general;
  sec.nodal_thickness = ctx.has("NODAL THICKNESS");
  sec.loc = ctx.keyword.loc;
  sec.offset = read_offset(ctx);
  if (composite ? !read_layers(ctx, sec) : !read_thickness_line(ctx, sec)) return;
  ctx.mesh().shell_sections.push_back(std::move(sec));
  ctx.state.open_parent = general ? "*SHELL GENERAL SECTION" : "*SHELL SECTION";  // its *TRANSVERSE SHEAR STIFFNESS
}

void shell_section(KeywordContext& ctx) { read_section(ctx, false); }
void shell_general_section(KeywordContext& ctx) { read_section(ctx, true); }

// *NODAL THICKNESS: `node or node set, thickness`.
void nodal_thickness(KeywordContext& ctx) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 2, "node or node set, thickness")) continue;
    auto nodes = ctx.nodes(f[0]);
    auto t = ctx.real(f[1], "thickness");
    if (!nodes || !t) continue;
    if (*t <= 0) {
      ctx.error(f[1].loc, fmt::format("the shell thickness must be positive, found {:g}", *t));
      continue;
    }
    for (std::int32_t n : *nodes) ctx.mesh().nodal_thickness[n] = *t;
  }
}

/// A field that names an entity by its label (digits), not a set.
bool is_label(const Field& f) {
  return !f.text.empty() && std::all_of(f.text.begin(), f.text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// *NORMAL: `element or element set, node or node set, nx, ny, nz` — a shell's director at its
// nodes in the set (Abaqus and CalculiX). Beams' n2 by *NORMAL: not yet.
void given_normal(KeywordContext& ctx, const Line& line, const std::vector<Field>& f) {
  auto elements = ctx.elements(f[0]);
  auto nodes = ctx.nodes(f[1]);
  if (!elements || !nodes) return;
  std::array<double, 3> n{};
  for (int i = 0; i < 3; ++i) {
    auto v = ctx.real(f[static_cast<std::size_t>(2 + i)], "normal component");
    if (!v) return;
    n[static_cast<std::size_t>(i)] = *v;
  }
  if (n == std::array<double, 3>{0.0, 0.0, 0.0}) {
    ctx.error(f[2].loc, "the normal is the zero vector");
    return;
  }
  // Sets pair each element with those of the nodes that are its own; two labels must fit.
  const bool labels = is_label(f[0]) && is_label(f[1]);
  auto& mesh = ctx.mesh();
  const std::size_t before = mesh.normals.size();
  for (std::int32_t e : *elements) {
    if (!model::is_shell(model::element_type(mesh.elements.type[static_cast<std::size_t>(e)]))) {
      ctx.error(f[0].loc, fmt::format("element {} is not a shell element (*NORMAL of beams is not supported yet)",
                                      mesh.elements.labels[static_cast<std::size_t>(e)]));
      return;
    }
    const auto conn = mesh.elements.nodes_of(static_cast<std::size_t>(e));
    for (std::int32_t node : *nodes)
      if (const auto at = std::find(conn.begin(), conn.end(), node); at != conn.end())
        mesh.normals.push_back({e, static_cast<int>(at - conn.begin()), n, line.loc});
  }
  if (mesh.normals.size() == before)
    ctx.error(f[1].loc, labels ? fmt::format("node {} is not a node of element {}", f[1].text, f[0].text)
                               : std::string("no node of the node set is a node of an element of the element set"));
}

void normal(KeywordContext& ctx) {
  resolve_pending_nodes(ctx.state.mesh_build(), ctx.diags);  // elements may precede their nodes
  if (ctx.has("TYPE") && ctx.name_value("TYPE") != "ELEMENT") {
    ctx.error_param("TYPE", "TYPE=CONTACT SURFACE is not supported yet (expected ELEMENT, the default)");
    return;
  }
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (ctx.check_count(f, line, 5, 5, "element or element set, node or node set, nx, ny, nz"))
      given_normal(ctx, line, f);
  }
}

}  // namespace

void shell_transverse_shear_stiffness(KeywordContext& ctx) {
  auto& sections = ctx.mesh().shell_sections;
  if (sections.empty()) return;  // the section itself was refused
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (!ctx.check_count(f, ctx.data[0], 2, 3, "K11, K22[, K12]")) return;
  std::array<double, 3> k{};
  const char* names[] = {"K11", "K22", "K12"};
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].empty()) continue;
    auto v = ctx.real(f[i], names[i]);
    if (!v) return;
    if (i < 2 && *v <= 0) {
      ctx.error(f[i].loc, fmt::format("{} must be positive, found {:g}", names[i], *v));
      return;
    }
    if (i == 2 && *v != 0) {
      ctx.error(f[i].loc, "a coupling term K12 other than 0 is not supported yet");
      return;
    }
    k[i] = *v;
  }
  sections.back().transverse_shear = k;
  if (ctx.data.size() > 1) ctx.error(ctx.data[1].loc, "expected one data line");
}

void add_shell_section_keywords(std::vector<KeywordSpec>& t) {
  const std::vector<ParamSpec> common = {{"ELSET", ValueKind::Required, ValueType::Text, {}, true},
                                         {"MATERIAL", ValueKind::Required, ValueType::Text},
                                         {"OFFSET", ValueKind::Required, ValueType::RealOrChoice, {"SPOS", "SNEG", "MIDDLE"}},
                                         {"NODAL THICKNESS", ValueKind::None, ValueType::Text},
                                         {"COMPOSITE", ValueKind::None, ValueType::Text},
                                         {"ORIENTATION", ValueKind::Required, ValueType::Text},
                                         {"SECTION INTEGRATION", ValueKind::Required, ValueType::Choice,
                                          {"SIMPSON", "GAUSS"}},
                                         {"POISSON", ValueKind::Required, ValueType::Real},
                                         {"DENSITY", ValueKind::Required, ValueType::Real}};
  // No numbers_from: a COMPOSITE line names its material; the handler reads every field.
  t.push_back({"*SHELL SECTION", kMeshScopes, common, DataLines::Required, shell_section});
  t.push_back({"*SHELL GENERAL SECTION", kMeshScopes, common, DataLines::Required, shell_general_section});
  t.push_back({"*NODAL THICKNESS", kMeshScopes, {}, DataLines::Required, nodal_thickness});
  t.push_back({"*NORMAL", kMeshScopes, {{"TYPE", ValueKind::Required, ValueType::Choice, {"ELEMENT", "CONTACT SURFACE"}}},
               DataLines::Required, normal});
  t.back().numbers_from = 2;
}

}  // namespace inpact::parser
