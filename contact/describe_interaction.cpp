// The one text of a resolved interaction (resolved_interaction.hpp): `inpact check`, the run's
// messages, the results file and the .dat header print exactly this.
#include <cmath>

#include <fmt/format.h>

#include "contact/resolved_interaction.hpp"

namespace inpact::contact {

namespace {

const char* method_name(model::EnforcementMethod m) {
  switch (m) {
    case model::EnforcementMethod::Direct: return "direct";
    case model::EnforcementMethod::PenaltyLinear: return "linear penalty";
    case model::EnforcementMethod::PenaltyNonlinear: return "nonlinear penalty";
    case model::EnforcementMethod::AugmentedLagrange: return "augmented Lagrange";
    case model::EnforcementMethod::Default: break;
  }
  return "default";
}

std::string enforcement_text(const ResolvedInteraction& r) {
  switch (r.enforcement) {
    case EnforcementKind::DirectMultipliers:
      return r.tied_pair ? "Lagrange multipliers (TIED: bonded once adjusted, no slip)" : "Lagrange multipliers";
    case EnforcementKind::PenaltyLaw:
      return r.scales_from_mesh ? "no Lagrange multipliers (slope <= 1000 k_e)"
                                : "no Lagrange multipliers (no k_e to compare the slope with)";
    case EnforcementKind::LawWithMultipliers:
      return "Lagrange multipliers (slope > 1000 k_e), the law's compliance on their diagonal";
    case EnforcementKind::AugmentedLagrange:
      return r.scales_from_mesh ? "augmented Lagrange multipliers (slope <= 1000 k_e)"
                                : "augmented Lagrange multipliers (no k_e to compare the slope with)";
  }
  return "";
}

std::string tolerance_text(const ResolvedInteraction& r) {
  const ResolvedNormalBehavior& b = r.behavior;
  std::string out = fmt::format("penetration tolerance {:.6g}", r.tolerance);
  if (!b.tolerance_is_absolute && b.tolerance)
    out += fmt::format(" ({:g} % of the characteristic length)", *b.tolerance * 100.0);
  if (b.tolerance_is_default) out += " (default)";
  return out;
}

std::string scales_text(const ResolvedInteraction& r) {
  if (!r.scales_from_mesh)
    return fmt::format("no element stiffness (node-based surfaces), characteristic length {:.6g} (the search radius)",
                       r.l_char);
  return fmt::format("k_e = {:.6g}, characteristic length {:.6g}", r.ke, r.l_char);
}

const char* offsets_text(GapOffsets o) {
  switch (o) {
    case GapOffsets::None: return "";
    case GapOffsets::Clearance: return "; initial gaps from *CLEARANCE";
    case GapOffsets::InitialGap: return "; each slave node bonded at its initial gap";
  }
  return "";
}

/// *CHANGE FRICTION's transition over the step: where μ and γ_crit start.
std::string ramp_text(const FrictionRamp& ramp) {
  const std::string from = ramp.from ? fmt::format("mu = {:g}, elastic slip {:.6g}", ramp.from->mu, ramp.from->gamma_crit)
                                     : std::string("frictionless");
  const std::string by = ramp.amplitude.empty() ? std::string("linearly over the step (step amplitude RAMP)")
                                                : fmt::format("by amplitude {}", ramp.amplitude);
  return fmt::format(" (*CHANGE FRICTION: from {} at the step start, {})", from, by);
}

}  // namespace

std::string describe(const ResolvedInteraction& r) {
  std::string out = fmt::format("{} {}: {}, {} sliding", r.general ? "general contact" : "contact pair", r.name,
                                r.surface_to_surface ? "surface to surface" : "node to surface",
                                r.finite_sliding ? "finite" : "small");
  if (r.behavior.law == model::PressureOverclosure::Hard) out += r.no_separation ? "; hard contact, no separation" : "; hard contact";
  out += fmt::format("; {} ({})", method_name(r.behavior.method), r.behavior.method_reason);
  if (r.law) out += "; " + r.law->describe();  // the law, with its values
  out += "; " + enforcement_text(r);
  if (r.augmented) out += "; " + tolerance_text(r);
  if (r.user_adaptive) out += "; user-adaptive stiffness in the first increment";
  out += "; " + scales_text(r);
  out += std::isfinite(r.hcrit) ? fmt::format("; HCRIT {:.6g}", r.hcrit) : std::string("; no HCRIT (softened law)");
  if (r.weight != 1.0) out += fmt::format("; weight {:g} ({})", r.weight, r.self_contact ? "self-contact" : "balanced master-slave");
  if (r.smoothed) out += "; smoothed (geometric correction)";
  out += offsets_text(r.offsets);
  if (r.thickness != 1.0) out += fmt::format("; out-of-plane thickness {:g}", r.thickness);
  out += r.friction ? "; " + describe(*r.friction) : std::string("; frictionless");
  if (r.friction_ramp) out += ramp_text(*r.friction_ramp);
  if (r.stabilization) out += "; " + describe(*r.stabilization);
  return out;
}

std::vector<std::string> describe(const std::vector<ResolvedInteraction>& records) {
  std::vector<std::string> out;
  for (const ResolvedInteraction& r : records)
    if (r.in_force) out.push_back(describe(r));
  return out;
}

}  // namespace inpact::contact
