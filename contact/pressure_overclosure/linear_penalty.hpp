#pragma once
/// Hard contact enforced by a linear penalty or augmented Lagrange [IG]:
///   p = ⟨λ + k (h + c0)⟩,  λ the augmented-Lagrange multiplier (0 for the pure penalty),
/// acting from h + c0 ≥ 0 when λ = 0 (touching included), else where λ + k (h + c0) > 0.
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class LinearPenaltyLaw final : public PressureLaw {
 public:
  /// Penalty stiffness `k` (pressure per overclosure), clearance at zero pressure `c0`.
  LinearPenaltyLaw(double k, double c0) : k_(k), c0_(c0) {}

  PressureValue eval(double h, double lambda) const override;
  double max_slope(double h_max) const override { return k_; }
  double h_zero() const override { return -c0_; }
  double stiffness() const override { return k_; }
  std::string describe() const override;

 protected:
  /// Where λ + k (h + c0) = 0.
  double onset(double lambda) const override { return -c0_ - lambda / k_; }

 private:
  double k_, c0_;
};

}  // namespace inpact::contact
