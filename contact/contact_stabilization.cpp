#include "contact_stabilization.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contact/resolved_interaction.hpp"

namespace inpact::contact {

namespace {

/// Does a *CONTACT STABILIZATION data line (first, second) name row `entry`? A blank first
/// surface names every interaction; otherwise the two surfaces, in either order.
bool names_row(const model::Model& m, const std::pair<std::string, std::string>& line, const ContactInteraction& entry) {
  if (line.first.empty()) return true;
  const std::string slave = deck_surface_name(m, entry.slave), master = deck_surface_name(m, entry.master);
  return (line.first == slave && line.second == master) || (line.first == master && line.second == slave);
}

bool names_row(const model::Model& m, const model::ContactStabilizationBlock& b, const ContactInteraction& entry) {
  if (b.surfaces.empty()) return true;
  return std::any_of(b.surfaces.begin(), b.surfaces.end(), [&](const auto& line) { return names_row(m, line, entry); });
}

/// The *CONTACT STABILIZATION block in force for `entry` in step `step`: the last one of this
/// step naming it, else one of an earlier step with AMPLITUDE= (Abaqus's carry-over of
/// "nondefault amplitudes"; a default ramp ends at zero) not cancelled by a RESET since.
const model::ContactStabilizationBlock* block_for(const model::Model& m, const ContactInteraction& entry,
                                                  std::size_t step) {
  const model::ContactStabilizationBlock* found = nullptr;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s) {
    if (found && found->amplitude.empty()) found = nullptr;  // a ramp to zero does not carry over
    for (const auto& b : m.steps[s].contact_stabilizations) {
      if (b.reset) found = nullptr;
      else if (names_row(m, b, entry)) found = &b;
    }
  }
  return found;
}

/// The *CONTACT CONTROLS with STABILIZE of step `step` for the pair (its own over the global
/// ones); STABILIZE is not carried into later steps.
const model::ContactControls* controls_for(const model::Model& m, std::size_t step, const model::ContactPair& pair) {
  if (step >= m.steps.size()) return nullptr;
  const model::ContactControls *global = nullptr, *specific = nullptr;
  for (const auto& c : m.steps[step].contact_controls) {
    if (!c.stabilize) continue;
    if (c.master.empty() && c.slave.empty()) global = &c;
    else if (c.master == pair.master && c.slave == pair.slave) specific = &c;
  }
  return specific ? specific : global;
}

}  // namespace

double StabilizationRule::scale_at(double t, double period, int increment, double amplitude_value) const {
  const double ramp = amplitude.empty() ? 1.0 + (end_factor - 1.0) * std::clamp(t / period, 0.0, 1.0) : amplitude_value;
  const double per_increment = std::pow(reduction_per_increment, std::max(0, increment - 1));
  return scale * ramp * per_increment;
}

std::optional<StabilizationRule> resolve_stabilization(const model::Model& m, const InteractionTable& table,
                                                       std::size_t row, std::size_t step, double ke, double l_char) {
  const ContactInteraction& entry = table.rows[row];
  StabilizationRule r;
  r.range = l_char;
  std::optional<double> coefficient;
  model::SourceLoc loc;
  if (const model::ContactControls* c = controls_for(m, step, entry.pair)) {
    r.pairwise = true;
    r.scale = *c->stabilize;
    r.tangent_fraction = c->tangent_fraction.value_or(1.0);
    r.end_factor = c->stabilize_end_factor.value_or(0.0);
    r.range = c->stabilize_range.value_or(l_char);
    coefficient = c->stabilize_coefficient;
    loc = c->loc;
  } else if (const model::ContactStabilizationBlock* b = block_for(m, entry, step)) {
    r.scale = b->scale_factor;
    r.tangent_fraction = b->tangent_fraction;
    r.amplitude = b->amplitude;
    r.reduction_per_increment = b->reduction_per_increment;
    r.range = b->range.value_or(l_char);
    loc = b->loc;
  } else {
    return std::nullopt;
  }
  const double period = m.steps[step].static_procedure ? m.steps[step].static_procedure->time_period : 1.0;
  r.coefficient_given = coefficient.has_value();
  r.coefficient = coefficient ? *coefficient : kContactDampingFraction * ke * period;
  if (!(r.coefficient > 0.0))
    throw InteractionError(fmt::format("interaction {}: the automatic contact damping coefficient scales with the "
                                       "element stiffness k_e of an element-based surface with an elastic material, "
                                       "which this interaction has none of; give the damping coefficient",
                                       entry.name()),
                           loc, r.pairwise ? "*CONTACT CONTROLS" : "*CONTACT STABILIZATION");
  return r;
}

std::string describe(const StabilizationRule& r) {
  std::string out = fmt::format("contact stabilization ({}): damping coefficient {:.6g}{}", 
                                r.pairwise ? "*CONTACT CONTROLS, STABILIZE" : "*CONTACT STABILIZATION", r.coefficient,
                                r.coefficient_given ? "" : fmt::format(" (automatic: {:g} k_e T)", kContactDampingFraction));
  if (r.scale != 1.0) out += fmt::format(" x {:g}", r.scale);
  out += fmt::format(", tangential fraction {:g}, zero beyond a clearance of {:.6g}", r.tangent_fraction, r.range);
  out += r.amplitude.empty() ? fmt::format(", ramped linearly to {:g} at the step end", r.end_factor)
                             : fmt::format(", scaled by amplitude {}", r.amplitude);
  if (r.reduction_per_increment != 1.0) out += fmt::format(", x {:g} per increment", r.reduction_per_increment);
  return out;
}

double gap_factor(double gap, double range) {
  if (gap <= 0.0) return 1.0;
  return gap >= range ? 0.0 : 1.0 - gap / range;
}

double gap_factor_slope(double gap, double range) { return gap > 0.0 && gap < range ? -1.0 / range : 0.0; }

void damping_contribution(const DampingInput& in, DampingContribution& out) {
  const std::size_t n = in.gradient.size();
  const std::size_t dim = static_cast<std::size_t>(in.dim);
  // B_tα: block b of the node weights w_b = ∇g_b·n times t_α.
  std::vector<double> bt[2] = {std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  const Vec3* t[2] = {&in.t1, &in.t2};
  for (std::size_t b = 0; b + dim <= n; b += dim) {
    double w = 0.0;
    for (std::size_t c = 0; c < dim; ++c) w += in.gradient[b + c] * in.normal[c];
    for (int a = 0; a < 2; ++a)
      for (std::size_t c = 0; c < dim; ++c) bt[a][b + c] = w * (*t[a])[c];
  }
  auto dot = [&](std::span<const double> v) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += v[i] * in.du[i];
    return s;
  };
  const double s_gap = gap_factor(in.gap, in.range), ds = gap_factor_slope(in.gap, in.range);
  const double k = in.area * in.stiffness, kt = k * in.tangent_fraction;
  const double vn = dot(in.gradient), vt[2] = {dot(bt[0]), dot(bt[1])};
  out.force.assign(n, 0.0);
  out.tangent.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    out.force[i] = k * s_gap * vn * in.gradient[i] + kt * s_gap * (vt[0] * bt[0][i] + vt[1] * bt[1][i]);
    for (std::size_t j = 0; j < n; ++j) {
      double kij = k * (s_gap + ds * vn) * in.gradient[i] * in.gradient[j];
      for (int a = 0; a < 2; ++a) kij += kt * (s_gap * bt[a][i] * bt[a][j] + ds * vt[a] * bt[a][i] * in.gradient[j]);
      out.tangent[i * n + j] = kij;
    }
  }
  out.dissipated = s_gap * (k * vn * vn + kt * (vt[0] * vt[0] + vt[1] * vt[1]));
}

}  // namespace inpact::contact
