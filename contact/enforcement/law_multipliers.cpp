#include "law_multipliers.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::contact {

StatusUpdate LawWithMultipliers::update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const {
  // As direct, with the law deciding closure: closed while the multiplier's pressure is
  // compressive, closing where the law acts (touching included) or where it starts closed,
  // from the law's pressure (0 for a node that starts closed at a small gap).
  PressureValue law;
  if (g.found) law = law_.eval(-g.gap, augmented_ ? s.lambda : 0.0);
  const bool closed =
      g.found && (s.closed ? (no_separation_ || -s.multiplier >= limits.open_below) : law.active || g.starts_closed);
  if (closed && !s.closed) s.multiplier = -law.p;
  if (!closed) s.multiplier = 0.0;
  return {closed, closed};
}

LawWithMultipliers::LawPoint LawWithMultipliers::law_point(const SlaveState& s) const {
  const double p = -s.multiplier;
  const double p_small = 1e-12 * std::max(ke_ * l_char_, std::abs(s.lambda));
  LawPoint out;
  if (p > p_small) {
    out.dp = law_.inverse(p, s.lambda, &out.h).dp;
    return out;
  }
  out.dp = law_.inverse(p_small, s.lambda, &out.h).dp;
  if (out.dp > 0.0) out.h += (p - p_small) / out.dp;
  return out;
}

}  // namespace inpact::contact
