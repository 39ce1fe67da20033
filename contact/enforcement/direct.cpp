#include "direct.hpp"

namespace inpact::contact {

StatusUpdate DirectMultipliers::update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const {
  const bool closed = g.found && (s.closed ? (no_separation_ || -s.lambda >= limits.open_below)
                                           : g.gap < limits.close_below || g.starts_closed);
  if (!closed) s.lambda = 0.0;
  return {closed, closed};
}

}  // namespace inpact::contact
