/// *COUPLING and the *KINEMATIC or *DISTRIBUTING that follows it [K16 *COUPLING, *KINEMATIC,
/// *DISTRIBUTING], [CCX *COUPLING]. The surface is resolved on the complete deck
/// (couplings.cpp).
#include <fmt/format.h>

#include "handlers.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace {

constexpr std::string_view kCoupling = "*COUPLING";

// *COUPLING, CONSTRAINT NAME=, REF NODE=, SURFACE= [, INFLUENCE RADIUS=, ORIENTATION=]: the
// ORIENTATION's local axes at each coupling node are those of a kinematic coupling's DOFs.
void coupling(KeywordContext& ctx) {
  model::Coupling c;
  c.name = ctx.name_value("CONSTRAINT NAME");
  c.loc = ctx.keyword.loc;
  c.surface = ctx.name_value("SURFACE");
  c.surface_loc = ctx.param_loc("SURFACE");
  c.ref_loc = ctx.param_loc("REF NODE");
  c.ref_node = ctx.single_node("REF NODE", "reference node");
  // Kept even when wrong, so that its *KINEMATIC or *DISTRIBUTING is read and not reported too.
  ctx.model().couplings.push_back(c);
  ctx.state.open_parent = kCoupling;
  if (ctx.has("ORIENTATION")) {
    ctx.model().couplings.back().orientation = ctx.name_value("ORIENTATION");
    ctx.model().couplings.back().orientation_loc = ctx.param_loc("ORIENTATION");
  }
  if (ctx.has("INFLUENCE RADIUS")) {
    const double radius = ctx.real_value("INFLUENCE RADIUS").value_or(0.0);
    if (radius > 0) ctx.model().couplings.back().influence_radius = radius;
    else ctx.error_param("INFLUENCE RADIUS", "the influence radius must be positive");
  }
}

/// The DOF lines "first, last" (last blank: first alone) into `dofs`; no line: all six.
/// `first_loc`: where the first DOF is written (the keyword line when there is no line).
bool read_dofs(KeywordContext& ctx, std::array<bool, 6>& dofs, model::SourceLoc& first_loc) {
  first_loc = ctx.keyword.loc;
  if (ctx.data.empty()) return true;
  dofs.fill(false);
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 2, "first DOF, last DOF")) return false;
    if (&line == &ctx.data.front()) first_loc = f[0].loc;
    const auto first = ctx.dof(f[0]);
    const auto last = f.size() > 1 && !f[1].empty() ? ctx.dof(f[1]) : first;
    if (!first || !last) return false;
    if (*last < *first) {
      ctx.error(f[1].loc, fmt::format("the last DOF {} is below the first {}", *last, *first));
      return false;
    }
    for (int d = *first; d <= *last; ++d) dofs[static_cast<std::size_t>(d - 1)] = true;
  }
  return true;
}

/// The open *COUPLING, or null (reported) when it already has its kind.
model::Coupling* open_coupling(KeywordContext& ctx) {
  model::Coupling& c = ctx.model().couplings.back();
  if (c.kind == model::Coupling::Kind::Unset) return &c;
  ctx.error(ctx.keyword.loc, fmt::format("coupling '{}' already has a *KINEMATIC or *DISTRIBUTING", c.name));
  return nullptr;
}

// *KINEMATIC: the coupling nodes' DOFs that follow the reference node's rigid motion.
void kinematic(KeywordContext& ctx) {
  model::Coupling* c = open_coupling(ctx);
  if (!c) return;
  c->kind = model::Coupling::Kind::Kinematic;  // set first: an error below is the only one
  model::SourceLoc first_loc;
  if (!read_dofs(ctx, c->dofs, first_loc)) return;
  if (!c->dofs[0] && !c->dofs[1] && !c->dofs[2])
    ctx.error(first_loc, "only rotations (DOFs 4–6) are coupled, and the coupling nodes of solid and plane elements "
                         "have none; couple a translation (DOFs 1–3)");
}

// *DISTRIBUTING [, WEIGHTING METHOD=UNIFORM|LINEAR|QUADRATIC|CUBIC, COUPLING=CONTINUUM]: the
// reference node's rotations that the coupling nodes' weighted motion defines, besides its
// translations (always coupled).
void distributing(KeywordContext& ctx) {
  model::Coupling* c = open_coupling(ctx);
  if (!c) return;
  c->kind = model::Coupling::Kind::Distributing;  // set first: an error below is the only one
  if (!c->orientation.empty())
    ctx.error(ctx.keyword.loc, "ORIENTATION on the *COUPLING of a *DISTRIBUTING is not supported yet (CalculiX reads "
                               "the reference node's loads in the local system, Abaqus in the global one)");
  if (ctx.has("COUPLING") && ctx.choice_value("COUPLING") != "CONTINUUM") {
    ctx.error_param("COUPLING", "COUPLING=STRUCTURAL (coupling nodes with rotations) is not supported yet: inpact's "
                                "solid and plane nodes have no rotations; use COUPLING=CONTINUUM");
    return;
  }
  const std::string w = ctx.choice_value("WEIGHTING METHOD");
  c->weighting = w == "LINEAR"      ? model::Coupling::Weighting::Linear
                 : w == "QUADRATIC" ? model::Coupling::Weighting::Quadratic
                 : w == "CUBIC"     ? model::Coupling::Weighting::Cubic
                                    : model::Coupling::Weighting::Uniform;
  model::SourceLoc first_loc;
  read_dofs(ctx, c->dofs, first_loc);
  // Only rotations can be released: Abaqus and CalculiX couple every translation whatever the
  // lines say.
  c->dofs[0] = c->dofs[1] = c->dofs[2] = true;
}

/// *DISTRIBUTING COUPLING's data lines "node or node set, weight", kept as written: a set may
/// be defined further down (CalculiX reads it so); couplings.cpp resolves them.
bool read_weighted_lines(KeywordContext& ctx, model::Coupling& c) {
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 2, "node or node set, weight")) return false;
    const auto weight = ctx.real(f[1], "weight");
    if (!weight) return false;
    if (*weight < 0) {
      ctx.error(f[1].loc, fmt::format("the weight {} is negative; expected a weight >= 0", *weight));
      return false;
    }
    c.weighted_lines.push_back({normalize_label(f[0].text), *weight, f[0].loc});
  }
  return true;
}

// *DISTRIBUTING COUPLING, ELSET=: the older, node-based form (Abaqus 6's, CalculiX's). The set's
// one DCOUP3D/DCOUP2D element holds the reference node, whose translations are the nodes'
// weighted mean, as a *COUPLING with *DISTRIBUTING of DOFs 1–3 over a node set. CalculiX couples
// translations only; Abaqus's element carries moments too (not supported: a moment on the
// reference node is a deck error, as on any uncoupled DOF).
void distributing_coupling(KeywordContext& ctx) {
  if (ctx.has("ORIENTATION")) {
    ctx.error_param("ORIENTATION", "ORIENTATION on a *DISTRIBUTING COUPLING is not supported yet");
    return;
  }
  const std::string elset = ctx.name_value("ELSET");
  const auto it = ctx.state.coupling_elements.find(elset);
  if (it == ctx.state.coupling_elements.end() || it->second.size() != 1) {
    ctx.error_param("ELSET", fmt::format("element set '{}' holds {} distributing coupling elements (*ELEMENT, "
                                         "TYPE=DCOUP3D, defined before this keyword); one, whose node is the "
                                         "reference node, was expected",
                                         elset, it == ctx.state.coupling_elements.end() ? 0 : it->second.size()));
    return;
  }
  const BuildState::CouplingElement& e = it->second.front();
  const auto ref = ctx.mesh().nodes.index.find(0, e.node_label);
  if (!ref) {
    ctx.error(e.loc, fmt::format("node {} of distributing coupling element {} is not defined (define it before the "
                                 "*DISTRIBUTING COUPLING)", e.node_label, e.label));
    return;
  }
  model::Coupling c;
  c.name = elset;
  c.kind = model::Coupling::Kind::Distributing;
  c.loc = ctx.keyword.loc;
  c.ref_loc = e.loc;
  c.ref_node = *ref;
  c.dofs = {true, true, true, false, false, false};
  if (read_weighted_lines(ctx, c)) ctx.model().couplings.push_back(std::move(c));
}

}  // namespace

void add_coupling_keywords(std::vector<KeywordSpec>& t) {
  using VK = ValueKind;
  using VT = ValueType;
  const std::vector<std::string_view> parent{kCoupling};
  t.push_back({"*COUPLING", kModelDataScopes,
               {{"CONSTRAINT NAME", VK::Required, VT::Text, {}, true},
                {"REF NODE", VK::Required, VT::Text, {}, true},
                {"SURFACE", VK::Required, VT::Text, {}, true},
                {"INFLUENCE RADIUS", VK::Required, VT::Real},
                {"ORIENTATION", VK::Required, VT::Text}},
               DataLines::None, coupling});
  t.push_back({"*KINEMATIC", kModelDataScopes, {}, DataLines::Optional, kinematic, parent});
  t.push_back({"*DISTRIBUTING", kModelDataScopes,
               {{"WEIGHTING METHOD", VK::Required, VT::Choice, {"UNIFORM", "LINEAR", "QUADRATIC", "CUBIC"}},
                {"COUPLING", VK::Required, VT::Choice, {"CONTINUUM", "STRUCTURAL"}}},
               DataLines::Optional, distributing, parent});
  t.push_back({"*DISTRIBUTING COUPLING", kModelDataScopes,
               {{"ELSET", VK::Required, VT::Text, {}, true}, {"ORIENTATION", VK::Required, VT::Text}},
               DataLines::Required, distributing_coupling});
}

}  // namespace inpact::parser
