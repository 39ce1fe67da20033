/// The step-wise changes of contact (history data): *CHANGE FRICTION (Abaqus/Standard and
/// CalculiX), *CHANGE SURFACE BEHAVIOR (CalculiX) and *MODEL CHANGE (TYPE=CONTACT PAIR, and
/// TYPE=ELEMENT, which it reads too). They are stored in the step (model::Step::friction_changes,
/// behavior_changes, pair_changes, element_changes);
/// contact/step_changes.hpp says what is in force in each step. Sources: [K16 *CHANGE FRICTION,
/// *MODEL CHANGE], [IG ctc_contactpair_std "Removing and Reactivating Contact Pairs"], [CCX]
/// (parser/KEYWORDS.md).
#include <algorithm>

#include <fmt/format.h>

#include "handlers.hpp"
#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser {

namespace contact_kw {

namespace {

/// The interaction named by INTERACTION=, reported at its value when the model data has none.
std::string named_interaction(KeywordContext& ctx) {
  const std::string name = ctx.name_value("INTERACTION");
  const auto& interactions = ctx.model().interactions;
  if (interactions.count(name)) return name;
  std::vector<std::string> names;
  for (const auto& [k, v] : interactions) names.push_back(k);
  const std::string guess = did_you_mean(name, names);
  ctx.error_param("INTERACTION", fmt::format("surface interaction '{}' is not defined{}", name,
                                             guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  return name;
}

}  // namespace

// *CHANGE FRICTION, INTERACTION= [, RESET] [, AMPLITUDE=] [K16]: the *FRICTION that follows
// (kw_surface_interaction.cpp) is the interaction's friction from this step on. RESET: the model
// data's friction again, no *FRICTION. Abaqus moves μ and the allowable elastic slip to their new
// values by the step's amplitude (RAMP for *STATIC) or AMPLITUDE=; other properties change at
// once [K16]. CalculiX reads only INTERACTION and changes at once [CCX], [CCXSRC changefrictions.f].
void change_friction(KeywordContext& ctx) {
  model::Step& step = *ctx.state.step;
  model::FrictionChange c;
  c.interaction = named_interaction(ctx);
  c.loc = ctx.keyword.loc;
  c.interaction_loc = ctx.param_loc("INTERACTION");
  c.reset = ctx.has("RESET");
  reject_param(ctx, "ELSET", "the friction of contact or connector elements; inpact has surface-based contact only");
  if (ctx.has("AMPLITUDE")) {
    c.amplitude = ctx.name_value("AMPLITUDE");
    c.amplitude_loc = ctx.param_loc("AMPLITUDE");  // checked when the deck is complete (finalize.cpp)
    if (c.reset) ctx.error_param("AMPLITUDE", "RESET returns the model data's friction at once; AMPLITUDE does not apply");
  }
  step.friction_changes.push_back(std::move(c));
  ctx.state.friction_change = &step.friction_changes.back();
  ctx.state.open_parent = kChangeFriction;
}

// *CHANGE SURFACE BEHAVIOR, INTERACTION= (CalculiX) [CCX]: the *SURFACE BEHAVIOR that follows is
// the interaction's normal behaviour from this step on. CalculiX's manual states no limit; what
// inpact cannot change within one analysis (the bonding of the TIED law, the number of rows of
// general contact) is refused where the interaction is resolved (contact/resolved_interaction.cpp).
void change_surface_behavior(KeywordContext& ctx) {
  model::Step& step = *ctx.state.step;
  model::SurfaceBehaviorChange c;
  c.interaction = named_interaction(ctx);
  c.loc = ctx.keyword.loc;
  c.interaction_loc = ctx.param_loc("INTERACTION");
  step.behavior_changes.push_back(std::move(c));
  ctx.state.behavior_change = &step.behavior_changes.back();
  ctx.state.open_parent = kChangeSurfaceBehavior;
}

namespace {

/// The *CONTACT PAIR (model data or a step up to this one) with these surfaces, or null.
const model::ContactPair* find_pair(const model::Model& m, const std::string& slave, const std::string& master) {
  auto match = [&](const model::ContactPair& p) { return p.slave == slave && p.master == master; };
  for (const auto& p : m.contact_pairs)
    if (match(p)) return &p;
  for (const auto& s : m.steps)
    for (const auto& p : s.contact_pairs)
      if (match(p)) return &p;
  return nullptr;
}

/// Is the pair removed by the latest *MODEL CHANGE so far (earlier steps, then this one's lines)?
bool removed_so_far(const model::Model& m, const std::string& slave, const std::string& master) {
  bool removed = false;
  for (const auto& s : m.steps)
    for (const auto& c : s.pair_changes)
      if (c.slave == slave && c.master == master) removed = !c.add;
  return removed;
}

/// One `slave, master` line of TYPE=CONTACT PAIR (self-contact: `surf,` or `surf, surf`).
void pair_change_line(KeywordContext& ctx, const Line& line, bool add) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 1, 2, "slave surface, master surface")) return;
  if (f[0].empty()) {
    ctx.error(f[0].loc, "the slave surface name is missing");
    return;
  }
  model::ContactPairChange c;
  c.slave = normalize_label(f[0].text);
  c.master = f.size() == 2 && !f[1].empty() ? normalize_label(f[1].text) : c.slave;
  c.add = add;
  c.loc = f[0].loc;
  const model::ContactPair* pair = find_pair(ctx.model(), c.slave, c.master);
  if (!pair) {
    ctx.error(c.loc, fmt::format("no *CONTACT PAIR has slave '{}' and master '{}' (a pair to remove or reactivate "
                                 "must be defined by *CONTACT PAIR){}",
                                 c.slave, c.master,
                                 ctx.model().general_contact.defined ? "; general contact is not changed this way" : ""));
    return;
  }
  // "You cannot remove tied contact pairs from a simulation" [IG ctc_contactpair_std].
  if (!add && pair->tied) {
    ctx.error(c.loc, fmt::format("the contact pair {}/{} is TIED, and a tied contact pair cannot be removed", c.slave,
                                 c.master));
    return;
  }
  const bool removed = removed_so_far(ctx.model(), c.slave, c.master);
  if (add && !removed)
    ctx.warning(c.loc, fmt::format("the contact pair {}/{} is in force: ADD has nothing to reactivate", c.slave, c.master));
  if (!add && removed)
    ctx.warning(c.loc, fmt::format("the contact pair {}/{} is already removed", c.slave, c.master));
  ctx.state.step->pair_changes.push_back(std::move(c));
}

}  // namespace

// *MODEL CHANGE, TYPE=ELEMENT (the default TYPE), ADD[=STRAIN FREE | WITH STRAIN] | REMOVE: data
// lines of element labels and element sets (model::ElementChange).
void element_change(KeywordContext& ctx, bool add) {
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, "data lines are missing: the elements or element sets to " +
                                   std::string(add ? "reactivate" : "remove"));
    return;
  }
  model::ElementChange c;
  c.add = add;
  c.with_strain = add && ctx.choice_value("ADD") == "WITHSTRAIN";
  c.loc = ctx.keyword.loc;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    for (const Field& field : f) {
      if (field.empty()) continue;
      if (auto rows = ctx.elements(field)) c.elements.insert(c.elements.end(), rows->begin(), rows->end());
    }
  }
  std::sort(c.elements.begin(), c.elements.end());
  c.elements.erase(std::unique(c.elements.begin(), c.elements.end()), c.elements.end());
  ctx.state.step->element_changes.push_back(std::move(c));
}

// *MODEL CHANGE, TYPE=CONTACT PAIR, ADD | REMOVE [K16], [IG], [CCX]: data lines `slave, master`
// name *CONTACT PAIRs (Abaqus: of the model data; inpact also those an earlier step defined).
// REMOVE: the pair is not in force from this step on; the contact forces it carried at the end
// of the previous step are applied as loads that ramp linearly to zero over the step [IG]
// (solver/step_conditions.hpp). ADD: it is in force again from this step on, every slave node
// starting open, with no friction history. TYPE=ELEMENT (the Abaqus default): element_change.
void model_change(KeywordContext& ctx) {
  int n_actions = 0;
  for (const KeywordParam& p : ctx.keyword.params) {
    if (p.name != "ADD" && p.name != "REMOVE" && p.name != "ACTIVATE" && p.name != "MECHSTRAINTORESIDUAL") continue;
    if (++n_actions > 1) {
      ctx.error(p.loc, "ADD, REMOVE and ACTIVATE are mutually exclusive");
      return;
    }
  }
  if (ctx.has("ACTIVATE")) {
    ctx.warning(ctx.param_loc("ACTIVATE"), "ACTIVATE prepares a restart analysis, which inpact does not have; ignored");
    if (!ctx.data.empty()) ctx.error(line_start(ctx.data[0]), "ACTIVATE takes no data lines");
    return;
  }
  reject_param(ctx, "MECHSTRAINTORESIDUAL", "CalculiX's conversion of mechanical strain into residual strain");
  if (ctx.has("MECHSTRAINTORESIDUAL")) return;
  if (n_actions == 0) {
    ctx.error(ctx.keyword.loc, "one of ADD or REMOVE is required");
    return;
  }
  const bool add = ctx.has("ADD");
  if (ctx.choice_value("TYPE") != "CONTACTPAIR") {
    element_change(ctx, add);
    return;
  }
  if (add && ctx.choice_value("ADD") == "WITHSTRAIN")
    ctx.warning(ctx.param_loc("ADD"), "ADD=WITH STRAIN applies to elements, not to contact pairs [K16]; ignored");
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, "data lines are missing: slave surface, master surface");
    return;
  }
  for (const Line& line : ctx.data) pair_change_line(ctx, line, add);
}

}  // namespace contact_kw

void add_step_contact_keywords(std::vector<KeywordSpec>& t) {
  using namespace contact_kw;
  using VK = ValueKind;
  using VT = ValueType;
  // History data [K16]; no data lines: *FRICTION follows. ELSET is Abaqus's for contact and
  // connector elements, listed to be refused clearly.
  t.push_back({"*CHANGE FRICTION", kStepScope,
               {{"INTERACTION", VK::Required, VT::Text, {}, true},
                {"ELSET", VK::Required, VT::Text},
                {"RESET", VK::None},
                {"AMPLITUDE", VK::Required, VT::Text}},
               DataLines::None, change_friction});
  // CalculiX [CCX]: *SURFACE BEHAVIOR follows.
  t.push_back({"*CHANGE SURFACE BEHAVIOR", kStepScope, {{"INTERACTION", VK::Required, VT::Text, {}, true}},
               DataLines::None, change_surface_behavior});
  // History data [K16]; MECHSTRAINTORESIDUAL is CalculiX's [CCX].
  t.push_back({"*MODEL CHANGE", kStepScope,
               {{"TYPE", VK::Required, VT::Choice, {"ELEMENT", "CONTACT PAIR"}},
                {"ADD", VK::Optional, VT::Choice, {"STRAIN FREE", "WITH STRAIN"}},
                {"REMOVE", VK::None},
                {"ACTIVATE", VK::None},
                {"MECHSTRAINTORESIDUAL", VK::None}},
               DataLines::Optional, model_change});
}

}  // namespace inpact::parser
