#pragma once
/// Direct hard contact: one Lagrange multiplier λ per closed slave node, pressure −λ, the
/// constraint A g = 0. A node closes when it penetrates (or touches within round-off, or starts
/// closed: NodeGap::starts_closed) and opens when its pressure turns tensile; NO SEPARATION (and
/// TIED pairs) never open a closed node.
#include "contact/enforcement/multiplier_method.hpp"

namespace inpact::contact {

class DirectMultipliers final : public MultiplierMethod {
 public:
  explicit DirectMultipliers(bool no_separation) : no_separation_(no_separation) {}
  StatusUpdate update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const override;

 private:
  bool no_separation_;
};

}  // namespace inpact::contact
