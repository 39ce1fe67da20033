/// *PRE-TENSION SECTION: a bolt load across a cut of a solid fastener [K16 *PRE-TENSION SECTION],
/// [IG Prescribed assembly loads], [CCX]. The split of the mesh is parser/pretension_split.cpp.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

/// NODE=: a node label or a node set of exactly one node.
bool read_pretension_node(KeywordContext& ctx, model::PretensionSection& s) {
  const KeywordParam* p = ctx.param("NODE");
  s.node_loc = p->value_loc;
  const Field field{*p->value, p->value_loc};
  auto rows = ctx.nodes(field);
  if (!rows) return false;
  if (rows->size() != 1) {
    ctx.error(p->value_loc, fmt::format("NODE='{}' holds {} nodes; the pre-tension node must be exactly one node",
                                        *p->value, rows->size()));
    return false;
  }
  s.node = rows->front();
  return true;
}

/// The optional data line: the normal's three components (the default is the surface's average
/// normal, computed by the split).
bool read_normal(KeywordContext& ctx, model::PretensionSection& s) {
  if (ctx.data.empty()) return true;
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (ctx.data.size() > 1) {
    ctx.error(ctx.data[1].loc, "takes one data line at most (the normal's three components)");
    return false;
  }
  if (!ctx.check_count(f, ctx.data[0], 3, 3, "the normal's three components n1, n2, n3")) return false;
  std::array<double, 3> n{};
  for (int i = 0; i < 3; ++i) {
    auto v = ctx.real(f[i], "normal component");
    if (!v) return false;
    n[i] = *v;
  }
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
    ctx.error(f[0].loc, "the normal is zero (expected a direction, or no data line for the surface's average normal)");
    return false;
  }
  s.given_normal = n;
  s.normal_loc = f[0].loc;
  return true;
}

// *PRE-TENSION SECTION, SURFACE=name | ELEMENT=, NODE=node or one-node set [, FOLLOWER=NO];
// optional data line n1, n2, n3. Only continuum sections (SURFACE=): inpact has no truss or beam
// elements for ELEMENT=, and the normal stays fixed (FOLLOWER=NO, Abaqus's default).
void pretension_section(KeywordContext& ctx) {
  if (ctx.has("ELEMENT")) {
    ctx.error_param("ELEMENT", "ELEMENT= (a truss or beam pre-tension section) is not supported yet: inpact has no "
                               "truss or beam elements; cut a solid fastener with SURFACE=");
    return;
  }
  if (!ctx.has("SURFACE")) {
    ctx.error(ctx.keyword.loc, "SURFACE= is required (the element-based surface that cuts the fastener)");
    return;
  }
  if (ctx.has("FOLLOWER") && ctx.choice_value("FOLLOWER") != "NO") {
    ctx.error_param("FOLLOWER", "FOLLOWER=YES (a normal that turns with the fastener) is not supported yet; the "
                                "normal is fixed (FOLLOWER=NO)");
    return;
  }
  model::PretensionSection s;
  s.loc = ctx.keyword.loc;
  s.surface = ctx.name_value("SURFACE");
  s.surface_loc = ctx.param_loc("SURFACE");
  if (!read_pretension_node(ctx, s) || !read_normal(ctx, s)) return;
  ctx.model().pretension_sections.push_back(std::move(s));
}

}  // namespace

void add_pretension_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  t.push_back({"*PRE-TENSION SECTION", kModelDataScopes,
               {{"SURFACE", VK::Required, VT::Text},
                {"ELEMENT", VK::Required, VT::Text},
                {"NODE", VK::Required, VT::Text, {}, true},
                {"FOLLOWER", VK::Optional, VT::Choice, {"YES", "NO"}}},
               DataLines::Optional, pretension_section});
}

}  // namespace inpact::parser
