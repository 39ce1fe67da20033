/// *CONTACT PAIR, *CLEARANCE and *CONTACT CONTROLS: contact pairs, their initial clearances and
/// the step-wise controls of their enforcement.
#include <fmt/format.h>

#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser::contact_kw {

namespace {

/// ADJUST=a | nset | YES | NO, with POSITION TOLERANCE (newer Abaqus) [IG ctc_adjustsurfaces_std].
void read_adjust(KeywordContext& ctx, model::ContactPair& pair) {
  const auto tolerance = ctx.real_value("POSITION TOLERANCE");
  if (tolerance && *tolerance < 0) {
    ctx.error_param("POSITION TOLERANCE", fmt::format("POSITION TOLERANCE must not be negative, found {}", *tolerance));
    return;
  }
  const KeywordParam* p = ctx.param("ADJUST");
  if (!p || !p->value) {
    if (tolerance) ctx.error_param("POSITION TOLERANCE", "POSITION TOLERANCE goes with ADJUST=YES or ADJUST=NO");
    return;
  }
  const std::string v = normalize_name(*p->value);
  if (auto a = parse_real(*p->value)) {
    if (*a < 0) ctx.error_param("ADJUST", fmt::format("the adjustment distance must not be negative, found {}", *a));
    else pair.adjust_distance = *a;
    if (tolerance) ctx.error_param("POSITION TOLERANCE", "POSITION TOLERANCE goes with ADJUST=YES or ADJUST=NO, not a distance");
  } else if (v == "YES") {
    // ADJUST=YES, POSITION TOLERANCE=a means ADJUST=a [IG]; without a tolerance inpact adjusts
    // only the overclosed nodes (a = 0) — Abaqus's own default tolerance is UNCONFIRMED.
    pair.adjust_distance = tolerance.value_or(0.0);
  } else if (v == "NO") {
    // ADJUST=NO, POSITION TOLERANCE stores the penetrations as offsets [IG]: that changes the
    // answer and inpact cannot do it.
    if (tolerance) ctx.error_param("POSITION TOLERANCE", "ADJUST=NO with POSITION TOLERANCE (stored offsets) is not supported yet");
  } else {
    pair.adjust_nset = normalize_label(*p->value);  // checked when the deck is complete
  }
}

}  // namespace

// *CONTACT PAIR, INTERACTION=, TYPE= [K16 §3.68], [CCX]. Defaults (Abaqus/Standard input):
// finite sliding, TYPE=NODE TO SURFACE; no ADJUST = an initial overclosure is an interference
// fit; EXTENSION ZONE 0.1, SMOOTH 0.2, HCRIT unset (= half a slave face), as model/contact.hpp
// says. Data lines `slave, master`; self-contact is `surf,` or `surf, surf` [IG].
void contact_pair(KeywordContext& ctx) {
  model::ContactPair base;
  base.interaction = ctx.name_value("INTERACTION");
  base.loc = ctx.keyword.loc;
  base.interaction_loc = ctx.param_loc("INTERACTION");
  base.geometric_correction_loc = ctx.param_loc("GEOMETRIC CORRECTION");
  base.adjust_loc = ctx.param_loc("ADJUST");

  const std::string type = ctx.choice_value("TYPE");
  if (type == "SURFACETOSURFACE") base.type = model::ContactDiscretization::SurfaceToSurface;
  else if (type == "MORTAR" || type == "LINMORTAR" || type == "PGLINMORTAR") {
    // CalculiX's mortar contact (dual or Petrov-Galerkin multipliers) enforces the same weighted
    // gap as inpact's surface to surface (standard basis): the pressures agree to the
    // discretisation error, the multiplier fields do not.
    base.type = model::ContactDiscretization::SurfaceToSurface;
    ctx.warning(ctx.param_loc("TYPE"), fmt::format("TYPE={} (CalculiX's mortar contact) runs as inpact's SURFACE TO "
                                                   "SURFACE: the same weighted gap, with standard rather than dual "
                                                   "multipliers", type));
  } else if (type == "MASSLESS")
    ctx.error_param("TYPE", "TYPE=MASSLESS (CalculiX's contact of explicit dynamics) is not supported by inpact; use "
                            "SURFACE TO SURFACE or NODE TO SURFACE");
  base.small_sliding = ctx.has("SMALL SLIDING");
  base.tied = ctx.has("TIED");
  base.no_thickness = ctx.has("NO THICKNESS");
  base.linear = ctx.has("LINEAR");
  base.geometric_correction = ctx.name_value("GEOMETRIC CORRECTION");
  read_adjust(ctx, base);

  if (auto z = ctx.real_value("EXTENSION ZONE")) {
    if (*z < 0 || *z > 0.2) ctx.error_param("EXTENSION ZONE", fmt::format("EXTENSION ZONE must lie in [0, 0.2], found {}", *z));
    else base.extension_zone = *z;
  }
  if (auto s = ctx.real_value("SMOOTH")) {
    if (*s < 0 || *s > 0.5) ctx.error_param("SMOOTH", fmt::format("SMOOTH must lie in [0, 0.5], found {}", *s));
    else base.smooth = *s;
  }
  if (auto h = ctx.real_value("HCRIT")) {
    if (*h <= 0) ctx.error_param("HCRIT", fmt::format("HCRIT must be positive, found {}", *h));
    else base.hcrit = *h;
  }
  if (base.tied && !base.adjust_distance && base.adjust_nset.empty())
    ctx.error_param("TIED", "TIED needs ADJUST (the slave nodes are moved onto the master before they are tied)");
  if (!base.geometric_correction.empty() && base.type != model::ContactDiscretization::SurfaceToSurface)
    ctx.error_param("GEOMETRIC CORRECTION", "GEOMETRIC CORRECTION applies to TYPE=SURFACE TO SURFACE only");

  // Abaqus/Standard formulation details that inpact's own discretisations do not have: the
  // answer they give differs from Abaqus's by discretisation error only, so they are accepted
  // with a warning.
  if (ctx.choice_value("SUPPLEMENTARY CONSTRAINTS") != "NO")
    warn_ignored(ctx, "SUPPLEMENTARY CONSTRAINTS", "inpact's node-to-surface contact adds no supplementary constraints");
  for (std::string_view p : {"MIDFACE NODES", "MINIMUM DISTANCE", "SLIDING TRANSITION", "TRACKING"})
    warn_ignored(ctx, p, "inpact's contact formulation has no such choice");
  for (std::string_view p : {"CPSET", "MECHANICAL CONSTRAINT", "WEIGHT"})
    warn_ignored(ctx, p, "it applies to Abaqus/Explicit only");
  if (ctx.choice_value("OP") == "DELETE")
    ctx.error_param("OP", "OP=DELETE (removing contact pairs) is not supported yet");

  auto& pairs = ctx.state.step ? ctx.state.step->contact_pairs : ctx.model().contact_pairs;
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 1, 2, "slave surface, master surface")) continue;
    if (f[0].empty()) {
      ctx.error(f[0].loc, "the slave surface name is missing");
      continue;
    }
    model::ContactPair pair = base;
    pair.slave = normalize_label(f[0].text);
    pair.master = f.size() == 2 && !f[1].empty() ? normalize_label(f[1].text) : pair.slave;
    pair.loc = f[0].loc;
    if (pair.slave == pair.master) {
      if (pair.small_sliding) ctx.error(f[0].loc, "self-contact cannot use SMALL SLIDING");
      if (pair.tied) ctx.error(f[0].loc, "self-contact cannot be TIED");
    }
    pairs.push_back(std::move(pair));
  }
}

// *CLEARANCE, SLAVE=, MASTER=, VALUE= | TABULAR [K16 §3.21], [CCX]. VALUE: one clearance for
// every slave node (> 0 a gap, < 0 an overclosure); TABULAR lines `node | nset, clearance`.
void clearance(KeywordContext& ctx) {
  model::Clearance c;
  c.slave = aliased_name(ctx, "SLAVE", "SECONDARY");
  c.master = aliased_name(ctx, "MASTER", "MAIN");
  c.loc = ctx.keyword.loc;
  if (c.slave.empty() || c.master.empty()) {
    ctx.error(ctx.keyword.loc, "missing required parameters SLAVE= (or SECONDARY=) and MASTER= (or MAIN=)");
    return;
  }
  reject_param(ctx, "BOLT", "bolt thread geometry");
  const bool tabular = ctx.has("TABULAR");
  c.value = ctx.real_value("VALUE");
  if (tabular == ctx.has("VALUE")) {
    ctx.error(ctx.keyword.loc, "give exactly one of VALUE= and TABULAR");
    return;
  }
  if (!tabular) {
    if (!ctx.data.empty()) ctx.error(line_start(ctx.data[0]), "VALUE= takes no data lines (use TABULAR for node-wise values)");
    ctx.model().clearances.push_back(std::move(c));
    return;
  }
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, "TABULAR needs data lines: slave node or node set, clearance");
    return;
  }
  std::vector<Field> f;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 5, "slave node or node set, clearance[, normal direction]")) continue;
    if (f.size() > 2) {
      // The clearance direction defaults to the master's normal; another one changes the answer.
      ctx.error(f[2].loc, "an explicit clearance direction is not supported yet");
      continue;
    }
    auto rows = ctx.nodes(f[0]);
    auto value = ctx.real(f[1], "clearance");
    if (!rows || !value) continue;
    for (std::int32_t row : *rows) c.node_values.emplace_back(row, *value);
  }
  ctx.model().clearances.push_back(std::move(c));
}

// *CONTACT CONTROLS (step data) [K16 §3.57], [IG ctc_contactcontrols_std], [AX p.782-783].
// Defaults: nothing set, so contact/ uses Abaqus's (relative penetration tolerance 0.1 %, 5 %
// for finite-sliding surface-to-surface, scaled by 1/√f_k when f_k < 1; stiffness factor 1);
// no SLAVE/MASTER = every pair; a pair's own controls override the global ones.
void contact_controls(KeywordContext& ctx) {
  model::ContactControls c;
  c.slave = aliased_name(ctx, "SLAVE", "SECONDARY");
  c.master = aliased_name(ctx, "MASTER", "MAIN");
  c.reset = ctx.has("RESET");
  c.loc = ctx.keyword.loc;
  if (c.slave.empty() != c.master.empty()) {
    ctx.error(ctx.keyword.loc, "SLAVE= and MASTER= (SECONDARY=/MAIN=) go together: give both or neither");
    return;
  }
  contact_controls_stabilize(ctx, c);  // kw_contact_stabilization.cpp
  for (std::string_view p : {"PERTURBATION TANGENT SCALE FACTOR", "PRESSURE DEPENDENT PERTURBATION"})
    warn_ignored(ctx, p, "it applies to linear perturbation steps only");
  for (std::string_view p : {"CPSET", "FASTLOCALTRK", "GLOBTRKINC", "SCALE PENALTY", "WARP CHECK PERIOD", "WARP CUT OFF"})
    warn_ignored(ctx, p, "it applies to Abaqus/Explicit only");

  if (ctx.has("ABSOLUTE PENETRATION TOLERANCE") && ctx.has("RELATIVE PENETRATION TOLERANCE"))
    ctx.error_param("RELATIVE PENETRATION TOLERANCE",
                    "ABSOLUTE and RELATIVE PENETRATION TOLERANCE are mutually exclusive");
  for (std::string_view p : {"ABSOLUTE PENETRATION TOLERANCE", "RELATIVE PENETRATION TOLERANCE"}) {
    auto v = ctx.real_value(p);
    if (!v) continue;
    if (*v <= 0) {
      ctx.error_param(p, fmt::format("{} must be positive, found {}", p, *v));
      continue;
    }
    (p.starts_with("ABS") ? c.absolute_penetration_tolerance : c.relative_penetration_tolerance) = *v;
  }
  if (ctx.has("STIFFNESS SCALE FACTOR")) {
    if (ctx.choice_value("STIFFNESS SCALE FACTOR") == "USERADAPTIVE") {
      c.user_adaptive_stiffness = true;
      // The factor list on its data line is not published (KEYWORDS.md Part D 2).
      if (ctx.data.size() > (ctx.has("STABILIZE") ? 1u : 0u))
        ctx.error(line_start(ctx.data[ctx.has("STABILIZE") ? 1 : 0]),
                  "explicit factors for STIFFNESS SCALE FACTOR=USER ADAPTIVE are not supported yet");
    } else if (auto f = ctx.real_value("STIFFNESS SCALE FACTOR")) {
      if (*f <= 0) ctx.error_param("STIFFNESS SCALE FACTOR", fmt::format("STIFFNESS SCALE FACTOR must be positive, found {}", *f));
      else c.stiffness_scale_factor = *f;
    }
  }
  if (!ctx.data.empty() && !c.user_adaptive_stiffness && !ctx.has("STABILIZE") &&
      !ctx.has("PRESSURE DEPENDENT PERTURBATION"))
    ctx.error(line_start(ctx.data[0]), "this keyword takes data lines only with STABILIZE, STIFFNESS SCALE FACTOR=USER ADAPTIVE "
                               "or PRESSURE DEPENDENT PERTURBATION");
  ctx.state.step->contact_controls.push_back(std::move(c));
}

}  // namespace inpact::parser::contact_kw
