/// *PRE-TENSION SECTION: a bolt load across a cut of a solid fastener [K16 *PRE-TENSION SECTION],
/// [IG Prescribed assembly loads], [CCX]. The split of the mesh is parser/pretension_split.cpp.
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

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

/// ELEMENT=: the one truss element (a label or a set of one) that is the section, or −1.
std::int32_t section_element(KeywordContext& ctx) {
  const KeywordParam* p = ctx.param("ELEMENT");
  auto rows = ctx.elements(Field{*p->value, p->value_loc});
  if (!rows) return -1;
  if (rows->size() != 1) {
    ctx.error(p->value_loc, fmt::format("ELEMENT='{}' holds {} elements; the section must be exactly one truss element",
                                        *p->value, rows->size()));
    return -1;
  }
  return rows->front();
}

// *PRE-TENSION SECTION, SURFACE=name | ELEMENT=, NODE=node or one-node set [, FOLLOWER=NO];
// optional data line n1, n2, n3. A continuum is cut along the surface, a shell along an edge-based
// surface (CalculiX's pret7; Abaqus cuts continua and trusses); a truss (ELEMENT=) at its
// second node, its axis the normal (a data line must say the same: CalculiX's decks give it).
// The normal stays fixed (FOLLOWER=NO, Abaqus's default).
void pretension_section(KeywordContext& ctx) {
  if (ctx.has("ELEMENT") == ctx.has("SURFACE")) {
    ctx.error(ctx.keyword.loc, "give one of SURFACE= (the element-based surface that cuts a solid fastener) and "
                               "ELEMENT= (a truss element)");
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
  s.surface_loc = ctx.param_loc(ctx.has("ELEMENT") ? "ELEMENT" : "SURFACE");
  if (ctx.has("ELEMENT") && (s.element = section_element(ctx)) < 0) return;
  s.node_loc = ctx.param_loc("NODE");
  s.node = ctx.single_node("NODE", "pre-tension node");
  if (s.node < 0 || !read_normal(ctx, s)) return;
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
