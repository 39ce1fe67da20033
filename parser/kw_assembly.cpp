/// *PART *END PART *ASSEMBLY *INSTANCE *END INSTANCE *END ASSEMBLY: the form Abaqus/CAE writes.
/// A part is read into a mesh of its own; each instance copies it into the model's mesh with
/// its transform, under a new instance index, and prefixes its set and surface names with
/// "INSTANCE." so that assembly-level data can say `Part-1-1.Set-1`.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "finalize.hpp"
#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

void part(KeywordContext& ctx) {
  const std::string key = ctx.name_value("NAME");
  auto [it, inserted] = ctx.state.parts.try_emplace(key);
  if (!inserted) {
    ctx.error_param("NAME", fmt::format("part '{}' is defined twice", key));
  }
  it->second.name = ctx.param("NAME")->value.value_or(key);
  it->second.loc = ctx.keyword.loc;
  ctx.state.part = &it->second;
  ctx.state.scope = kPartScope;
}

void end_part(KeywordContext& ctx) {
  resolve_pending_nodes(ctx.state.part->build, ctx.diags);
  ctx.state.part = nullptr;
  ctx.state.scope = kModelScope;
}

void assembly(KeywordContext& ctx) {
  if (ctx.state.assembly_seen) ctx.error(ctx.keyword.loc, "only one *ASSEMBLY is allowed");
  ctx.state.assembly_seen = true;
  ctx.state.scope = kAssemblyScope;
}

void end_assembly(KeywordContext& ctx) { ctx.state.scope = kModelScope; }

void instance(KeywordContext& ctx) {
  OpenInstance inst;
  inst.name = ctx.param("NAME")->value.value_or("");
  inst.part = ctx.name_value("PART");
  inst.loc = ctx.keyword.loc;
  std::vector<Field> f;
  if (ctx.data.size() > 2) ctx.error(ctx.data[2].loc, "at most two data lines: translation, then rotation");
  for (std::size_t i = 0; i < std::min<std::size_t>(ctx.data.size(), 2); ++i) {
    split_fields(ctx.data[i], f);
    if (i == 0) {
      if (!ctx.check_count(f, ctx.data[i], 1, 3, "translation x, y, z")) continue;
      for (std::size_t k = 0; k < f.size(); ++k)
        if (!f[k].empty())
          if (auto v = ctx.real(f[k], "translation")) inst.translation[k] = *v;
    } else {
      if (!ctx.check_count(f, ctx.data[i], 7, 7, "axis point a (x, y, z), point b (x, y, z), angle in degrees"))
        continue;
      for (std::size_t k = 0; k < 7; ++k)
        if (auto v = ctx.real(f[k], k < 6 ? "rotation axis point" : "rotation angle")) inst.rotation[k] = *v;
      inst.has_rotation = true;
    }
  }
  auto pit = ctx.state.parts.find(inst.part);
  if (pit == ctx.state.parts.end()) {
    ctx.error_param("PART", fmt::format("part '{}' is not defined (a *PART must come before its instances)", inst.part));
  } else {
    inst.def = pit->second;
  }
  inst.first_rigid_body = ctx.model().rigid_bodies.size();
  inst.first_analytical_surface = ctx.model().analytical_surfaces.size();
  ctx.state.instance = std::move(inst);
  ctx.state.part = &ctx.state.instance->def;
  ctx.state.scope = kInstanceScope;
}

/// Rotates x about the axis through a and b by `degrees` (right-hand rule), Rodrigues' formula.
std::array<double, 3> rotate(const std::array<double, 3>& x, const std::array<double, 7>& r) {
  std::array<double, 3> k{r[3] - r[0], r[4] - r[1], r[5] - r[2]};
  const double len = std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  if (len == 0.0) return x;
  for (double& c : k) c /= len;
  const double th = r[6] * std::numbers::pi / 180.0, c = std::cos(th), s = std::sin(th);
  const std::array<double, 3> v{x[0] - r[0], x[1] - r[1], x[2] - r[2]};
  const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  const std::array<double, 3> kxv{k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = r[i] + v[i] * c + kxv[i] * s + k[i] * kv * (1 - c);
  return out;
}

/// A direction turned as rotate() turns points: the difference of two turned points.
std::array<double, 3> rotate_direction(const std::array<double, 3>& d, const std::array<double, 7>& r) {
  const auto tip = rotate({r[0] + d[0], r[1] + d[1], r[2] + d[2]}, r);
  return {tip[0] - r[0], tip[1] - r[1], tip[2] - r[2]};
}

void move_rigid_bodies(KeywordContext& ctx, const OpenInstance& inst, std::int32_t node_base, std::int32_t elem_base);
void refuse_turned_orientation(KeywordContext& ctx, const OpenInstance& inst, const std::string& orientation);

/// Copies the part's mesh into the model's mesh as a new instance.
void end_instance(KeywordContext& ctx) {
  resolve_pending_nodes(ctx.state.instance->def.build, ctx.diags);
  const OpenInstance inst = std::move(*ctx.state.instance);
  ctx.state.instance.reset();
  ctx.state.part = nullptr;
  ctx.state.scope = kAssemblyScope;
  auto& names = ctx.model().instances;
  const std::string key = normalize_label(inst.name);
  for (const auto& n : names)
    if (normalize_label(n) == key) {
      ctx.diags.error(inst.loc, "*INSTANCE", fmt::format("instance '{}' is defined twice", inst.name));
      return;
    }
  const auto id = static_cast<std::int32_t>(names.size());
  names.push_back(inst.name);

  const model::Mesh& src = inst.def.build.mesh;
  model::Mesh& dst = ctx.state.model_mesh.mesh;
  const auto node_base = static_cast<std::int32_t>(dst.nodes.size());
  const auto elem_base = static_cast<std::int32_t>(dst.elements.size());
  for (std::size_t n = 0; n < src.nodes.size(); ++n) {
    std::array<double, 3> x = src.nodes.coords[n];
    for (int i = 0; i < 3; ++i) x[i] += inst.translation[i];  // translation first, then rotation
    if (inst.has_rotation) x = rotate(x, inst.rotation);
    dst.nodes.index.insert(id, src.nodes.labels[n], static_cast<std::int32_t>(dst.nodes.size()));
    dst.nodes.labels.push_back(src.nodes.labels[n]);
    dst.nodes.coords.push_back(x);
    dst.nodes.instance.push_back(id);
  }
  model::Elements& de = dst.elements;
  const model::Elements& se = src.elements;
  for (std::size_t e = 0; e < se.size(); ++e) {
    de.index.insert(id, se.labels[e], static_cast<std::int32_t>(de.size()));
    de.labels.push_back(se.labels[e]);
    de.type.push_back(se.type[e]);
    de.instance.push_back(id);
    de.loc.push_back(se.loc[e]);
    for (std::int32_t n : se.nodes_of(e)) de.conn.push_back(n < 0 ? n : n + node_base);
    de.offsets.push_back(static_cast<std::int64_t>(de.conn.size()));
  }
  const std::string prefix = key + ".";
  for (const auto& [k, s] : src.nsets) {
    model::Set copy = s;
    copy.name = inst.name + "." + s.name;
    for (auto& r : copy.rows) r += node_base;
    dst.nsets[prefix + k] = std::move(copy);
  }
  for (const auto& [k, s] : src.elsets) {
    model::Set copy = s;
    copy.name = inst.name + "." + s.name;
    for (auto& r : copy.rows) r += elem_base;
    dst.elsets[prefix + k] = std::move(copy);
  }
  for (const auto& [k, s] : src.surfaces) {
    model::Surface copy = s;
    copy.name = inst.name + "." + s.name;
    for (auto& f : copy.faces) f.element += elem_base;
    for (auto& f : copy.edges) f.element += elem_base;
    for (auto& n : copy.nodes) n += node_base;
    dst.surfaces[prefix + k] = std::move(copy);
  }
  for (const auto& sec : src.sections) {
    if (!sec.orientation.empty()) refuse_turned_orientation(ctx, inst, sec.orientation);
    model::SolidSection copy = sec;
    copy.elset = prefix + sec.elset;
    dst.sections.push_back(std::move(copy));
  }
  for (const auto& spring : src.springs) {
    model::SpringSection copy = spring;
    copy.elset = prefix + spring.elset;
    dst.springs.push_back(std::move(copy));
  }
  for (const auto& beam : src.beam_sections) {  // n1 turns with the instance
    model::BeamSection copy = beam;
    copy.elset = prefix + beam.elset;
    if (inst.has_rotation) copy.n1 = rotate_direction(beam.n1, inst.rotation);
    dst.beam_sections.push_back(std::move(copy));
  }
  for (const auto& shell : src.shell_sections) {
    if (!shell.orientation.empty()) refuse_turned_orientation(ctx, inst, shell.orientation);
    for (const model::ShellLayer& layer : shell.layers)
      if (!layer.orientation.empty()) refuse_turned_orientation(ctx, inst, layer.orientation);
    model::ShellSection copy = shell;
    copy.elset = prefix + shell.elset;
    dst.shell_sections.push_back(std::move(copy));
  }
  for (const auto& [node, thickness] : src.nodal_thickness) dst.nodal_thickness[node + node_base] = thickness;
  // Given normals are directions: they turn with the instance.
  auto turned = [&](model::Mesh::GivenNormal n) {
    if (inst.has_rotation) n.direction = rotate_direction(n.direction, inst.rotation);
    return n;
  };
  for (const auto& n : src.normals) {
    dst.normals.push_back(turned(n));
    dst.normals.back().element += elem_base;
  }
  for (const auto& [node, n] : src.node_normals) dst.node_normals[node + node_base] = turned(n);
  move_rigid_bodies(ctx, inst, node_base, elem_base);
}

/// An *ORIENTATION is model-wide and does not move with an instance: a section of a rotated
/// instance that uses one would get the part's axes, not the instance's; a cylindrical one's axis
/// stays where the part has it when the instance is translated.
void refuse_turned_orientation(KeywordContext& ctx, const OpenInstance& inst, const std::string& orientation) {
  const auto found = ctx.model().orientations.find(orientation);
  const bool cylindrical = found != ctx.model().orientations.end() &&
                           found->second.system == model::Orientation::System::Cylindrical;
  const bool moved = inst.translation != std::array<double, 3>{0.0, 0.0, 0.0};
  if (!inst.has_rotation && !(cylindrical && moved)) return;
  ctx.diags.error(inst.loc, "*INSTANCE",
                  fmt::format("instance '{}' is {} and a section in it uses the {}orientation '{}': orientations do not "
                              "move with an instance yet (place this instance {}, or mesh the part where the "
                              "assembly has it)", inst.name, inst.has_rotation ? "rotated" : "translated",
                              cylindrical ? "cylindrical " : "", orientation,
                              inst.has_rotation ? "unrotated" : "untranslated"));
}

/// An analytical surface defined inside the instance, moved with it like its nodes: translated,
/// then turned (the origin as a point, the axes as directions). A SEGMENTS profile lies in the
/// global (x, y) plane: it takes an in-plane translation; a turned one is refused.
void move_analytical_surface(KeywordContext& ctx, const OpenInstance& inst, model::AnalyticalSurface& a) {
  const auto& t = inst.translation;
  if (a.type == model::AnalyticalSurface::Type::Segments) {
    if (inst.has_rotation || t[2] != 0.0) {
      ctx.diags.error(inst.loc, "*INSTANCE",
                      fmt::format("instance '{}' holds the SEGMENTS surface '{}' and is rotated or moved out of its "
                                  "plane: only an in-plane translation of a SEGMENTS profile is supported",
                                  inst.name, a.name));
      return;
    }
    auto shift = [&](std::array<double, 2>& p) { p = {p[0] + t[0], p[1] + t[1]}; };
    shift(a.start);
    for (model::ProfileSegment& s : a.segments) {
      shift(s.end);
      if (s.kind == model::ProfileSegment::Kind::Arc) shift(s.center);
    }
    return;
  }
  for (int i = 0; i < 3; ++i) a.origin[i] += t[i];
  if (!inst.has_rotation) return;
  const auto& r = inst.rotation;
  a.origin = rotate(a.origin, r);
  for (auto& axis : a.axes) axis = rotate_direction(axis, r);
}

/// The rigid bodies and analytical surfaces defined inside the instance (an analytical rigid part
/// as Abaqus/CAE writes it) onto the model's rows and coordinates.
void move_rigid_bodies(KeywordContext& ctx, const OpenInstance& inst, std::int32_t node_base, std::int32_t elem_base) {
  auto& bodies = ctx.model().rigid_bodies;
  for (std::size_t b = inst.first_rigid_body; b < bodies.size(); ++b) {
    model::RigidBody& body = bodies[b];
    body.ref_node += node_base;
    if (body.rot_node >= 0 && !body.rot_node_added) body.rot_node += node_base;
    for (auto& n : body.nodes) n += node_base;
    for (auto& n : body.pinned) n += node_base;
    for (auto& e : body.elements) e += elem_base;
  }
  auto& surfaces = ctx.model().analytical_surfaces;
  for (std::size_t a = inst.first_analytical_surface; a < surfaces.size(); ++a)
    move_analytical_surface(ctx, inst, surfaces[a]);
}

}  // namespace

void add_assembly_keywords(std::vector<KeywordSpec>& t) {
  t.push_back({"*PART", kModelScope, {{"NAME", ValueKind::Required, ValueType::Text, {}, true}}, DataLines::None, part});
  t.push_back({"*END PART", kPartScope, {}, DataLines::None, end_part});
  t.push_back({"*ASSEMBLY", kModelScope, {{"NAME", ValueKind::Required, ValueType::Text, {}, true}}, DataLines::None, assembly});
  t.push_back({"*END ASSEMBLY", kAssemblyScope, {}, DataLines::None, end_assembly});
  t.push_back({"*INSTANCE", kAssemblyScope,
               {{"NAME", ValueKind::Required, ValueType::Text, {}, true},
                {"PART", ValueKind::Required, ValueType::Text, {}, true}},
               DataLines::Optional, instance});
  t.back().numbers_from = 0;
  t.push_back({"*END INSTANCE", kInstanceScope, {}, DataLines::None, end_instance});
}

}  // namespace inpact::parser
