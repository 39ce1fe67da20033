#include "direct.hpp"

#include <algorithm>

namespace inpact::contact {

StatusUpdate DirectMultipliers::update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const {
  const bool closed = g.found && (s.closed ? (no_separation_ || -s.lambda >= limits.open_below)
                                           : g.gap < limits.close_below || g.starts_closed);
  if (!closed) s.lambda = 0.0;
  return {closed, closed};
}

double DirectMultipliers::pressure(const SlaveState& s, const NodeGap& g) const {
  return s.closed && g.found ? std::max(-s.lambda, 0.0) : 0.0;
}

NodePressure DirectMultipliers::output(const SlaveState& s, const NodeGap& g) const {
  const bool closed = s.closed && g.found;
  return {closed ? -s.lambda : 0.0, closed};
}

}  // namespace inpact::contact
