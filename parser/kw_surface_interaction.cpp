/// *SURFACE INTERACTION with its sub-options *SURFACE BEHAVIOR and *FRICTION: the contact
/// property (normal law, enforcement method, friction) that pairs and general contact refer to.
/// Defaults are Abaqus/Standard's (parser/KEYWORDS.md Part A and C); what is left unset here is
/// resolved against the mesh by contact/normal_behavior.hpp.
#include <fmt/format.h>

#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser::contact_kw {

namespace {

using model::EnforcementMethod;
using model::PressureOverclosure;

/// The one data line of an option that takes at most one (nullptr when there is none).
const Line* at_most_one_line(KeywordContext& ctx, std::string_view layout) {
  if (ctx.data.size() > 1) ctx.error(line_start(ctx.data[1]), fmt::format("expected one data line ({})", layout));
  return ctx.data.empty() ? nullptr : &ctx.data[0];
}

/// Where a *SURFACE BEHAVIOR goes: its *SURFACE INTERACTION's, or the open *CHANGE SURFACE
/// BEHAVIOR's; null (reported) when that already has one.
std::optional<model::SurfaceBehavior>* behavior_target(KeywordContext& ctx) {
  const bool change = ctx.state.open_parent == kChangeSurfaceBehavior;
  auto& target = change ? ctx.state.behavior_change->behavior : ctx.state.interaction->behavior;
  if (!target) return &target;
  ctx.error(ctx.keyword.loc, change ? fmt::format("this *CHANGE SURFACE BEHAVIOR of '{}' already has a *SURFACE BEHAVIOR",
                                                  ctx.state.behavior_change->interaction)
                                    : fmt::format("surface interaction '{}' already has a *SURFACE BEHAVIOR",
                                                  ctx.state.interaction->name));
  return nullptr;
}

/// Where a *FRICTION goes: its *SURFACE INTERACTION's, or the open *CHANGE FRICTION's; null
/// (reported) when that already has one, or is a RESET.
std::optional<model::Friction>* friction_target(KeywordContext& ctx) {
  const bool change = ctx.state.open_parent == kChangeFriction;
  auto& target = change ? ctx.state.friction_change->friction : ctx.state.interaction->friction;
  if (change && ctx.state.friction_change->reset) {
    ctx.error(ctx.keyword.loc, "*CHANGE FRICTION, RESET returns the model data's friction: no *FRICTION follows it "
                               "(drop RESET to give new values)");
    return nullptr;
  }
  if (!target) return &target;
  ctx.error(ctx.keyword.loc, change ? fmt::format("this *CHANGE FRICTION of '{}' already has a *FRICTION",
                                                  ctx.state.friction_change->interaction)
                                    : fmt::format("surface interaction '{}' already has a *FRICTION",
                                                  ctx.state.interaction->name));
  return nullptr;
}

}  // namespace

// *SURFACE INTERACTION, NAME=: an optional data line with the out-of-plane thickness (2D) or
// the area per node of node-based surfaces; default 1.0 [K16], [IG friction].
void surface_interaction(KeywordContext& ctx) {
  const std::string key = ctx.name_value("NAME");
  auto [it, inserted] = ctx.model().interactions.try_emplace(key);
  if (!inserted) ctx.error_param("NAME", fmt::format("surface interaction '{}' is defined twice", key));
  model::SurfaceInteraction& inter = it->second;
  inter = model::SurfaceInteraction{};
  inter.name = ctx.param("NAME")->value.value_or(key);
  inter.loc = ctx.keyword.loc;
  ctx.state.interaction = &inter;
  ctx.state.open_parent = kSurfaceInteraction;

  // A user interaction subroutine (UINTER) replaces the whole contact law: inpact has none.
  reject_param(ctx, "USER", "user subroutine UINTER");
  reject_param(ctx, "DEPVAR", "only with USER");
  reject_param(ctx, "PROPERTIES", "only with USER");
  reject_param(ctx, "UNSYMM", "only with USER");
  warn_ignored(ctx, "PAD THICKNESS", "it applies to Abaqus/Explicit only");
  if (auto t = ctx.real_value("TRACKING THICKNESS")) {
    if (*t <= 0) ctx.error_param("TRACKING THICKNESS", fmt::format("TRACKING THICKNESS must be positive, found {}", *t));
    else inter.tracking_thickness = *t;
  }

  if (const Line* line = at_most_one_line(ctx, "out-of-plane thickness or area per node")) {
    std::vector<Field> f;
    split_fields(*line, f);
    if (!ctx.check_count(f, *line, 1, 1, "out-of-plane thickness or area per node")) return;
    std::optional<double> t;
    if (!optional_real(ctx, f, 0, "out-of-plane thickness", t) || !t) return;
    if (*t <= 0) ctx.error(f[0].loc, fmt::format("the out-of-plane thickness must be positive, found {}", *t));
    else inter.out_of_plane_thickness = *t;
  }
}

namespace {

/// PENALTY / AUGMENTED LAGRANGE data line: k_pen (blank or 0 = default), c0 (default 0),
/// scale factor (default 1); PENALTY=NONLINEAR adds r_u, K_i/K_f, r_l [IG], [K66 p.512].
void read_penalty_line(KeywordContext& ctx, const Line& line, model::SurfaceBehavior& b) {
  const bool nonlinear = b.method == EnforcementMethod::PenaltyNonlinear;
  const char* layout = nonlinear
                           ? "final stiffness, clearance at zero pressure, scale factor, upper quadratic limit "
                             "scale factor, initial/final stiffness ratio, lower quadratic limit ratio"
                           : "penalty stiffness, clearance at zero pressure, scale factor";
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 1, nonlinear ? 6 : 3, layout)) return;
  std::optional<double> k, c0, scale, r_u, ratio, r_l;
  if (!optional_real(ctx, f, 0, "penalty stiffness", k) || !optional_real(ctx, f, 1, "clearance at zero pressure", c0) ||
      !optional_real(ctx, f, 2, "stiffness scale factor", scale) ||
      !optional_real(ctx, f, 3, "upper quadratic limit scale factor", r_u) ||
      !optional_real(ctx, f, 4, "initial/final stiffness ratio", ratio) ||
      !optional_real(ctx, f, 5, "lower quadratic limit ratio", r_l))
    return;
  // Abaqus 6.5 said "must be positive"; later manuals read a blank as the default, and 0 is
  // read the same way (KEYWORDS.md): only a negative stiffness is an error.
  if (k && *k < 0) ctx.error(f[0].loc, fmt::format("the penalty stiffness must be positive, found {}", *k));
  else if (k && *k > 0) b.penalty_stiffness = *k;
  if (c0) b.clearance_at_zero_pressure = *c0;
  if (scale && *scale <= 0) ctx.error(f[2].loc, fmt::format("the stiffness scale factor must be positive, found {}", *scale));
  else if (scale) b.stiffness_scale_factor = *scale;
  if (r_u && *r_u <= 0)
    ctx.error(f[3].loc, fmt::format("the upper quadratic limit scale factor must be positive, found {}", *r_u));
  else if (r_u) b.upper_quadratic_limit_scale_factor = *r_u;
  if (ratio && (*ratio <= 0 || *ratio > 1))
    ctx.error(f[4].loc, fmt::format("the initial/final stiffness ratio must lie in (0, 1], found {}", *ratio));
  else if (ratio) b.initial_final_stiffness_ratio = *ratio;
  if (r_l && (*r_l <= 0 || *r_l >= 1))
    ctx.error(f[5].loc, fmt::format("the lower quadratic limit ratio must lie in (0, 1), found {}", *r_l));
  else if (r_l) b.lower_quadratic_limit_ratio = *r_l;
}

/// EXPONENTIAL: c0, p0 (no defaults in Abaqus/Standard [IG]); k_max is Abaqus/Explicit's.
/// c0 is read with Abaqus's meaning (the clearance at which the pressure falls to zero); a
/// CalculiX deck means the distance at which it falls to 1 % of p0 (KEYWORDS.md Part A).
void read_exponential(KeywordContext& ctx, const Line& line, model::SurfaceBehavior& b) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 2, 3, "clearance c0 at zero pressure, pressure p0 at zero clearance")) return;
  auto c0 = ctx.real(f[0], "clearance c0 at which the pressure is zero");
  auto p0 = ctx.real(f[1], "pressure p0 at zero clearance");
  if (!c0 || !p0) return;
  if (*c0 <= 0) ctx.error(f[0].loc, fmt::format("the clearance c0 must be positive, found {}", *c0));
  if (*p0 <= 0) ctx.error(f[1].loc, fmt::format("the pressure p0 must be positive, found {}", *p0));
  if (f.size() == 3 && !f[2].empty())
    ctx.warning(f[2].loc, "the maximum stiffness (third field) applies to Abaqus/Explicit only; ignored");
  b.exponential_c0 = *c0;
  b.exponential_p0 = *p0;
}

/// LINEAR: k (Abaqus); CalculiX adds σ∞ and c0 for node-to-surface contact [CCX].
void read_linear(KeywordContext& ctx, const Line& line, model::SurfaceBehavior& b) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 1, 3, "slope k[, σ∞, c0 (CalculiX)]")) return;
  auto k = ctx.real(f[0], "slope of the pressure-overclosure line");
  std::optional<double> sigma_inf, c0;
  if (!k || !optional_real(ctx, f, 1, "tension at large clearance σ∞", sigma_inf) ||
      !optional_real(ctx, f, 2, "spring generation factor c0", c0))
    return;
  // CalculiX would substitute 50 × E for a slope ≤ 0; a deck that means a slope must give one.
  if (*k <= 0) ctx.error(f[0].loc, fmt::format("the slope of the pressure-overclosure line must be positive, found {}", *k));
  else b.linear_slope = *k;
  b.linear_sigma_inf = sigma_inf;
  if (c0 && *c0 <= 0) ctx.error(f[2].loc, fmt::format("c0 must be positive, found {}", *c0));
  else b.linear_c0 = c0;
  // Where inpact differs from CalculiX: its LINEAR law is Abaqus's, p = k h for h > 0 and no
  // tension; CalculiX's tension branch up to σ∞ and its contact distance c0 are not modelled.
  if ((sigma_inf && *sigma_inf != 0.0) || c0)
    ctx.warning(f[1].loc, "CalculiX's σ∞ (tension at large clearance) and c0 (contact distance) are read but not "
                          "used: inpact's LINEAR law is Abaqus's, p = k h for overclosure h > 0, without tension");
}

/// TABULAR: `pressure, overclosure` lines in ascending overclosure, at least two [K66 p.514];
/// a third field is CalculiX's temperature, which inpact cannot vary.
void read_tabular(KeywordContext& ctx, model::SurfaceBehavior& b) {
  std::vector<Field> f;
  bool ok = true;
  for (const Line& line : ctx.data) {
    split_fields(line, f);
    if (!ctx.check_count(f, line, 2, 3, "pressure, overclosure")) {
      ok = false;
      continue;
    }
    auto p = ctx.real(f[0], "pressure");
    auto h = ctx.real(f[1], "overclosure");
    if (f.size() == 3 && !f[2].empty()) {
      ctx.error(f[2].loc, "temperature-dependent pressure-overclosure tables are not supported yet");
      ok = false;
    }
    if (!p || !h) {
      ok = false;
      continue;
    }
    if (*p < 0) {
      ctx.error(f[0].loc, fmt::format("the contact pressure must not be negative, found {}", *p));
      ok = false;
    } else if (!b.table.empty()) {
      const auto& prev = b.table.back();
      if (*h <= prev[1]) {
        ctx.error(f[1].loc, fmt::format("overclosures must increase from line to line: {} follows {}", *h, prev[1]));
        ok = false;
      } else if (*p <= prev[0]) {
        // A falling or flat segment leaves the contact without (or with negative) stiffness.
        ctx.error(f[0].loc, fmt::format("pressures must increase with overclosure: {} follows {}", *p, prev[0]));
        ok = false;
      }
    }
    b.table.push_back({*p, *h});
  }
  if (ok && b.table.size() < 2)
    ctx.error(line_start(ctx.data.front()), "a tabular pressure-overclosure law needs at least two data lines");
  if (ok && !b.table.empty() && b.table.front()[0] > 0)
    ctx.warning(line_start(ctx.data.front()),
                "the first pressure is not zero: the pressure jumps from zero to it at the first overclosure");
}

}  // namespace

// *SURFACE BEHAVIOR [K16 §18.48], [IG], [AX]. Defaults: PRESSURE-OVERCLOSURE=HARD; no
// enforcement flag = the method Abaqus picks for the formulation (EnforcementMethod::Default,
// resolved in contact/normal_behavior.cpp); bare PENALTY = PENALTY=LINEAR.
// Under *CHANGE SURFACE BEHAVIOR (a step) it is read the same way into the step's change.
void surface_behavior(KeywordContext& ctx) {
  std::optional<model::SurfaceBehavior>* target = behavior_target(ctx);
  if (!target) return;
  model::SurfaceBehavior b;
  b.loc = ctx.keyword.loc;

  const std::string law = ctx.choice_value("PRESSURE-OVERCLOSURE");
  if (law.empty() || law == "HARD") b.pressure_overclosure = PressureOverclosure::Hard;
  else if (law == "EXPONENTIAL") b.pressure_overclosure = PressureOverclosure::Exponential;
  else if (law == "LINEAR") b.pressure_overclosure = PressureOverclosure::Linear;
  else if (law == "TABULAR") b.pressure_overclosure = PressureOverclosure::Tabular;
  else if (law == "TIED") b.pressure_overclosure = PressureOverclosure::Tied;
  else if (law == "SCALEFACTOR") {
    ctx.error_param("PRESSURE-OVERCLOSURE", "PRESSURE-OVERCLOSURE=SCALE FACTOR applies to Abaqus/Explicit general contact only");
    return;
  } else if (law == "HERTZ" || law == "JKR" || law == "LKM") {
    ctx.error_param("PRESSURE-OVERCLOSURE",
                    fmt::format("PRESSURE-OVERCLOSURE={} (discrete element method) is not supported by inpact", law));
    return;
  } else {
    return;  // not a valid choice: already reported by the reader
  }
  const bool hard = b.pressure_overclosure == PressureOverclosure::Hard;

  int n_methods = 0;
  for (const KeywordParam& p : ctx.keyword.params) {
    if (p.name != "AUGMENTEDLAGRANGE" && p.name != "DIRECT" && p.name != "PENALTY") continue;
    if (++n_methods > 1) {  // reported at the second one, in deck order
      ctx.error(p.loc, "AUGMENTED LAGRANGE, DIRECT and PENALTY are mutually exclusive");
      return;
    }
  }
  if (ctx.has("AUGMENTED LAGRANGE")) b.method = EnforcementMethod::AugmentedLagrange;
  else if (ctx.has("DIRECT")) b.method = EnforcementMethod::Direct;
  else if (ctx.has("PENALTY"))
    b.method = ctx.choice_value("PENALTY") == "NONLINEAR" ? EnforcementMethod::PenaltyNonlinear
                                                          : EnforcementMethod::PenaltyLinear;
  const bool penalty_like = b.method == EnforcementMethod::AugmentedLagrange ||
                            b.method == EnforcementMethod::PenaltyLinear ||
                            b.method == EnforcementMethod::PenaltyNonlinear;
  if (penalty_like && !hard) {
    // [K17]: these apply "only ... with a default hard pressure-overclosure relationship";
    // softened laws are always enforced directly [IG].
    ctx.error_param(ctx.has("PENALTY") ? "PENALTY" : "AUGMENTED LAGRANGE",
                    fmt::format("{} applies to hard contact only; PRESSURE-OVERCLOSURE={} is enforced directly",
                                ctx.has("PENALTY") ? "PENALTY" : "AUGMENTED LAGRANGE", law));
    return;
  }
  if (ctx.has("NO SEPARATION")) {
    // [K16]: "the PRESSURE-OVERCLOSURE parameter cannot be used with the NO SEPARATION
    // parameter in an Abaqus/Standard analysis".
    if (ctx.has("PRESSURE-OVERCLOSURE")) {
      ctx.error_param("NO SEPARATION", "NO SEPARATION cannot be combined with PRESSURE-OVERCLOSURE");
      return;
    }
    b.no_separation = true;
  }

  switch (b.pressure_overclosure) {
    case PressureOverclosure::Hard: {
      if (ctx.data.empty()) break;
      if (!penalty_like) {
        ctx.error(line_start(ctx.data[0]), "hard contact takes a data line only with PENALTY or AUGMENTED LAGRANGE");
        return;
      }
      if (const Line* line = at_most_one_line(ctx, "penalty stiffness, clearance at zero pressure, scale factor"))
        read_penalty_line(ctx, *line, b);
      break;
    }
    case PressureOverclosure::Exponential:
      if (ctx.data.empty()) {
        ctx.error_param("PRESSURE-OVERCLOSURE", "EXPONENTIAL needs a data line: c0, p0 (they have no defaults)");
        return;
      }
      read_exponential(ctx, *at_most_one_line(ctx, "c0, p0"), b);
      break;
    case PressureOverclosure::Linear:
      if (ctx.data.empty()) {
        ctx.error_param("PRESSURE-OVERCLOSURE", "LINEAR needs its slope on a data line");
        return;
      }
      read_linear(ctx, *at_most_one_line(ctx, "slope"), b);
      break;
    case PressureOverclosure::Tabular:
      if (ctx.data.empty()) {
        ctx.error_param("PRESSURE-OVERCLOSURE", "TABULAR needs data lines: pressure, overclosure");
        return;
      }
      read_tabular(ctx, b);
      break;
    case PressureOverclosure::Tied: {
      // CalculiX: one line with the normal stiffness K (> 0) [CCX].
      if (ctx.data.empty()) {
        ctx.error_param("PRESSURE-OVERCLOSURE", "TIED needs its stiffness on a data line");
        return;
      }
      const Line& line = *at_most_one_line(ctx, "stiffness");
      std::vector<Field> f;
      split_fields(line, f);
      if (!ctx.check_count(f, line, 1, 1, "stiffness")) return;
      auto k = ctx.real(f[0], "tied stiffness");
      if (k && *k <= 0) ctx.error(f[0].loc, fmt::format("the tied stiffness must be positive, found {}", *k));
      else if (k) b.tied_slope = *k;
      break;
    }
  }
  *target = std::move(b);
}

// *FRICTION [K16 §6.36], [IG ctc_friction]. Defaults: isotropic Coulomb friction enforced by
// stiffness (elastic slip) with SLIP TOLERANCE 0.005 of the characteristic length (left unset
// here, resolved by contact/); no *FRICTION at all means frictionless.
// Data line: Abaqus `μ, slip rate, pressure, temperature, fields...` (a single line is a
// constant μ, whatever the other fields say); CalculiX `μ, stick slope λ`. The second field is
// read as CalculiX's λ: on a single Abaqus line it has no effect, so that reading is the only
// one that can matter. More lines would be a rate/pressure/temperature table: not supported.
// Under *CHANGE FRICTION (a step) it is read the same way into the step's change.
void friction(KeywordContext& ctx) {
  std::optional<model::Friction>* target = friction_target(ctx);
  if (!target) return;
  model::Friction fr;
  fr.loc = ctx.keyword.loc;
  reject_param(ctx, "USER", "user subroutine FRIC");
  reject_param(ctx, "DEPVAR", "only with USER");
  reject_param(ctx, "PROPERTIES", "only with USER");
  reject_param(ctx, "ANISOTROPIC", "anisotropic friction");
  reject_param(ctx, "ANISOTROPIC BEHAVIOR", "anisotropic friction");
  reject_param(ctx, "EXPONENTIAL DECAY", "static-kinetic exponential decay");
  reject_param(ctx, "TEST DATA", "static-kinetic exponential decay");
  warn_ignored(ctx, "SHEAR TRACTION SLOPE", "it applies to Abaqus/Explicit only");
  if (auto n = ctx.int_value("DEPENDENCIES"); n && *n > 0)
    ctx.error_param("DEPENDENCIES", "field-variable-dependent friction is not supported yet");
  // TAUMAX omitted or 0 means no shear stress limit in Abaqus/Standard.
  if (auto tau = ctx.real_value("TAUMAX"); tau && *tau != 0)
    ctx.error_param("TAUMAX", "a shear stress limit (TAUMAX) is not supported yet");

  fr.rough = ctx.has("ROUGH");
  fr.lagrange = ctx.has("LAGRANGE");
  if (fr.rough)
    for (std::string_view p : {"LAGRANGE", "ELASTIC SLIP", "SLIP TOLERANCE"})
      if (ctx.has(p)) ctx.error_param(p, fmt::format("ROUGH and {} are mutually exclusive", p));
  if (auto v = ctx.real_value("SLIP TOLERANCE")) {
    if (*v <= 0) ctx.error_param("SLIP TOLERANCE", fmt::format("SLIP TOLERANCE must be positive, found {}", *v));
    else fr.slip_tolerance = *v;
  }
  if (auto v = ctx.real_value("ELASTIC SLIP")) {
    // ELASTIC SLIP overrides SLIP TOLERANCE [K16]; both are kept, contact/ applies the rule.
    if (*v <= 0) ctx.error_param("ELASTIC SLIP", fmt::format("ELASTIC SLIP must be positive, found {}", *v));
    else fr.elastic_slip = *v;
  }
  if (fr.lagrange && ctx.has("ELASTIC SLIP"))
    ctx.error_param("ELASTIC SLIP", "LAGRANGE enforces sticking exactly; ELASTIC SLIP does not apply");

  if (fr.rough) {
    if (!ctx.data.empty()) ctx.error(line_start(ctx.data[0]), "ROUGH friction takes no data lines");
    *target = fr;
    return;
  }
  if (ctx.data.empty()) {
    ctx.error(ctx.keyword.loc, "data line is missing: friction coefficient");
    return;
  }
  if (ctx.data.size() > 1) {
    ctx.error(line_start(ctx.data[1]), "rate-, pressure- or temperature-dependent friction (more than one data line) is not supported yet");
    return;
  }
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (f.empty() || f[0].empty()) {
    ctx.error(line_start(ctx.data[0]), "the friction coefficient is missing");
    return;
  }
  auto mu = ctx.real(f[0], "friction coefficient");
  std::optional<double> lambda;
  if (!mu || !optional_real(ctx, f, 1, "stick slope", lambda)) return;
  if (*mu < 0) {
    ctx.error(f[0].loc, fmt::format("the friction coefficient must not be negative, found {}", *mu));
    return;
  }
  fr.mu = *mu;
  // CalculiX replaces λ ≤ 0 by a default; so does inpact (unset), so only a positive λ is kept.
  if (lambda && *lambda > 0) fr.stick_slope = *lambda;
  *target = fr;
}

}  // namespace inpact::parser::contact_kw
