#include "penalty.hpp"

namespace inpact::contact {

PressureValue PenaltyLaw::law_pressure(const SlaveState& s, const NodeGap& g) const {
  if (!g.found) return {};
  PressureValue v = law_.eval(-g.gap, options_.augmented ? s.lambda : 0.0);
  if (options_.user_adaptive) {
    v.p *= adaptive_scale_;
    v.dp *= adaptive_scale_;
  }
  return v;
}

bool PenaltyLaw::closed(const PressureValue& pv) const {
  return options_.tied_law ? pv.active : pv.p > 0.0;  // a tied node is closed in tension too
}

StatusUpdate PenaltyLaw::update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const {
  const PressureValue pv = law_pressure(s, g);
  // The tangent is the law's exact one, which Newton's quadratic convergence needs; at
  // augmented Lagrange's 1000 k_e the Newton loop keeps nodes from bouncing across the kink
  // instead (solver/newton.cpp, limit_correction).
  // A node touching within round-off brings the law's first slope too: a penalty law acts only
  // from h + c0 ≥ 0, and a body resting on its contact at a gap of +1e-12 would otherwise have
  // no stiffness at all. So does a node that starts closed (it touched when the pair came into
  // force): the first system of a body resting on it is regular.
  const bool touching = g.found && (g.gap < limits.close_below || g.starts_closed);
  return {closed(pv), pv.active || touching};
}

NormalForce PenaltyLaw::normal_force(const SlaveState& s, const NodeGap& g) const {
  const PressureValue pv = law_pressure(s, g);
  if (g.starts_closed && !pv.active) return start_closed_force(g);
  // An open node kept for damping or touching (update_status) brings the law's first slope.
  return {-pv.p, pv.active ? pv.dp : law_.max_slope(0.0)};
}

NormalForce PenaltyLaw::start_closed_force(const NodeGap& g) const {
  // p = k (h − h_zero) continued below h_zero (tensile): the force that closes the node's gap
  // in the first solve, where the law's stiffness alone would let it close by only P/(k A).
  const double k = law_.max_slope(0.0) * (options_.user_adaptive ? adaptive_scale_ : 1.0);
  return {k * (g.gap + law_.h_zero()), k};
}

NodePressure PenaltyLaw::output(const SlaveState& s, const NodeGap& g) const {
  const PressureValue pv = law_pressure(s, g);
  return {pv.p, closed(pv)};
}

}  // namespace inpact::contact
