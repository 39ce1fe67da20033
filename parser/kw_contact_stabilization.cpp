/// Contact stabilization (history data): *CONTACT STABILIZATION and the STABILIZE parameter of
/// *CONTACT CONTROLS. Both become one rule per interaction (contact/contact_stabilization.hpp).
/// Sources: [K16 *CONTACT STABILIZATION], [IG "Stabilization for general contact in
/// Abaqus/Standard"], [IG ctc_contactcontrols_std "Automatic stabilization of rigid body
/// motions in contact problems"] (parser/KEYWORDS.md).
#include <fmt/format.h>

#include "kw_contact.hpp"
#include "text.hpp"

namespace inpact::parser::contact_kw {

namespace {

/// A parameter value that must be >= 0 (> 0 when `positive`); nullopt (after reporting) if not.
std::optional<double> non_negative(KeywordContext& ctx, std::string_view param, bool positive) {
  const auto v = ctx.real_value(param);
  if (!v) return std::nullopt;
  if (*v < 0.0 || (positive && *v == 0.0)) {
    ctx.error_param(param, fmt::format("{} must be {}, found {}", param, positive ? "positive" : "zero or positive", *v));
    return std::nullopt;
  }
  return v;
}

/// One `first surface, second surface` data line of *CONTACT STABILIZATION.
void surface_line(KeywordContext& ctx, const Line& line, model::ContactStabilizationBlock& b) {
  std::vector<Field> f;
  split_fields(line, f);
  if (!ctx.check_count(f, line, 1, 2, "first surface, second surface (blank first surface: every interaction)")) return;
  const std::string first = f[0].empty() ? std::string() : normalize_label(f[0].text);
  const std::string second = f.size() == 2 && !f[1].empty() ? normalize_label(f[1].text) : first;
  if (first.empty() && !second.empty()) {
    ctx.error(f[1].loc, "a second surface needs a first one (a blank first surface means every interaction)");
    return;
  }
  b.surfaces.emplace_back(first, second);  // the names are checked when the deck is complete (finalize.cpp)
  b.surface_locs.push_back(f[0].loc);
  b.surface_locs.push_back(f.size() == 2 && !f[1].empty() ? f[1].loc : f[0].loc);
}

}  // namespace

// *CONTACT STABILIZATION [K16]: AMPLITUDE (s_ampl; default 1 → 0 linearly over the step),
// RANGE (the clearance at which damping becomes zero; default: the interaction's characteristic
// facet length), REDUCTION PER INCREMENT (0.1), SCALE FACTOR (1; USER ADAPTIVE is refused),
// TANGENT FRACTION (0); RESET alone, without data lines. Data lines name surface pairs.
// Abaqus documents it for general contact; inpact applies it to *CONTACT PAIRs as well.
void contact_stabilization(KeywordContext& ctx) {
  model::ContactStabilizationBlock b;
  b.loc = ctx.keyword.loc;
  b.reset = ctx.has("RESET");
  if (b.reset) {
    for (const KeywordParam& p : ctx.keyword.params)
      if (p.name != "RESET") ctx.error(p.loc, "RESET cannot be used with other parameters");
    if (!ctx.data.empty()) ctx.error(line_start(ctx.data[0]), "RESET takes no data lines");
    ctx.state.step->contact_stabilizations.push_back(std::move(b));
    return;
  }
  if (ctx.has("AMPLITUDE")) {
    b.amplitude = ctx.name_value("AMPLITUDE");
    b.amplitude_loc = ctx.param_loc("AMPLITUDE");  // checked when the deck is complete (finalize.cpp)
  }
  b.range = non_negative(ctx, "RANGE", true);
  if (const auto r = non_negative(ctx, "REDUCTION PER INCREMENT", false)) {
    if (*r > 1.0)
      ctx.error_param("REDUCTION PER INCREMENT", fmt::format("REDUCTION PER INCREMENT must be at most 1, found {}", *r));
    else b.reduction_per_increment = *r;
  }
  if (ctx.has("SCALE FACTOR") && ctx.choice_value("SCALE FACTOR") == "USERADAPTIVE")
    ctx.error_param("SCALE FACTOR", "SCALE FACTOR=USER ADAPTIVE (a factor varying over the iterations) is not "
                                    "supported yet; give a number");
  else if (const auto s = non_negative(ctx, "SCALE FACTOR", true)) b.scale_factor = *s;
  if (const auto t = non_negative(ctx, "TANGENT FRACTION", false)) b.tangent_fraction = *t;
  for (const Line& line : ctx.data) surface_line(ctx, line, b);
  ctx.state.step->contact_stabilizations.push_back(std::move(b));
}

// *CONTACT CONTROLS, STABILIZE[=factor][, TANGENT FRACTION=t] [IG ctc_contactcontrols_std]: the
// factor scales the automatic damping coefficient (flag: 1); TANGENT FRACTION (default 1) scales
// it tangentially. Optional data line: damping coefficient (blank: automatic), the factor the
// damping keeps at the step end (default 0), the clearance at which damping becomes zero
// (default: the characteristic facet length). For this step only.
void contact_controls_stabilize(KeywordContext& ctx, model::ContactControls& c) {
  if (!ctx.has("STABILIZE")) {
    if (ctx.has("TANGENT FRACTION")) ctx.error_param("TANGENT FRACTION", "TANGENT FRACTION goes with STABILIZE");
    return;
  }
  if (ctx.choice_value("STABILIZE") == "USERADAPTIVE") {
    ctx.error_param("STABILIZE", "STABILIZE=USER ADAPTIVE (a factor varying over the iterations) is not supported "
                                 "yet; give a number or the flag alone");
    return;
  }
  c.stabilize = !ctx.param("STABILIZE")->value ? std::optional<double>(1.0) : non_negative(ctx, "STABILIZE", true);
  if (!c.stabilize) return;
  c.tangent_fraction = non_negative(ctx, "TANGENT FRACTION", false);
  if (ctx.data.empty()) return;
  if (ctx.data.size() > 1) ctx.error(line_start(ctx.data[1]), "STABILIZE takes one data line");
  std::vector<Field> f;
  split_fields(ctx.data[0], f);
  if (!ctx.check_count(f, ctx.data[0], 1, 3,
                       "damping coefficient (blank: automatic), factor at the step end, clearance where damping ends"))
    return;
  const char* what[] = {"damping coefficient", "factor at the step end", "clearance where damping ends"};
  std::optional<double>* out[] = {&c.stabilize_coefficient, &c.stabilize_end_factor, &c.stabilize_range};
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!optional_real(ctx, f, i, what[i], *out[i]) || !*out[i]) continue;
    const double v = **out[i];
    if (v < 0.0 || (i != 1 && v == 0.0) || (i == 1 && v > 1.0)) {
      ctx.error(f[i].loc, fmt::format("the {} must be {}, found {}", what[i], i == 1 ? "in [0, 1]" : "positive", v));
      out[i]->reset();
    }
  }
}

}  // namespace inpact::parser::contact_kw
