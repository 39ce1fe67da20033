#pragma once
/// A penalty-type or softened law whose slope exceeds 1000 k_e, enforced with a Lagrange
/// multiplier per closed node as table 38.1.21 says Abaqus does: the constraint
/// A (g + h(p)) = 0 with h(p) the law's inverse and p = −multiplier, and its compliance
/// −A / p'(h) on the multiplier's diagonal, so the stiffness never enters K and its
/// conditioning (a perturbed Lagrangian). At convergence the pressure is the law's exactly.
#include "contact/enforcement/multiplier_method.hpp"

namespace inpact::contact {

class LawWithMultipliers final : public MultiplierMethod {
 public:
  /// k_e × l_char: the pressure scale below which an inverse of the law is taken linearly.
  LawWithMultipliers(PressureOverclosure law, bool no_separation, bool augmented, double l_char, double ke)
      : law_(std::move(law)), no_separation_(no_separation), augmented_(augmented), l_char_(l_char), ke_(ke) {}
  double SlaveState::*multiplier() const override { return &SlaveState::multiplier; }
  /// A node touching at zero pressure carries round-off of the slope × length: not a reason to
  /// open it (it would close again at once: chattering).
  double pressure_round_off() const override { return 1e-4 * law_.max_slope(0.0) * l_char_; }
  StatusUpdate update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const override;
  double constraint_overclosure(const SlaveState& s) const override { return law_point(s).h; }
  double compliance_slope(const SlaveState& s) const override { return law_point(s).dp; }
  bool augmented() const override { return augmented_; }
  double h_zero() const override { return law_.h_zero(); }

 private:
  struct LawPoint {
    double h = 0.0, dp = 0.0;
  };
  /// The overclosure h at which the law gives the pressure p = −multiplier, and p'(h) there. A
  /// tensile p (possible within the iterations) continues the law linearly below its first
  /// pressure, so the constraint stays smooth.
  LawPoint law_point(const SlaveState& s) const;
  PressureOverclosure law_;
  bool no_separation_, augmented_;
  double l_char_, ke_;
};

}  // namespace inpact::contact
