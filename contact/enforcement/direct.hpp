#pragma once
/// Direct hard contact: one Lagrange multiplier λ per closed slave node, pressure −λ, the
/// constraint A g = 0. A node closes when it penetrates (or touches within round-off, or starts
/// closed: NodeGap::starts_closed) and opens when its pressure turns tensile; NO SEPARATION (and
/// TIED pairs) never open a closed node.
#include "contact/enforcement.hpp"

namespace inpact::contact {

class DirectMultipliers final : public Enforcement {
 public:
  explicit DirectMultipliers(bool no_separation) : no_separation_(no_separation) {}
  bool uses_multipliers() const override { return true; }
  StatusUpdate update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const override;
  NormalForce normal_force(const SlaveState& s, const NodeGap&) const override { return {s.lambda, 0.0}; }
  double pressure(const SlaveState& s, const NodeGap& g) const override;
  NodePressure output(const SlaveState& s, const NodeGap& g) const override;

 private:
  bool no_separation_;
};

}  // namespace inpact::contact
