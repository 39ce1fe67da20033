#include "resolved_interaction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "contact/contact_surface.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/pair_kinematics.hpp"
#include "contact/step_changes.hpp"

namespace inpact::contact {

namespace {

using model::EnforcementMethod;
using Law = model::PressureOverclosure;

/// The *CONTACT CONTROLS in force for `pair` in step `step`: the pair's own over the global
/// ones, carried over from earlier steps until RESET.
const model::ContactControls* controls_for(const model::Model& m, std::size_t step, const model::ContactPair& pair) {
  const model::ContactControls *global = nullptr, *specific = nullptr;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s)
    for (const auto& c : m.steps[s].contact_controls) {
      const bool all = c.master.empty() && c.slave.empty();
      const bool mine = c.master == pair.master && c.slave == pair.slave;
      if (c.reset) {
        if (all) global = specific = nullptr;
        if (mine) specific = nullptr;
      }
      if (all) global = &c;
      else if (mine) specific = &c;
    }
  return specific ? specific : global;
}

/// surface_scales() once per surface (it visits every element).
class ScaleCache {
 public:
  explicit ScaleCache(const model::Model& m) : m_(m) {}
  std::optional<SurfaceScales> of(const model::Surface* s) {
    auto it = cache_.find(s);
    if (it == cache_.end()) it = cache_.emplace(s, surface_scales(m_, *s)).first;
    return it->second;
  }

 private:
  const model::Model& m_;
  std::map<const model::Surface*, std::optional<SurfaceScales>> cache_;
};

/// Step 3: k_e and the characteristic length.
void resolve_scales(const model::Model& m, const ContactInteraction& entry, ScaleCache& cache, ResolvedInteraction& r) {
  auto scales = cache.of(entry.slave);
  const auto other = entry.slave != entry.master ? cache.of(entry.master) : std::nullopt;
  if (!scales) scales = other;
  else if (other) {
    double ke = softer_element_stiffness(*scales, *other);
    // A balanced two-row interaction (general contact): both rows take the mean of the two
    // surfaces' scales, so they hold one law, see the same gap, and each reports the pressure
    // that acts (with its own k_e each row would carry a different share of the load).
    if (entry.general && entry.weight != 1.0) {
      ke = 0.5 * (ke + softer_element_stiffness(*other, *scales));
      scales->characteristic_length = 0.5 * (scales->characteristic_length + other->characteristic_length);
    }
    scales->element_stiffness = ke;
  }
  r.scales_from_mesh = scales.has_value();
  r.ke = scales ? scales->element_stiffness : 0.0;
  r.l_char = scales ? scales->characteristic_length : pair_search_radius(m, *entry.slave, *entry.master, r.thickness);
}

[[noreturn]] void refuse(const model::SourceLoc& loc, const std::string& keyword, const std::string& what) {
  throw InteractionError(what, loc, keyword);
}

/// Step 4: the law and how it is enforced.
void resolve_enforcement(const ContactInteraction& entry, ResolvedInteraction& r) {
  const ResolvedNormalBehavior& b = r.behavior;
  const model::ContactPair& deck = entry.pair;
  const bool softened = b.law != Law::Hard && !deck.tied;
  const bool direct = (b.method == EnforcementMethod::Direct && b.law == Law::Hard) || deck.tied;
  // TIED (after ADJUST): direct hard contact that never separates, and no slip (ROUGH).
  // CalculiX's PRESSURE-OVERCLOSURE=TIED: a bonded spring p = k h from the initial gap (its
  // offsets), tension included, and no slip at the *FRICTION stick slope.
  r.tied_pair = deck.tied;
  r.tied_law = b.law == Law::Tied;
  r.no_separation = b.deck.no_separation || deck.tied || r.tied_law;
  r.augmented = b.method == EnforcementMethod::AugmentedLagrange && !deck.tied;
  if (direct) {
    r.enforcement = EnforcementKind::DirectMultipliers;
    return;
  }
  if (!softened && !b.given_stiffness && !r.scales_from_mesh)
    refuse(deck.loc, entry.general ? "*CONTACT" : "*CONTACT PAIR",
           fmt::format("pair {}: the default penalty stiffness needs an element-based surface with an elastic "
                       "material; give the stiffness on *SURFACE BEHAVIOR", r.name));
  r.law = PressureOverclosure::from(b, r.ke, r.l_char);
  // Table 38.1.21: Lagrange multipliers above 1000 k_e (the law's slope at zero clearance;
  // exponential: at h = 0). Without k_e (node-based slave and master) there is nothing to
  // compare with.
  const bool stiff = r.scales_from_mesh && uses_lagrange_multipliers(b, r.ke, r.law->max_slope(0.0));
  r.enforcement = stiff ? EnforcementKind::LawWithMultipliers
                  : r.augmented ? EnforcementKind::AugmentedLagrange
                                : EnforcementKind::PenaltyLaw;
  r.user_adaptive = b.user_adaptive_stiffness && !stiff;
}

/// A *CHANGE FRICTION of step `step` that moves μ or γ_crit: the ramp from the previous step's law
/// (FrictionRamp). None with *STEP, AMPLITUDE=STEP (and no AMPLITUDE=), or when ROUGH is involved.
std::optional<FrictionRamp> friction_ramp(const model::Model& m, const std::string& name, std::size_t step,
                                          const ResolvedInteraction& r) {
  const model::FrictionChange* c = friction_change_in(m, name, step);
  if (!c || (c->amplitude.empty() && m.steps[step].amplitude == model::Step::DefaultAmplitude::Step)) return std::nullopt;
  const std::optional<model::SurfaceInteraction> before =
      step == 0 ? std::optional<model::SurfaceInteraction>(m.interactions.at(name)) : interaction_in_step(m, name, step - 1);
  FrictionRamp ramp{resolve_friction(before && before->friction ? &*before->friction : nullptr, r.l_char, r.ke),
                    c->amplitude};
  const std::optional<FrictionLaw>& to = r.friction;
  if ((ramp.from && ramp.from->rough) || (to && to->rough)) return std::nullopt;
  const double mu0 = ramp.from ? ramp.from->mu : 0.0, mu1 = to ? to->mu : 0.0;
  const bool same_slip = !ramp.from || !to || ramp.from->gamma_crit == to->gamma_crit;
  if (mu0 == mu1 && same_slip) return std::nullopt;
  return ramp;
}

/// Step 5: HCRIT, friction and the gap offsets.
void resolve_limits_and_friction(const model::Model& m, const ContactInteraction& entry,
                                 const model::SurfaceInteraction* inter, ResolvedInteraction& r) {
  const model::ContactPair& deck = entry.pair;
  const bool softened = r.behavior.law != Law::Hard && !deck.tied;
  if (r.augmented) r.tolerance = *penetration_tolerance(r.behavior, r.l_char);
  r.hcrit = softened ? std::numeric_limits<double>::infinity() : deck.hcrit.value_or(0.5 * r.l_char);
  // Friction: γ_crit from the same characteristic length (KEYWORDS.md Part C c).
  model::Friction tie;
  if (r.tied_law && inter && inter->friction) tie = *inter->friction;
  tie.rough = true;
  const bool tied = deck.tied || r.tied_law;
  r.friction = resolve_friction(tied ? &tie : inter && inter->friction ? &*inter->friction : nullptr, r.l_char, r.ke);
  if (r.tied_law && tie.stick_slope) r.friction->fixed_stiffness = *tie.stick_slope;  // CalculiX's λ
  if (!tied && inter) r.friction_ramp = friction_ramp(m, deck.interaction, r.step, r);
  if (r.friction && r.friction->rough && !(r.ke > 0.0))
    refuse(inter && inter->friction ? inter->friction->loc : deck.loc, inter && inter->friction ? "*FRICTION" : "*CONTACT PAIR",
           fmt::format("pair {}: ROUGH friction needs the element stiffness k_e of an element-based surface with an "
                       "elastic material", r.name));
  const bool has_clearance = !entry.general && std::any_of(m.clearances.begin(), m.clearances.end(), [&](const auto& c) {
    return clearance_names(c, deck);
  });
  r.offsets = r.tied_law ? GapOffsets::InitialGap : has_clearance ? GapOffsets::Clearance : GapOffsets::None;
}

/// What the enforcement cannot do (checked on the resolved method, so check and run agree).
void refuse_unsupported(const ContactInteraction& entry, const model::SurfaceInteraction* inter,
                        const ResolvedInteraction& r) {
  const model::ContactPair& p = entry.pair;
  const std::string kw = entry.general ? "*CONTACT" : "*CONTACT PAIR";
  if (r.self_contact && r.behavior.method == EnforcementMethod::Direct)
    refuse(p.loc, kw, fmt::format("self-contact of {} with direct enforcement is not analysed (every contact would be "
                                  "constrained twice, once from each side); use AUGMENTED LAGRANGE (the default for "
                                  "self-contact) or PENALTY", p.slave));
  if (inter && inter->behavior && inter->behavior->no_separation && !p.tied &&
      (r.behavior.method != EnforcementMethod::Direct || r.behavior.law != Law::Hard))
    refuse(inter->behavior->loc, "*SURFACE BEHAVIOR",
           "NO SEPARATION is analysed with direct hard contact only (a closed node keeps its multiplier, which may "
           "turn tensile); add DIRECT or drop the penalty or softened law");
}

/// Is CalculiX's TIED law in force for `name` in step `step` (the model data's, or a change's)?
bool tied_law_in(const model::Model& m, const std::string& name, std::size_t step) {
  const std::optional<model::SurfaceInteraction> inter = interaction_in_step(m, name, step);
  return inter && inter->behavior && inter->behavior->pressure_overclosure == Law::Tied;
}

/// What *CHANGE SURFACE BEHAVIOR cannot do in inpact: bond the surfaces in a later step (the TIED
/// law bonds each slave node at its initial gap, so it must hold from the model data on), or
/// switch general contact between a method with multipliers and a penalty law (which decides
/// whether the interaction is one row or two, interaction_table.hpp general_contact_one_row).
void refuse_behavior_change(const model::Model& m, const ContactInteraction& entry, std::size_t step,
                            const ResolvedInteraction& r) {
  const model::SurfaceBehaviorChange* c = behavior_change_for(m, entry.pair.interaction, step);
  if (!c) return;
  const model::SourceLoc& loc = c->behavior->loc;
  if (c->behavior->pressure_overclosure == Law::Tied) {
    const auto& data = m.interactions.at(entry.pair.interaction).behavior;
    bool tied_before = data && data->pressure_overclosure == Law::Tied;
    for (std::size_t s = 0; s < step && tied_before; ++s) tied_before = tied_law_in(m, entry.pair.interaction, s);
    if (!tied_before)
      refuse(loc, "*SURFACE BEHAVIOR",
             fmt::format("*CHANGE SURFACE BEHAVIOR to PRESSURE-OVERCLOSURE=TIED: inpact bonds each slave node at its "
                         "initial gap, so the TIED law of '{}' must be in force from the model data on",
                         entry.pair.interaction));
  }
  if (entry.general) {
    const auto it = m.interactions.find(entry.pair.interaction);
    const ResolvedNormalBehavior data =
        resolve_normal_behavior(&it->second, model::ContactDiscretization::SurfaceToSurface, false, true);
    if (general_contact_one_row(data.method) != general_contact_one_row(r.behavior.method))
      refuse(loc, "*SURFACE BEHAVIOR",
             fmt::format("*CHANGE SURFACE BEHAVIOR of '{}', which general contact uses: switching between a method "
                         "with multipliers (direct, augmented Lagrange: one row) and a penalty law (two balanced "
                         "rows) within the analysis is not supported",
                         entry.pair.interaction));
  }
}

ResolvedInteraction resolve_row(const model::Model& m, const InteractionTable& table, std::size_t row,
                                std::size_t step, ScaleCache& cache) {
  const ContactInteraction& entry = table.rows[row];
  const model::ContactPair& deck = entry.pair;
  // The interaction as this step has it (the model data's with the step changes up to it).
  const std::optional<model::SurfaceInteraction> in_step = interaction_in_step(m, deck.interaction, step);
  const model::SurfaceInteraction* inter = in_step ? &*in_step : nullptr;
  ResolvedInteraction r;
  r.row = row;
  r.step = step;
  r.name = entry.name();
  r.general = entry.general;
  r.self_contact = deck.slave == deck.master;
  r.surface_to_surface = deck.type == model::ContactDiscretization::SurfaceToSurface;
  r.finite_sliding = !deck.small_sliding;
  r.weight = entry.weight;
  r.thickness = inter ? inter->out_of_plane_thickness : 1.0;
  NormalBehaviorOptions options;
  options.controls = controls_for(m, step, deck);
  // Self-contact: augmented Lagrange by default (Abaqus's for 3-D node to surface; inpact's in
  // 2D too, where Abaqus would use multipliers that a two-sided contact would duplicate).
  options.self_contact_3d = r.self_contact;
  r.behavior = resolve_normal_behavior(inter, deck.type, deck.small_sliding, entry.general, options);
  refuse_unsupported(entry, inter, r);
  refuse_behavior_change(m, entry, step, r);
  resolve_scales(m, entry, cache, r);
  resolve_enforcement(entry, r);
  resolve_limits_and_friction(m, entry, inter, r);
  r.stabilization = resolve_stabilization(m, table, row, step, r.ke, r.l_char);
  if (r.surface_to_surface) {
    const model::ContactPair* named = entry.general ? nullptr : &deck;
    r.smoothed = !corrections_for(m, deck_surface_name(m, entry.master), named).empty() ||
                 !corrections_for(m, deck_surface_name(m, entry.slave), named).empty();
  }
  return r;
}

/// A balanced interaction whose law goes to multipliers would hold two multipliers on one gap:
/// its first row takes the whole weight, the second is not in force.
void merge_balanced_multiplier_rows(const InteractionTable& table, std::vector<ResolvedInteraction>& records) {
  for (std::size_t k = 0; k < records.size(); ++k) {
    ResolvedInteraction& r = records[k];
    const ContactInteraction& entry = table.rows[r.row];
    if (r.enforcement != EnforcementKind::LawWithMultipliers || !entry.general || entry.weight == 1.0 ||
        entry.slave == entry.master)
      continue;
    const bool second = r.row > 0 && table.rows[r.row - 1].general && table.rows[r.row - 1].slave == entry.master &&
                        table.rows[r.row - 1].master == entry.slave;
    if (second) r.in_force = false;
    else r.weight = 1.0;
  }
}

}  // namespace

std::string deck_surface_name(const model::Model& m, const model::Surface* s) {
  const auto it = m.mesh.surfaces.find(s->name);
  return it != m.mesh.surfaces.end() && &it->second == s ? s->name : std::string();
}

std::vector<ResolvedInteraction> resolve_interactions(const model::Model& m, const InteractionTable& table,
                                                      std::size_t step) {
  ScaleCache cache(m);
  std::vector<ResolvedInteraction> out;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const ContactInteraction& e = table.rows[row];
    if (e.first_step > step) continue;
    if (!e.general && pair_removed(m, e.pair.slave, e.pair.master, step)) continue;  // *MODEL CHANGE, REMOVE
    out.push_back(resolve_row(m, table, row, step, cache));
  }
  merge_balanced_multiplier_rows(table, out);
  return out;
}

std::optional<FrictionLaw> ResolvedInteraction::friction_at(double a) const {
  if (!friction_ramp) return friction;
  const std::optional<FrictionLaw>& from = friction_ramp->from;
  a = std::clamp(a, 0.0, 1.0);
  // Every property but μ and γ_crit is the new law's at once [K16 *CHANGE FRICTION].
  FrictionLaw now = friction ? *friction : *from;
  const double mu0 = from ? from->mu : 0.0, mu1 = friction ? friction->mu : 0.0;
  const double g1 = friction ? friction->gamma_crit : from->gamma_crit, g0 = from ? from->gamma_crit : g1;
  now.mu = mu0 + a * (mu1 - mu0);
  now.gamma_crit = g0 + a * (g1 - g0);
  return now;
}

std::vector<std::vector<ResolvedInteraction>> resolve_all_steps(const model::Model& m, const InteractionTable& table) {
  std::vector<std::vector<ResolvedInteraction>> out;
  for (std::size_t s = 0; s < m.steps.size(); ++s) out.push_back(resolve_interactions(m, table, s));
  return out;
}

}  // namespace inpact::contact
