/// *RIGID BODY: a set of nodes or elements that moves with a reference node [K16 *RIGID BODY],
/// [CCX *RIGID BODY]. The checks against the whole mesh and the rotation node inpact adds for
/// an Abaqus deck are in rigid_bodies.cpp (they need the complete deck).
#include <algorithm>

#include <fmt/format.h>

#include "handlers.hpp"

namespace inpact::parser {

namespace {

/// The nodes of a node-set parameter (TIE NSET, PIN NSET, NSET) added to `nodes`.
bool add_set_nodes(KeywordContext& ctx, std::string_view param, std::vector<std::int32_t>& nodes) {
  const KeywordParam* p = ctx.param(param);
  if (!p) return true;
  auto rows = ctx.nodes(Field{*p->value, p->value_loc});
  if (!rows) return false;
  nodes.insert(nodes.end(), rows->begin(), rows->end());
  return true;
}

/// ANALYTICAL SURFACE=: the analytical surface's index, −1 after an error (not one, or carried
/// by another body already).
std::int32_t analytical_surface_index(KeywordContext& ctx) {
  const std::string name = ctx.name_value("ANALYTICAL SURFACE");
  const auto it = ctx.mesh().surfaces.find(name);
  if (it == ctx.mesh().surfaces.end() || it->second.kind != model::Surface::Kind::Analytical) {
    ctx.error_param("ANALYTICAL SURFACE", fmt::format("'{}' is not an analytical surface: define it before the *RIGID "
                                                      "BODY with *SURFACE, TYPE=SEGMENTS, CYLINDER or REVOLUTION",
                                                      ctx.param("ANALYTICAL SURFACE")->value.value_or(name)));
    return -1;
  }
  const std::int32_t index = it->second.analytical;
  for (const model::RigidBody& other : ctx.model().rigid_bodies)
    if (other.analytical_surface == index) {
      ctx.error_param("ANALYTICAL SURFACE", fmt::format("surface '{}' is carried by another *RIGID BODY already", it->second.name));
      return -1;
    }
  return index;
}

// *RIGID BODY, REF NODE=, ELSET= | TIE NSET= | PIN NSET= [, ROT NODE=, NSET= (CalculiX)].
// The nodes of TIE NSET and PIN NSET both follow the body in translation; tied nodes with
// rotations (beam and shell nodes) turn with it too, pinned ones keep their own. CalculiX's NSET
// is a TIE NSET, and its ROT NODE holds the rotations (in its translations) instead of the
// reference node's 4–6.
void rigid_body(KeywordContext& ctx) {
  for (std::string_view p : {"ISOTHERMAL", "POSITION", "DENSITY"})
    if (ctx.has(p)) {
      ctx.error_param(p, fmt::format("{} is not supported yet", p));
      return;
    }
  model::RigidBody b;
  b.loc = ctx.keyword.loc;
  b.ref_loc = ctx.param_loc("REF NODE");
  b.ref_node = ctx.single_node("REF NODE", "reference node");
  if (b.ref_node < 0) return;
  if (ctx.has("ROT NODE") && (b.rot_node = ctx.single_node("ROT NODE", "rotation node")) < 0) return;
  if (b.rot_node == b.ref_node) {
    ctx.error_param("ROT NODE", "the rotation node must not be the reference node");
    return;
  }
  if (!add_set_nodes(ctx, "TIE NSET", b.nodes) || !add_set_nodes(ctx, "PIN NSET", b.pinned) ||
      !add_set_nodes(ctx, "NSET", b.nodes))
    return;
  b.nodes.insert(b.nodes.end(), b.pinned.begin(), b.pinned.end());
  std::sort(b.pinned.begin(), b.pinned.end());
  if (const KeywordParam* p = ctx.param("ELSET")) {
    auto rows = ctx.elements(Field{*p->value, p->value_loc});
    if (!rows) return;
    b.elements = std::move(*rows);
  }
  if (ctx.has("ANALYTICAL SURFACE") && (b.analytical_surface = analytical_surface_index(ctx)) < 0) return;
  if (b.nodes.empty() && b.elements.empty() && b.analytical_surface < 0) {
    ctx.error(ctx.keyword.loc, "the rigid body has no nodes: give ELSET=, TIE NSET=, PIN NSET= (NSET= in CalculiX) or "
                               "ANALYTICAL SURFACE=");
    return;
  }
  std::sort(b.elements.begin(), b.elements.end());
  b.elements.erase(std::unique(b.elements.begin(), b.elements.end()), b.elements.end());
  ctx.model().rigid_bodies.push_back(std::move(b));
}

}  // namespace

void add_rigid_body_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  // In an *INSTANCE too: Abaqus/CAE writes an analytical rigid part's body there, beside its
  // reference point and surface (names resolve in the instance as for its sets).
  t.push_back({"*RIGID BODY", kModelDataScopes | kInstanceScope,
               {{"REF NODE", VK::Required, VT::Text, {}, true},
                {"ROT NODE", VK::Required, VT::Text},
                {"ELSET", VK::Required, VT::Text},
                {"TIE NSET", VK::Required, VT::Text},
                {"PIN NSET", VK::Required, VT::Text},
                {"NSET", VK::Required, VT::Text},
                {"ANALYTICAL SURFACE", VK::Required, VT::Text},
                {"ISOTHERMAL", VK::Optional, VT::Text},
                {"POSITION", VK::Required, VT::Text},
                {"DENSITY", VK::Required, VT::Text}},
               DataLines::None, rigid_body});
}

}  // namespace inpact::parser
