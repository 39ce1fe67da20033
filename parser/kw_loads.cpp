/// *BOUNDARY *CLOAD *DLOAD *DSLOAD *TEMPERATURE *INITIAL CONDITIONS: prescribed values and loads.
/// *AMPLITUDE (kw_amplitude.cpp) and *EQUATION (kw_equation.cpp) register with this group.
/// Sources: K16 §2.12 (*BOUNDARY), §4.31 (*DLOAD) and CCX, see KEYWORDS.md.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "handlers.hpp"
#include "model/element_types.hpp"
#include "model/reference_nodes.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

using model::Op;

Op op_of(const KeywordContext& ctx) { return ctx.choice_value("OP") == "NEW" ? Op::New : Op::Mod; }

/// Parameters that select features inpact does not have: each one given is an error.
void reject_params(KeywordContext& ctx, std::initializer_list<std::string_view> names) {
  for (std::string_view p : names)
    if (ctx.has(p)) ctx.error_param(p, fmt::format("{} is not supported yet", p));
}

/// History loads without data lines only make sense as OP=NEW: "remove every earlier load of
/// this kind" (how Abaqus/CAE deactivates loads in later steps).
bool data_or_new(KeywordContext& ctx) {
  if (!ctx.data.empty() || op_of(ctx) == Op::New) return true;
  ctx.error(ctx.keyword.loc, "data lines are missing (without them only OP=NEW, which removes earlier loads, "
                             "makes sense)");
  return false;
}

bool starts_with_letter(std::string_view s) {
  return !s.empty() && std::isalpha(static_cast<unsigned char>(s.front()));
}

// --- *BOUNDARY -------------------------------------------------------------------------------

struct DofRange {
  int first, last;
};

/// The "type" format of *BOUNDARY: zero values on these DOFs [K16 §2.12]; DOF sets from
/// [FEMGV] (secondary source). 1-3 are displacements, 4-6 rotations about x, y, z. inpact's
/// solid and plane elements have DOFs 1-3 only, so the rotational part is recorded but
/// constrains nothing.
struct BoundaryType {
  std::string_view name;
  std::vector<DofRange> dofs;
};
const std::vector<BoundaryType>& boundary_types() {
  static const std::vector<BoundaryType> types{
      {"XSYMM", {{1, 1}, {5, 6}}},          // symmetry about a plane x = const: u1 = ur2 = ur3 = 0
      {"YSYMM", {{2, 2}, {4, 4}, {6, 6}}},  // y = const: u2 = ur1 = ur3 = 0
      {"ZSYMM", {{3, 5}}},                  // z = const: u3 = ur1 = ur2 = 0
      {"XASYMM", {{2, 4}}},                 // antisymmetry about x = const: u2 = u3 = ur1 = 0
      {"YASYMM", {{1, 1}, {3, 3}, {5, 5}}}, // y = const: u1 = u3 = ur2 = 0
      {"ZASYMM", {{1, 2}, {6, 6}}},         // z = const: u1 = u2 = ur3 = 0
      {"PINNED", {{1, 3}}},                 // all displacements: u1 = u2 = u3 = 0
      {"ENCASTRE", {{1, 6}}}};              // fully built in: every displacement and rotation
  return types;
}

/// One data line of *BOUNDARY into entries: `node|set, first[, last[, value]]` or `node|set, TYPE`.
void boundary_line(KeywordContext& ctx, const Line& line, bool fixed, std::vector<model::BoundaryEntry>& out) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 2, 4, "node or node set, first DOF[, last DOF[, value]] or node or node set, type"))
    return;
  auto nodes = ctx.nodes(f[0]);
  model::BoundaryEntry e;
  e.target = std::string(f[0].text);
  e.loc = line.loc;
  if (starts_with_letter(f[1].text)) {
    const std::string type = normalize_name(f[1].text);
    const auto& types = boundary_types();
    auto it = std::find_if(types.begin(), types.end(), [&](const BoundaryType& t) { return t.name == type; });
    if (it == types.end()) {
      std::vector<std::string> names;
      for (const auto& t : types) names.emplace_back(t.name);
      const std::string guess = did_you_mean(type, names);
      ctx.error(f[1].loc, fmt::format("'{}' is not a boundary type{}", f[1].text,
                                      guess.empty() ? " (expected a DOF number or XSYMM, YSYMM, ZSYMM, XASYMM, YASYMM, "
                                                      "ZASYMM, PINNED, ENCASTRE)"
                                                    : fmt::format(" (did you mean {}?)", guess)));
      return;
    }
    if (f.size() > 2) {
      ctx.error(f[2].loc, fmt::format("the boundary type {} takes no further fields", type));
      return;
    }
    if (!nodes) return;
    e.nodes = std::move(*nodes);
    for (const DofRange& r : it->dofs) {
      e.first_dof = r.first;
      e.last_dof = r.last;
      out.push_back(e);
    }
    return;
  }
  auto first = ctx.dof(f[1]);
  auto last = f.size() > 2 && !f[2].empty() ? ctx.dof(f[2]) : first;
  std::optional<double> value = 0.0;
  if (f.size() > 3 && !f[3].empty()) {
    value = ctx.real(f[3], "prescribed value");
    if (fixed && value) ctx.warning(f[3].loc, "the value is ignored: FIXED holds the value at the start of the step");
  }
  if (!nodes || !first || !last || !value) return;
  if (*last < *first) {
    ctx.error(f[2].loc, fmt::format("the last DOF {} is smaller than the first DOF {}", *last, *first));
    return;
  }
  e.nodes = std::move(*nodes);
  e.first_dof = *first;
  e.last_dof = *last;
  e.value = fixed ? 0.0 : *value;
  out.push_back(std::move(e));
}

// *BOUNDARY: model data (no parameters, in force from the first step) or history data with
// OP=MOD|NEW, AMPLITUDE=, TYPE=DISPLACEMENT, FIXED [K16 §2.12].
void boundary(KeywordContext& ctx) {
  const bool history = ctx.state.scope == kStepScope;
  model::BoundaryBlock b;
  b.loc = ctx.keyword.loc;
  if (!history) {
    for (const auto& p : ctx.keyword.params)
      ctx.error(p.loc, fmt::format("{} applies only in a *STEP: model-level *BOUNDARY takes no parameters", p.name));
  } else {
    b.op = op_of(ctx);
    b.amplitude = ctx.name_value("AMPLITUDE");
    b.fixed = ctx.has("FIXED");
    const std::string type = ctx.choice_value("TYPE");
    if (!type.empty() && type != "DISPLACEMENT")
      ctx.error_param("TYPE", fmt::format("TYPE={} is not supported (static steps prescribe displacements)", type));
    if (b.fixed && ctx.has("TYPE")) ctx.error_param("TYPE", "TYPE cannot be used with FIXED");
    reject_params(ctx, {"USER", "SUBMODEL", "PHANTOM"});
    // LOAD CASE is accepted and left unread: only *BUCKLE steps use it, every other procedure
    // ignores it [K16]. Abaqus: the OP parameter must be the same for all *BOUNDARY options within a step.
    for (const auto& other : ctx.state.step->boundaries)
      if (other.op != b.op) {
        ctx.error_param("OP", fmt::format("OP must be the same on every *BOUNDARY of a step (line {} has OP={})",
                                          other.loc.line, other.op == Op::New ? "NEW" : "MOD"));
        break;
      }
  }
  for (const Line& line : ctx.data) boundary_line(ctx, line, b.fixed, b.entries);
  if (b.op == Op::New || !ctx.data.empty())
    (history ? ctx.state.step->boundaries : ctx.model().boundaries).push_back(std::move(b));
}

// --- *CLOAD ----------------------------------------------------------------------------------

// *CLOAD, OP=, AMPLITUDE=: `node|set, dof, magnitude`.
/// Beam and shell nodes get their rotations once the deck is read (rotation_nodes.cpp).
bool has_rotating_elements(const model::Mesh& mesh) {
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (model::has_rotations(model::element_type(mesh.elements.type[e]))) return true;
  return false;
}

void cload(KeywordContext& ctx) {
  if (!data_or_new(ctx)) return;
  reject_params(ctx, {"FOLLOWER", "USER", "ORIENTATION"});
  model::CloadBlock b;
  b.op = op_of(ctx);
  b.amplitude = ctx.name_value("AMPLITUDE");
  b.loc = ctx.keyword.loc;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 3, "node or node set, DOF, magnitude")) continue;
    auto nodes = ctx.nodes(f[0]);
    auto dof = ctx.dof(f[1]);
    auto magnitude = ctx.real(f[2], "magnitude");
    if (!nodes || !dof || !magnitude) continue;
    const bool reference_nodes = std::all_of(nodes->begin(), nodes->end(), [&](std::int32_t n) {
      return model::is_reference_node(ctx.model(), n);
    });
    if (*dof > 3 && !reference_nodes && !has_rotating_elements(ctx.mesh()))
      ctx.warning(f[1].loc, fmt::format("DOF {} is a rotation: inpact's solid and plane elements have none, so "
                                        "this moment acts on nothing", *dof));
    b.entries.push_back({std::string(f[0].text), std::move(*nodes), *dof, *magnitude, f[0].loc});
  }
  ctx.state.step->cloads.push_back(std::move(b));
}

// --- *DLOAD / *DSLOAD ------------------------------------------------------------------------

/// OP, AMPLITUDE and the parameters both distributed-load keywords share.
model::DloadBlock dload_block(KeywordContext& ctx) {
  // Pressure on the deformed face (a follower load) is the Abaqus default; FOLLOWER=NO is not.
  if (ctx.choice_value("FOLLOWER") == "NO") ctx.error_param("FOLLOWER", "FOLLOWER=NO is not supported yet");
  reject_params(ctx, {"CONSTANT RESULTANT", "ORIENTATION", "USER"});
  model::DloadBlock b;
  b.op = op_of(ctx);
  b.amplitude = ctx.name_value("AMPLITUDE");
  b.loc = ctx.keyword.loc;
  return b;
}

/// `Pn` → face n-1 when every element has that face; nullopt (with an error) otherwise.
std::optional<std::uint8_t> pressure_face(KeywordContext& ctx, const Field& label, int n,
                                          const std::vector<std::int32_t>& elements) {
  const auto& el = ctx.mesh().elements;
  for (std::int32_t e : elements) {
    const auto& info = model::element_type(el.type[e]);
    if (model::is_shell(info)) {
      ctx.error(label.loc, fmt::format("element {} ({}) is a shell: its pressure label is P (acting along the "
                                       "positive normal)", el.labels[e], info.name));
      return std::nullopt;
    }
    if (n > static_cast<int>(info.faces.size())) {
      ctx.error(label.loc, fmt::format("element {} ({}) has no face {}: its pressure labels are P1..P{}", el.labels[e],
                                       info.name, n, info.faces.size()));
      return std::nullopt;
    }
  }
  return static_cast<std::uint8_t>(n - 1);
}

/// The shell edge tractions by label stem: EDNOR, EDSHR, EDT (model::EdgeTraction).
std::optional<model::EdgeTraction> edge_traction_of(std::string_view stem) {
  if (stem == "EDNOR") return model::EdgeTraction::Normal;
  if (stem == "EDSHR") return model::EdgeTraction::Shear;
  if (stem == "EDT") return model::EdgeTraction::Transverse;
  return std::nullopt;
}

/// `EDNORn`, `EDSHRn`, `EDTn` → the traction and edge n − 1 when every element is a shell with that
/// edge; nullopt when the label is none of them; −1 for the edge when an error was reported.
std::optional<std::pair<model::EdgeTraction, int>> edge_load_label(KeywordContext& ctx, const Field& label_field,
                                                                    const std::string& label,
                                                                    const std::vector<std::int32_t>& elements) {
  const std::size_t digits = label.find_first_of("0123456789");
  if (digits == std::string::npos || digits + 1 != label.size()) return std::nullopt;
  const auto traction = edge_traction_of(std::string_view(label).substr(0, digits));
  if (!traction) return std::nullopt;
  const int edge = label[digits] - '1';
  const auto& el = ctx.mesh().elements;
  if (edge < 0) {
    ctx.error(label_field.loc, fmt::format("{} names no edge: a shell's edges are numbered from 1", label));
    return std::pair{*traction, -1};
  }
  for (std::int32_t e : elements) {
    const auto& info = model::element_type(el.type[static_cast<std::size_t>(e)]);
    if (!model::is_shell(info)) {
      ctx.error(label_field.loc, fmt::format("{} is a load on a shell's edge; element {} ({}) is not a shell", label,
                                             el.labels[static_cast<std::size_t>(e)], info.name));
      return std::pair{*traction, -1};
    }
    if (edge >= static_cast<int>(info.edges.size())) {
      const std::string stem = label.substr(0, digits);
      ctx.error(label_field.loc, fmt::format("element {} ({}) has no edge {}: expected {}1..{}{}", el.labels[e],
                                             info.name, label[digits], stem, stem, info.edges.size()));
      return std::pair{*traction, -1};
    }
  }
  return std::pair{*traction, edge};
}

/// Fields f[first..first+2] as a vector into `out`; false (errors given) when one is not a number.
bool read_vector(KeywordContext& ctx, const std::vector<Field>& f, std::size_t first, const char* what,
                 std::array<double, 3>& out) {
  bool ok = true;
  for (std::size_t i = 0; i < 3; ++i) {
    auto v = ctx.real(f[first + i], what);
    if (v) out[i] = *v;
    else ok = false;
  }
  return ok;
}

/// Scales `v` to unit length; false (an error at `at`) for the zero vector.
bool normalize(KeywordContext& ctx, const Field& at, const char* what, std::array<double, 3>& v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (length == 0) {
    ctx.error(at.loc, fmt::format("the {} is the zero vector", what));
    return false;
  }
  for (double& c : v) c /= length;
  return true;
}

/// An axisymmetric model can only spin about its symmetry axis, the global y-axis through the
/// origin (r = x): any other axis would not be axisymmetric.
bool centrifugal_axis_fits(KeywordContext& ctx, const Field& at, const model::DloadEntry& e,
                           const std::vector<std::int32_t>& elements) {
  const auto& el = ctx.mesh().elements;
  const bool axisymmetric = std::any_of(elements.begin(), elements.end(), [&](std::int32_t row) {
    return model::element_type(el.type[row]).family == model::ElementFamily::Axisymmetric;
  });
  const bool y_axis = e.point[0] == 0.0 && e.point[2] == 0.0 && e.direction[0] == 0.0 && e.direction[2] == 0.0;
  if (!axisymmetric || y_axis) return true;
  ctx.error(at.loc, "axisymmetric elements rotate about the symmetry axis: the axis must be the global y-axis "
                    "(point 0, y, 0 and direction 0, 1, 0)");
  return false;
}

/// The axis of CENTRIF and ROTA: `element|elset, LABEL, magnitude, x0, y0, z0, n1, n2, n3`.
bool read_rotation_axis(KeywordContext& ctx, const std::vector<Field>& f, const Line& line, const char* what,
                        model::DloadEntry& e) {
  const std::string expected =
      fmt::format("element or element set, {}, axis point x, y, z, axis direction x, y, z", what);
  return ctx.check_count(f, line, 9, 9, expected.c_str()) && read_vector(ctx, f, 3, "rotation axis point", e.point) &&
         read_vector(ctx, f, 6, "rotation axis direction", e.direction) &&
         normalize(ctx, f[6], "rotation axis direction", e.direction);
}

/// A rotary acceleration keeps a plane model in its plane only about an axis normal to it, and
/// an axisymmetric model has no circumferential displacement to carry it (Abaqus: ROTA is for
/// two- and three-dimensional models).
bool rotary_axis_fits(KeywordContext& ctx, const Field& at, const model::DloadEntry& e,
                      const std::vector<std::int32_t>& elements) {
  const auto& el = ctx.mesh().elements;
  bool axisymmetric = false, planar = false;
  for (std::int32_t row : elements) {
    const auto& type = model::element_type(el.type[row]);
    axisymmetric |= type.family == model::ElementFamily::Axisymmetric;
    planar |= type.dim == 2 && type.family != model::ElementFamily::Axisymmetric;
  }
  if (axisymmetric) {
    ctx.error(at.loc, "ROTA is not available for axisymmetric elements (they carry no circumferential displacement)");
    return false;
  }
  if (planar && (e.direction[0] != 0.0 || e.direction[1] != 0.0)) {
    ctx.error(at.loc, "on plane elements the axis of ROTA must be normal to the plane (direction 0, 0, 1)");
    return false;
  }
  return true;
}

std::vector<std::int32_t> all_elements(KeywordContext& ctx) {
  std::vector<std::int32_t> rows(ctx.mesh().elements.size());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = static_cast<std::int32_t>(r);
  return rows;
}

// *DLOAD, OP=, AMPLITUDE=: `element|elset, Pn, p` (pressure on face n, positive into the
// element), `element|elset, GRAV, g, n1, n2, n3` (gravity: g along the direction n, which is
// normalised; needs *DENSITY), `element|elset, CENTRIF, ω², x0, y0, z0, n1, n2, n3` (the
// centrifugal force ρ ω² r of a rotation about the axis through x0 along n; needs *DENSITY),
// `element|elset, ROTA, α, x0, y0, z0, n1, n2, n3` (the rotary acceleration α about that axis;
// its d'Alembert force −ρ α n × r; needs *DENSITY), `element|elset, BX|BY|BZ, b` (force per unit
// volume), `element|elset, EDNORn|EDSHRn|EDTn, q` (a traction per unit length on edge n of shells,
// model::EdgeTraction). GRAV with the element field empty loads every element of the model.
void dload(KeywordContext& ctx) {
  if (!data_or_new(ctx)) return;
  model::DloadBlock b = dload_block(ctx);
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 9, "element or element set, load type, magnitude[, direction or axis]")) continue;
    const std::string label = normalize_name(f[1].text);
    // GRAV without an element set loads the whole model (Abaqus/CAE writes `, GRAV, g, n1, n2, n3`).
    auto elements = f[0].empty() && label == "GRAV" ? std::optional(all_elements(ctx)) : ctx.elements(f[0]);
    auto magnitude = ctx.real(f[2], "magnitude");
    if (!elements || !magnitude) continue;
    model::DloadEntry e;
    e.target = std::string(f[0].text);
    e.magnitude = *magnitude;
    e.loc = f[0].loc;
    const bool face_label = label.size() == 2 && label[0] == 'P' && label[1] >= '1' && label[1] <= '9';
    if (label == "P") {
      // A shell's positive pressure acts along its positive normal (Abaqus: "the force vector points
      // along the element SPOS normal"; CalculiX alike): a pressure on face SNEG (S1). A *DSLOAD on
      // an SPOS surface pushes the other way, against that surface's normal.
      const auto not_shell = std::find_if(elements->begin(), elements->end(), [&](std::int32_t r) {
        return !model::is_shell(model::element_type(ctx.mesh().elements.type[static_cast<std::size_t>(r)]));
      });
      if (not_shell != elements->end()) {
        ctx.error(f[1].loc, fmt::format("P (without a face number) is for shells: element {} is not one; on solid and "
                                        "plane elements give the face, P1, P2, ...",
                                        ctx.mesh().elements.labels[static_cast<std::size_t>(*not_shell)]));
        continue;
      }
      e.kind = model::DloadEntry::Kind::Pressure;
      e.faces.assign(elements->size(), 0);
    } else if (const auto edge_load = edge_load_label(ctx, f[1], label, *elements)) {
      if (edge_load->second < 0) continue;
      if (!ctx.check_count(f, line, 3, 3, "element or element set, edge load type, force per unit length")) continue;
      e.kind = model::DloadEntry::Kind::EdgeLoad;
      e.edge_traction = edge_load->first;
      e.faces.assign(elements->size(), static_cast<std::uint8_t>(edge_load->second));
    } else if (face_label) {
      auto face = pressure_face(ctx, f[1], label[1] - '0', *elements);
      if (!face) continue;
      e.kind = model::DloadEntry::Kind::Pressure;
      e.faces.assign(elements->size(), *face);
    } else if (label == "GRAV") {
      // (a 2D model's direction may stop at y, as Abaqus/CAE writes it)
      if (!ctx.check_count(f, line, 5, 6, "element or element set, GRAV, magnitude, direction x, y[, z]")) continue;
      if (f.size() == 5) f.push_back(Field{"0", f[4].loc});
      if (!read_vector(ctx, f, 3, "gravity direction", e.direction) || !normalize(ctx, f[3], "gravity direction", e.direction))
        continue;
      e.kind = model::DloadEntry::Kind::Gravity;
    } else if (label == "CENTRIF") {
      if (!read_rotation_axis(ctx, f, line, "CENTRIF, omega squared", e)) continue;
      if (!centrifugal_axis_fits(ctx, f[6], e, *elements)) continue;
      e.kind = model::DloadEntry::Kind::Centrifugal;
    } else if (label == "ROTA") {
      if (!read_rotation_axis(ctx, f, line, "ROTA, rotary acceleration", e)) continue;
      if (!rotary_axis_fits(ctx, f[6], e, *elements)) continue;
      e.kind = model::DloadEntry::Kind::RotaryAcceleration;
    } else if (label == "BX" || label == "BY" || label == "BZ") {
      if (!ctx.check_count(f, line, 3, 3, "element or element set, BX|BY|BZ, magnitude")) continue;
      e.kind = model::DloadEntry::Kind::BodyForce;
      e.direction[label[1] - 'X'] = 1.0;
    } else {
      std::vector<std::string> names{"GRAV", "CENTRIF", "ROTA", "BX", "BY", "BZ", "P1", "P2", "P3", "P4", "P5", "P6",
                                     "EDNOR1", "EDSHR1", "EDT1"};
      const std::string guess = did_you_mean(label, names);
      ctx.error(f[1].loc, fmt::format("load type '{}' is not supported (inpact supports Pn, GRAV, CENTRIF, ROTA, BX, BY, BZ, "
                                      "and on shell edges EDNORn, EDSHRn, EDTn){}",
                                      f[1].text, guess.empty() ? "" : fmt::format("; did you mean {}?", guess)));
      continue;
    }
    e.elements = std::move(*elements);
    b.entries.push_back(std::move(e));
  }
  ctx.state.step->dloads.push_back(std::move(b));
}

// *DSLOAD, OP=, AMPLITUDE=: `surface, P, p` — a pressure on the faces of an element-based
// surface, stored like *DLOAD Pn with one face per element; `surface, EDNOR|EDSHR|EDT, q` — a
// traction per unit length on the shell edges of an edge-based surface, stored like EDNORn.
void dsload(KeywordContext& ctx) {
  if (!data_or_new(ctx)) return;
  model::DloadBlock b = dload_block(ctx);
  b.surface_load = true;
  std::vector<Field> f;
  const auto& surfaces = ctx.mesh().surfaces;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 3, "surface, load type, magnitude")) continue;
    auto magnitude = ctx.real(f[2], "magnitude");
    const std::string label = normalize_name(f[1].text);
    const auto edge_traction = edge_traction_of(label);
    if (label != "P" && !edge_traction) {
      ctx.error(f[1].loc, fmt::format("load type '{}' is not supported on *DSLOAD (P, a pressure on faces; EDNOR, EDSHR, "
                                      "EDT, a traction on shell edges)", f[1].text));
      continue;
    }
    const std::string key = normalize_label(f[0].text);
    auto it = surfaces.find(key);
    if (it == surfaces.end()) {
      std::vector<std::string> names;
      for (const auto& [k, s] : surfaces) names.push_back(k);
      const std::string guess = did_you_mean(key, names);
      ctx.error(f[0].loc, fmt::format("surface '{}' is not defined{}", f[0].text,
                                      guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
      continue;
    }
    if (it->second.kind != model::Surface::Kind::Element) {
      ctx.error(f[0].loc, fmt::format("surface '{}' is node-based: {} needs {}", f[0].text, label,
                                      edge_traction ? "shell edges (E1, E2, ...)" : "element faces"));
      continue;
    }
    const auto& loaded = edge_traction ? it->second.edges : it->second.faces;
    if (loaded.empty()) {
      ctx.error(f[1].loc, fmt::format("surface '{}' is made of {}: {} loads {}", f[0].text,
                                      edge_traction ? "element faces" : "shell edges", label,
                                      edge_traction ? "shell edges (E1, E2, ...)" : "element faces"));
      continue;
    }
    if (!magnitude) continue;
    model::DloadEntry e;
    e.kind = edge_traction ? model::DloadEntry::Kind::EdgeLoad : model::DloadEntry::Kind::Pressure;
    if (edge_traction) e.edge_traction = *edge_traction;
    e.target = std::string(f[0].text);
    e.magnitude = *magnitude;
    e.loc = f[0].loc;
    for (const model::Face& face : loaded) {
      e.elements.push_back(face.element);
      e.faces.push_back(face.face);
    }
    b.entries.push_back(std::move(e));
  }
  ctx.state.step->dloads.push_back(std::move(b));
}

// --- temperatures ----------------------------------------------------------------------------

/// `node|set, T[, ∂T/∂n]` lines: the third field is the gradient through a shell's thickness
/// (Abaqus's TEMPERATURE=GRADIENTS, the shell section's default; CalculiX alike). A beam's two
/// gradients are not read.
std::vector<model::TemperatureEntry> temperature_lines(KeywordContext& ctx) {
  std::vector<model::TemperatureEntry> out;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 3, "node or node set, temperature[, gradient through a shell's thickness]"))
      continue;
    auto nodes = ctx.nodes(f[0]);
    auto t = ctx.real(f[1], "temperature");
    std::optional<double> gradient;
    if (f.size() > 2 && !f[2].empty()) {
      gradient = ctx.real(f[2], "temperature gradient");
      if (!gradient) continue;
    }
    if (nodes && t) out.push_back({std::string(f[0].text), std::move(*nodes), *t, gradient, line.loc});
  }
  return out;
}

// *TEMPERATURE, OP=, AMPLITUDE=: prescribed nodal temperatures in a step.
void temperature(KeywordContext& ctx) {
  if (!data_or_new(ctx)) return;
  reject_params(ctx, {"USER", "FILE", "BSTEP", "BINC", "ESTEP", "EINC", "INPUT", "MIDSIDE", "INTERPOLATE"});
  model::TemperatureBlock b;
  b.op = op_of(ctx);
  b.amplitude = ctx.name_value("AMPLITUDE");
  b.loc = ctx.keyword.loc;
  b.entries = temperature_lines(ctx);
  ctx.state.step->temperatures.push_back(std::move(b));
}

// TYPE=PLASTIC STRAIN lines: element or element set, integration point (empty: every point),
// then the plastic strain components in the order of the stress components (3D: 11 22 33 12
// 13 23, 2D: 11 22 33 12), missing ones zero. The field layout (element, point, components) is
// CalculiX's and, from memory, Abaqus's for continuum elements without section points.
void initial_plastic_strain_lines(KeywordContext& ctx) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 3, 8, "element or element set, integration point, plastic strain components"))
      continue;
    model::InitialPlasticStrain e;
    auto rows = ctx.elements(f[0]);
    if (!rows) continue;
    e.target = std::string(f[0].text);
    e.elements = std::move(*rows);
    if (!f[1].empty()) {
      auto ip = ctx.integer(f[1], "integration point");
      if (!ip) continue;
      if (*ip < 1) {
        ctx.error(f[1].loc, fmt::format("the integration point number must be positive, found {}", *ip));
        continue;
      }
      e.point = static_cast<int>(*ip);
    }
    bool ok = true;
    for (std::size_t k = 2; k < f.size() && ok; ++k) {
      if (f[k].empty()) continue;
      auto v = ctx.real(f[k], "plastic strain component");
      if (v) e.components[k - 2] = *v;
      ok = v.has_value();
    }
    e.loc = line.loc;
    if (ok) ctx.model().initial_plastic_strains.push_back(std::move(e));
  }
}

// *INITIAL CONDITIONS, TYPE=TEMPERATURE: the temperatures at the start of the analysis;
// TYPE=PLASTIC STRAIN: the plastic strains of integration points.
void initial_conditions(KeywordContext& ctx) {
  const std::string type = ctx.choice_value("TYPE");
  if (type == "PLASTICSTRAIN" || type == "PLASTIC STRAIN") {
    reject_params(ctx, {"USER", "FILE", "STEP", "INC", "INPUT"});
    initial_plastic_strain_lines(ctx);
    return;
  }
  if (type != "TEMPERATURE") {
    ctx.error_param("TYPE", fmt::format("TYPE={} is not supported yet (only TEMPERATURE and PLASTIC STRAIN)",
                                        ctx.param("TYPE")->value.value_or("")));
    return;
  }
  reject_params(ctx, {"USER", "FILE", "STEP", "INC", "INPUT"});
  auto entries = temperature_lines(ctx);
  auto& dst = ctx.model().initial_temperatures;
  dst.insert(dst.end(), std::make_move_iterator(entries.begin()), std::make_move_iterator(entries.end()));
}

}  // namespace

void add_load_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  const ParamSpec op{"OP", VK::Required, VT::Choice, {"MOD", "NEW"}};
  const ParamSpec amp{"AMPLITUDE", VK::Required};
  t.push_back({"*BOUNDARY", kModelDataScopes | kStepScope,
               {op, amp, {"TYPE", VK::Required, VT::Choice, {"DISPLACEMENT", "VELOCITY", "ACCELERATION"}},
                {"FIXED", VK::None}, {"USER", VK::None}, {"LOAD CASE", VK::Required, VT::Int},
                {"SUBMODEL", VK::None}, {"PHANTOM", VK::Required}},
               DataLines::Optional, boundary});
  t.back().numbers_from = 2;  // node or node set, DOF or boundary type
  t.push_back({"*CLOAD", kStepScope,
               {op, amp, {"FOLLOWER", VK::None}, {"USER", VK::None}, {"ORIENTATION", VK::Required}},
               DataLines::Optional, cload});
  t.back().numbers_from = 1;  // node or node set
  const std::vector<ParamSpec> dload_params{op, amp,
                                            {"FOLLOWER", VK::Optional, VT::Choice, {"YES", "NO"}},
                                            {"CONSTANT RESULTANT", VK::Optional, VT::Choice, {"YES", "NO"}},
                                            {"ORIENTATION", VK::Required},
                                            {"USER", VK::None}};
  t.push_back({"*DLOAD", kStepScope, dload_params, DataLines::Optional, dload});
  t.back().numbers_from = 2;  // element or element set, load type
  t.push_back({"*DSLOAD", kStepScope, dload_params, DataLines::Optional, dsload});
  t.back().numbers_from = 2;  // surface, load type
  t.push_back({"*TEMPERATURE", kStepScope,
               {op, amp, {"USER", VK::None}, {"FILE", VK::Required}, {"BSTEP", VK::Required, VT::Int},
                {"BINC", VK::Required, VT::Int}, {"ESTEP", VK::Required, VT::Int}, {"EINC", VK::Required, VT::Int},
                {"INPUT", VK::Required}, {"MIDSIDE", VK::None}, {"INTERPOLATE", VK::None}},
               DataLines::Optional, temperature});
  t.back().numbers_from = 1;  // node or node set
  t.push_back({"*INITIAL CONDITIONS", kModelDataScopes,
               {{"TYPE", VK::Required, VT::Choice,
                 {"TEMPERATURE", "STRESS", "VELOCITY", "FIELD", "PLASTIC STRAIN", "HARDENING", "SOLUTION", "RATIO",
                  "PORE PRESSURE", "SATURATION", "CONTACT", "ROTATING VELOCITY", "INITIAL GAP", "DISPLACEMENT",
                  "FLUID PRESSURE", "MASS FLOW RATE", "CONCENTRATION", "SPECIFIC ENERGY", "DENSITY"},
                 true},
                {"USER", VK::None}, {"FILE", VK::Required}, {"STEP", VK::Required, VT::Int},
                {"INC", VK::Required, VT::Int}, {"INPUT", VK::Required}},
               DataLines::Required, initial_conditions});
  t.back().numbers_from = 1;  // node or node set (TEMPERATURE), element or element set (PLASTIC STRAIN)
  add_amplitude_keywords(t);
  add_equation_keywords(t);
}

}  // namespace inpact::parser
