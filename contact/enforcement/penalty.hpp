#pragma once
/// A penalty-type or softened pressure-overclosure law without multipliers: p = p(h), h = −g,
/// f_c = −A p ∇g, K_c = A p' ∇g∇gᵀ − A p ∇²g. Augmented Lagrange is the linear penalty law
/// with a multiplier λ per node, p = ⟨λ + k (h + c0)⟩, and λ ← p after Newton converges while a
/// penetration exceeds the tolerance (solver/analysis.cpp's augmentation loop).
#include "contact/enforcement.hpp"

namespace inpact::contact {

struct PenaltyOptions {
  bool augmented = false;      ///< augmented Lagrange: λ shifts the law
  bool tied_law = false;       ///< CalculiX's TIED law: closed in tension too
  bool user_adaptive = false;  ///< USER ADAPTIVE: the law scaled by set_adaptive_scale()
};

class PenaltyLaw final : public Enforcement {
 public:
  PenaltyLaw(PressureOverclosure law, PenaltyOptions options) : law_(std::move(law)), options_(options) {}
  StatusUpdate update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const override;
  NormalForce normal_force(const SlaveState& s, const NodeGap& g) const override;
  double pressure_slope(const SlaveState& s, const NodeGap& g) const override { return law_pressure(s, g).dp; }
  double pressure(const SlaveState& s, const NodeGap& g) const override { return law_pressure(s, g).p; }
  NodePressure output(const SlaveState& s, const NodeGap& g) const override;
  bool augmented() const override { return options_.augmented; }
  double h_zero() const override { return law_.h_zero(); }
  void set_adaptive_scale(double scale) override { adaptive_scale_ = scale; }

 private:
  /// The law at the node's overclosure (λ: augmented Lagrange only), times USER ADAPTIVE's factor.
  PressureValue law_pressure(const SlaveState& s, const NodeGap& g) const;
  /// The contact status the law gives: pressure (the TIED law: where it acts, tension too).
  bool closed(const PressureValue& pv) const;
  /// A node that starts closed short of the law's range (NodeGap::starts_closed): the law's
  /// first slope k, and the pressure k (h − h_zero) continued into tension, as a closed node of
  /// a status-based penalty method carries until its status is checked (its first update).
  NormalForce start_closed_force(const NodeGap& g) const;
  PressureOverclosure law_;
  PenaltyOptions options_;
  double adaptive_scale_ = 1.0;
};

}  // namespace inpact::contact
