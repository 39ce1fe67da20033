/// *HEADING *NODE *ELEMENT *NSET *ELSET *SURFACE: the mesh and its named regions (an analytical
/// *SURFACE's profile: kw_analytical_surface.cpp).
#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "finalize.hpp"
#include "handlers.hpp"
#include "model/mesh_queries.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using model::Set;

void sort_unique(std::vector<std::int32_t>& rows) {
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
}

/// The set `name` in `sets`, created on first use (Abaqus appends to an existing set).
Set& set_named(std::map<std::string, Set>& sets, const KeywordContext& ctx, std::string_view param) {
  const std::string key = ctx.name_value(param);
  Set& s = sets[key];
  if (s.name.empty()) {
    s.name = ctx.param(param)->value.value_or(key);
    s.loc = ctx.keyword.loc;
  }
  return s;
}

// *HEADING: free text, kept for the report.
void heading(KeywordContext& ctx) {
  for (const Line& line : ctx.data) {
    if (!ctx.model().heading.empty()) ctx.model().heading += '\n';
    ctx.model().heading += std::string(trim(line.text));
  }
}

// *NODE, NSET=: label, x, y[, z][, nx, ny, nz]. Missing coordinates are zero (2D decks give two);
// a normal, when given, is the shells' director there (solver/shell_normals.hpp).
void node(KeywordContext& ctx) {
  model::Nodes& nodes = ctx.mesh().nodes;
  Set* nset = ctx.has("NSET") ? &set_named(ctx.mesh().nsets, ctx, "NSET") : nullptr;
  std::vector<Field> f;
  nodes.labels.reserve(nodes.labels.size() + ctx.data.size());
  nodes.coords.reserve(nodes.coords.size() + ctx.data.size());
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 7, "node label, x, y, z[, nx, ny, nz]")) continue;
    auto label = ctx.integer(f[0], "node label");
    if (!label) continue;
    if (*label <= 0) {
      ctx.error(f[0].loc, fmt::format("node label {} must be positive", *label));
      continue;
    }
    std::array<double, 3> x{0, 0, 0};
    bool ok = true;
    for (std::size_t i = 1; i < std::min<std::size_t>(f.size(), 4); ++i) {
      if (f[i].empty()) continue;
      static constexpr std::string_view kCoordinate[] = {"", "coordinate 1", "coordinate 2", "coordinate 3"};
      auto v = ctx.real(f[i], kCoordinate[i]);
      if (!v) ok = false;
      else x[i - 1] = *v;
    }
    std::array<double, 3> normal{0, 0, 0};
    for (std::size_t i = 4; i < f.size(); ++i) {
      if (f[i].empty()) continue;
      auto v = ctx.real(f[i], "normal component");
      if (!v) ok = false;
      else normal[i - 4] = *v;
    }
    if (!ok) continue;
    const auto row = static_cast<std::int32_t>(nodes.labels.size());
    if (!nodes.index.insert(0, *label, row)) {
      ctx.error(f[0].loc, fmt::format("node {} is defined twice", *label));
      continue;
    }
    if (normal != std::array<double, 3>{0, 0, 0}) ctx.mesh().node_normals[row] = {0, 0, normal, line.loc};
    nodes.labels.push_back(*label);
    nodes.coords.push_back(x);
    nodes.instance.push_back(0);
    if (nset) nset->rows.push_back(row);
  }
  if (nset) sort_unique(nset->rows);
}

// *ELEMENT, TYPE=DCOUP3D | DCOUP2D, ELSET=: "label, node", the reference node of the
// *DISTRIBUTING COUPLING that names the set. The set exists (empty) so that a section may name it,
// as CalculiX's decks do.
void coupling_elements(KeywordContext& ctx) {
  if (ctx.state.part) {
    ctx.error_param("TYPE", "distributing coupling elements inside a *PART are not supported yet");
    return;
  }
  if (!ctx.has("ELSET")) {
    ctx.error(ctx.keyword.loc, "distributing coupling elements need ELSET=, the set *DISTRIBUTING COUPLING names");
    return;
  }
  set_named(ctx.state.mesh_build().mesh.elsets, ctx, "ELSET");
  auto& list = ctx.state.coupling_elements[ctx.name_value("ELSET")];
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 2, "element label and its one node label")) continue;
    const auto label = ctx.integer(f[0], "element label");
    const auto node = ctx.integer(f[1], "node label");
    if (label && node) list.push_back({*label, *node, f[1].loc});
  }
}

// *ELEMENT, TYPE=, ELSET=: label, node labels; a line ending in a comma continues.
void element(KeywordContext& ctx) {
  const std::string type_name = ctx.name_value("TYPE");
  if (type_name == "DCOUP3D" || type_name == "DCOUP2D") {
    coupling_elements(ctx);
    return;
  }
  const model::ElementTypeInfo* type = model::find_element_type(type_name);
  if (!type) {
    std::vector<std::string> names;
    for (const auto& t : model::element_types()) names.emplace_back(t.name);
    const std::string guess = did_you_mean(type_name, names);
    ctx.error_param("TYPE", fmt::format("element type '{}' is not supported{}", type_name,
                                        guess.empty() ? fmt::format(" (supported: C3D8, C3D8R, C3D8I, C3D20(R), C3D4, C3D10, C3D6, CPE/CPS/CAX 3, 4, 6, 8 and their R/I forms, T2D2, T3D2, T3D3, SPRINGA, SPRING1, SPRING2)")
                                                      : fmt::format(" (did you mean {}?)", guess)));
    return;
  }
  MeshBuild& build = ctx.state.mesh_build();
  model::Elements& el = build.mesh.elements;
  const model::Nodes& nodes = build.mesh.nodes;
  Set* elset = ctx.has("ELSET") ? &set_named(build.mesh.elsets, ctx, "ELSET") : nullptr;
  const std::uint8_t type_index = model::element_type_index(*type);
  const std::size_t need = 1 + type->n_nodes;
  const std::string layout = fmt::format("element label and {} node labels for {}", type->n_nodes, type->name);
  el.labels.reserve(el.labels.size() + ctx.data.size());
  el.conn.reserve(el.conn.size() + ctx.data.size() * type->n_nodes);

  std::vector<Field> f, record;
  for (std::size_t i = 0; i < ctx.data.size(); ++i) {
    const Line& first = ctx.data[i];
    split_fields(first, record);
    // Continuation: a record short of nodes whose line ends with a comma goes on.
    while (record.size() < need && trim(ctx.data[i].text).ends_with(',') && i + 1 < ctx.data.size()) {
      split_fields(ctx.data[++i], f);
      record.insert(record.end(), f.begin(), f.end());
    }
    if (!ctx.check_count(record, first, need, need, layout)) continue;
    auto label = ctx.integer(record[0], "element label");
    if (!label) continue;
    if (*label <= 0) {
      ctx.error(record[0].loc, fmt::format("element label {} must be positive", *label));
      continue;
    }
    bool ok = true;
    const std::size_t conn_start = el.conn.size();
    for (std::size_t k = 1; k < need; ++k) {
      auto n = ctx.integer(record[k], "node label");
      if (!n) {
        ok = false;
        break;
      }
      if (auto r = nodes.index.find(0, *n)) {
        el.conn.push_back(*r);
      } else {
        build.pending.push_back({el.conn.size(), *n, 0, record[k].loc});
        el.conn.push_back(-1);
      }
    }
    // The label is indexed only once the whole record is good: an index entry for an element
    // that was then dropped would point at the row of the next element.
    const auto row = static_cast<std::int32_t>(el.labels.size());
    if (ok && !el.index.insert(0, *label, row)) {
      auto prev = el.index.find(0, *label);
      ctx.error(record[0].loc, fmt::format("element {} is defined twice (first at line {})", *label,
                                           el.loc[*prev].line));
      ok = false;
    }
    if (!ok) {
      // Undo the partial element so the table stays consistent.
      el.conn.resize(conn_start);
      while (!build.pending.empty() && build.pending.back().conn_index >= conn_start) build.pending.pop_back();
      continue;
    }
    el.labels.push_back(*label);
    el.type.push_back(type_index);
    el.instance.push_back(0);
    el.offsets.push_back(static_cast<std::int64_t>(el.conn.size()));
    el.loc.push_back(first.loc);
    if (elset) elset->rows.push_back(row);
  }
  if (elset) sort_unique(elset->rows);
}

/// *NSET and *ELSET share their data forms: labels and set names, or GENERATE ranges.
void fill_set(KeywordContext& ctx, bool is_node_set) {
  model::Mesh& mesh = ctx.mesh();
  auto& sets = is_node_set ? mesh.nsets : mesh.elsets;
  const char* param = is_node_set ? "NSET" : "ELSET";
  if (ctx.has("INSTANCE")) {
    const std::string inst = ctx.name_value("INSTANCE");
    const auto& names = ctx.model().instances;
    auto it = std::find_if(names.begin() + 1, names.end(),
                           [&](const std::string& n) { return normalize_label(n) == inst; });
    if (it == names.end()) {
      ctx.error_param("INSTANCE", fmt::format("instance '{}' is not defined", inst));
      return;
    }
    ctx.label_instance = static_cast<std::int32_t>(it - names.begin());
  }
  Set& set = set_named(sets, ctx, param);
  set.internal = set.internal || ctx.has("INTERNAL");
  const model::LabelMap& index = is_node_set ? mesh.nodes.index : mesh.elements.index;
  const char* what = is_node_set ? "node" : "element";
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (ctx.has("GENERATE")) {
      if (!ctx.check_count(f, line, 2, 3, "first label, last label[, increment]")) continue;
      auto a = ctx.integer(f[0], "first label");
      auto b = ctx.integer(f[1], "last label");
      auto step = f.size() > 2 && !f[2].empty() ? ctx.integer(f[2], "increment") : std::optional<std::int64_t>(1);
      if (!a || !b || !step) continue;
      if (*step <= 0 || *b < *a) {
        ctx.error(line.loc, fmt::format("GENERATE needs first <= last and a positive increment (got {}, {}, {})", *a, *b, *step));
        continue;
      }
      // Labels in the range that do not exist are skipped, as generated ranges often span gaps.
      // The arithmetic is unsigned (no overflow near the int64 limits), and a range wider than
      // the mesh is matched against the mesh's labels instead of walked label by label, which
      // for `1, 9223372036854775807` would never end.
      const auto first = static_cast<std::uint64_t>(*a);
      const auto inc = static_cast<std::uint64_t>(*step);
      const std::uint64_t n_range = (static_cast<std::uint64_t>(*b) - first) / inc + 1;
      const auto& labels = is_node_set ? mesh.nodes.labels : mesh.elements.labels;
      if (n_range > labels.size()) {
        for (std::size_t row = 0; row < labels.size(); ++row) {
          const std::int64_t l = labels[row];
          if (l < *a || l > *b || (static_cast<std::uint64_t>(l) - first) % inc != 0) continue;
          auto r = index.find(ctx.label_instance, l);
          if (r && static_cast<std::size_t>(*r) == row) set.rows.push_back(*r);
        }
        continue;
      }
      for (std::uint64_t k = 0; k < n_range; ++k)
        if (auto r = index.find(ctx.label_instance, static_cast<std::int64_t>(first + k * inc))) set.rows.push_back(*r);
      continue;
    }
    for (const Field& field : f) {
      if (field.empty()) continue;
      auto rows = is_node_set ? ctx.nodes(field) : ctx.elements(field);
      if (rows) set.rows.insert(set.rows.end(), rows->begin(), rows->end());
    }
    (void)what;
  }
  sort_unique(set.rows);
}

void nset(KeywordContext& ctx) {
  if (ctx.has("ELSET")) {
    // *NSET, ELSET=: the nodes of an element set.
    auto it = ctx.mesh().elsets.find(ctx.name_value("ELSET"));
    if (it == ctx.mesh().elsets.end()) {
      ctx.error_param("ELSET", fmt::format("element set '{}' is not defined", ctx.name_value("ELSET")));
      return;
    }
    Set& set = set_named(ctx.mesh().nsets, ctx, "NSET");
    resolve_pending_nodes(ctx.state.mesh_build(), ctx.diags);
    for (std::int32_t e : it->second.rows)
      for (std::int32_t n : ctx.mesh().elements.nodes_of(e)) set.rows.push_back(n);
    sort_unique(set.rows);
    return;
  }
  fill_set(ctx, true);
}

void elset(KeywordContext& ctx) { fill_set(ctx, false); }

/// The face number of an `S1`..`S6` field for this element type (a rigid element's or shell's
/// SNEG = 0 and SPOS = 1; CalculiX names a shell's SNEG S1 and its SPOS S2), or nullopt with an
/// error.
std::optional<std::uint8_t> face_of(KeywordContext& ctx, const Field& f, std::int32_t element) {
  const auto& info = model::element_type(ctx.mesh().elements.type[element]);
  const std::string id = normalize_name(f.text);
  if (model::is_rigid(info) || model::is_shell(info)) {
    if (id == "SNEG" || id == "SPOS") return static_cast<std::uint8_t>(id == "SPOS" ? 1 : 0);
    if (model::is_shell(info) && (id == "S1" || id == "S2")) return static_cast<std::uint8_t>(id == "S2" ? 1 : 0);
    ctx.error(f.loc, fmt::format("element {} ({}) is a {} element: its faces are SPOS and SNEG{}, not '{}'",
                                 ctx.mesh().elements.labels[element], info.name,
                                 model::is_rigid(info) ? "rigid" : "shell",
                                 model::is_rigid(info)
                                     ? ""
                                     : fmt::format(" (CalculiX's S2 and S1), its edges E1..E{} (CalculiX's S3..S{})",
                                                   info.edges.size(), info.edges.size() + 2),
                                 f.text));
    return std::nullopt;
  }
  if (id.size() == 2 && id[0] == 'S' && id[1] >= '1' && id[1] <= '6') {
    const int n = id[1] - '1';
    if (n < static_cast<int>(info.faces.size())) return static_cast<std::uint8_t>(n);
    ctx.error(f.loc, fmt::format("element {} ({}) has no face {}: it has S1..S{}",
                                 ctx.mesh().elements.labels[element], info.name, id, info.faces.size()));
    return std::nullopt;
  }
  if (id == "SPOS" || id == "SNEG") {
    ctx.error(f.loc, fmt::format("{} is a shell face; element {} ({}) is a solid", id,
                                 ctx.mesh().elements.labels[element], info.name));
    return std::nullopt;
  }
  ctx.error(f.loc, fmt::format("face identifier '{}' is not valid: expected S1..S{}", f.text, info.faces.size()));
  return std::nullopt;
}

/// The edge of a shell an identifier names: Abaqus's E1..En, or CalculiX's S3..S(n + 2) (its S1 and
/// S2 are the faces); −1 when the element has no such edge (reported); nullopt for any other
/// identifier or element (face_of reports those).
std::optional<int> shell_edge_of(KeywordContext& ctx, const Field& f, std::int32_t element) {
  const auto& info = model::element_type(ctx.mesh().elements.type[element]);
  const std::string id = normalize_name(f.text);
  if (!model::is_shell(info) || id.size() != 2 || (id[0] != 'E' && id[0] != 'S') || id[1] < '1' || id[1] > '9')
    return std::nullopt;
  const int edge = id[1] - (id[0] == 'E' ? '1' : '3');
  if (edge < 0) return std::nullopt;
  if (edge < static_cast<int>(info.edges.size())) return edge;
  ctx.error(f.loc, fmt::format("element {} ({}) has no edge {}: its edges are E1..E{} (CalculiX's S3..S{})",
                               ctx.mesh().elements.labels[element], info.name, id, info.edges.size(),
                               info.edges.size() + 2));
  return -1;
}

// *SURFACE, NAME=, TYPE=ELEMENT|NODE.
void surface(KeywordContext& ctx) {
  const std::string name = ctx.name_value("NAME");
  model::Surface& surf = ctx.mesh().surfaces[name];
  if (surf.name.empty()) {
    surf.name = ctx.param("NAME")->value.value_or(name);
    surf.loc = ctx.keyword.loc;
  }
  const std::string type = ctx.choice_value("TYPE");
  if (type == "SEGMENTS" || type == "CYLINDER" || type == "REVOLUTION") {
    analytical_surface(ctx, surf, type);
    return;
  }
  if (ctx.has("FILLET RADIUS")) {
    ctx.error_param("FILLET RADIUS", "FILLET RADIUS belongs to an analytical surface (TYPE=SEGMENTS, CYLINDER or REVOLUTION)");
    return;
  }
  if (surf.kind == model::Surface::Kind::Analytical) {
    ctx.error(ctx.keyword.loc, fmt::format("surface '{}' is an analytical surface already; it cannot have faces or nodes too", surf.name));
    return;
  }
  surf.kind = type == "NODE" ? model::Surface::Kind::Node : model::Surface::Kind::Element;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (surf.kind == model::Surface::Kind::Node) {
      if (!ctx.check_count(f, line, 1, 2, "node or node set, area")) continue;
      auto rows = ctx.nodes(f[0]);
      double area = 1.0;
      if (f.size() > 1 && !f[1].empty()) {
        auto a = ctx.real(f[1], "area");
        if (!a) continue;
        area = *a;
      }
      if (!rows) continue;
      for (auto r : *rows) {
        surf.nodes.push_back(r);
        surf.node_areas.push_back(area);
      }
      continue;
    }
    if (!ctx.check_count(f, line, 1, 2, "element or element set, face identifier")) continue;
    auto rows = ctx.elements(f[0]);
    if (!rows) continue;
    if (f.size() == 1 || f[1].empty()) {
      const auto two_sided = [&](std::int32_t r) {
        const auto& t = model::element_type(ctx.mesh().elements.type[r]);
        return model::is_rigid(t) || model::is_shell(t);
      };
      if (const auto e = std::find_if(rows->begin(), rows->end(), two_sided); e != rows->end()) {
        ctx.error(f[0].loc, fmt::format("element {} is a {} element: give its face, SPOS or SNEG (a surface on both "
                                        "sides is not supported yet)", ctx.mesh().elements.labels[*e],
                                        model::is_rigid(model::element_type(ctx.mesh().elements.type[*e])) ? "rigid"
                                                                                                           : "shell"));
        continue;
      }
      // No face given: the free faces of these elements.
      resolve_pending_nodes(ctx.state.mesh_build(), ctx.diags);
      auto faces = model::exterior_faces(ctx.mesh().elements, *rows);
      surf.faces.insert(surf.faces.end(), faces.begin(), faces.end());
      continue;
    }
    for (auto e : *rows) {
      if (const auto edge = shell_edge_of(ctx, f[1], e)) {
        if (*edge < 0) break;
        surf.edges.push_back({e, static_cast<std::uint8_t>(*edge)});
        continue;
      }
      auto face = face_of(ctx, f[1], e);
      if (!face) break;
      surf.faces.push_back({e, *face});
    }
    if (!surf.faces.empty() && !surf.edges.empty()) {
      ctx.error(f[1].loc, fmt::format("surface '{}' has element faces and shell edges: a surface is made of one or the "
                                      "other (define two surfaces)", surf.name));
      return;
    }
  }
  if (surf.kind == model::Surface::Kind::Element && surf.faces.empty() && surf.edges.empty() && !ctx.diags.has_errors())
    ctx.error(ctx.keyword.loc, fmt::format("surface '{}' has no faces", surf.name));
  // A surface is a set of faces (Abaqus, CalculiX): a face given twice (two overlapping element
  // sets, an element's free faces and one of them by name) is one face, loaded once.
  std::set<std::pair<std::int32_t, int>> seen;
  std::erase_if(surf.faces, [&](const model::Face& face) { return !seen.insert({face.element, face.face}).second; });
  seen.clear();
  std::erase_if(surf.edges, [&](const model::Face& edge) { return !seen.insert({edge.element, edge.face}).second; });
}

}  // namespace

void add_mesh_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*HEADING", kModelScope, {}, DataLines::Optional, heading});
  t.push_back({"*NODE", kMeshScopes, {{"NSET", ValueKind::Required}, {"SYSTEM", ValueKind::Required, ValueType::Choice, {"R"}}},
               DataLines::Optional, node, {}, true});
  t.back().numbers_from = 4;  // label, x, y, z and the normal read by the handler
  t.push_back({"*ELEMENT", kMeshScopes,
               {{"TYPE", ValueKind::Required, ValueType::Text, {}, true}, {"ELSET", ValueKind::Required}},
               DataLines::Optional, element, {}, true});
  t.push_back({"*NSET", kMeshScopes,
               {{"NSET", ValueKind::Required, ValueType::Text, {}, true}, {"GENERATE"}, {"INTERNAL"},
                {"UNSORTED"}, {"INSTANCE", ValueKind::Required}, {"ELSET", ValueKind::Required}},
               DataLines::Optional, nset, {}, true});
  t.push_back({"*ELSET", kMeshScopes,
               {{"ELSET", ValueKind::Required, ValueType::Text, {}, true}, {"GENERATE"}, {"INTERNAL"},
                {"UNSORTED"}, {"INSTANCE", ValueKind::Required}},
               DataLines::Optional, elset, {}, true});
  t.push_back({"*SURFACE", kMeshScopes,
               {{"NAME", ValueKind::Required, ValueType::Text, {}, true},
                {"TYPE", ValueKind::Required, ValueType::Choice, {"ELEMENT", "NODE", "SEGMENTS", "CYLINDER", "REVOLUTION"}},
                {"FILLET RADIUS", ValueKind::Required, ValueType::Real},
                {"INTERNAL"}},
               DataLines::Required, surface, {}, true});
}

}  // namespace inpact::parser
