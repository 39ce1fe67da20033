#pragma once
/// What the methods with a Lagrange multiplier per closed node share: the pressure is −(the
/// multiplier) while the node is closed (never tensile for friction and augmentation; CPRESS
/// shows a bonded node's tension), and the multiplier is the force coefficient,
/// f_c = A multiplier ∇g. Which field holds the multiplier is the method's (multiplier()).
#include <algorithm>

#include "contact/enforcement.hpp"

namespace inpact::contact {

class MultiplierMethod : public Enforcement {
 public:
  bool uses_multipliers() const final { return true; }
  NormalForce normal_force(const SlaveState& s, const NodeGap&) const final { return {s.*multiplier(), 0.0}; }
  double pressure(const SlaveState& s, const NodeGap& g) const final {
    return s.closed && g.found ? std::max(-(s.*multiplier()), 0.0) : 0.0;
  }
  NodePressure output(const SlaveState& s, const NodeGap& g) const final {
    const bool closed = s.closed && g.found;
    return {closed ? -(s.*multiplier()) : 0.0, closed};
  }
};

}  // namespace inpact::contact
