#pragma once
/// Hard contact enforced by PENALTY=NONLINEAR [IG]: with s = h + c0,
///   p = K_i s                                   for 0 ≤ s ≤ s_e
///   stiffness rising linearly from K_i to K_f   for s_e ≤ s ≤ s_d (p quadratic)
///   slope K_f                                   for s > s_d
/// p and dp/dh are continuous at s_e and s_d. s_d = r_u L_char, s_e = r_l s_d, K_i = ratio K_f
/// (KEYWORDS.md *SURFACE BEHAVIOR; contact/pressure_overclosure.cpp computes them).
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class NonlinearPenaltyLaw final : public PressureLaw {
 public:
  /// Final and initial stiffness, clearance at zero pressure, and the ends s_e ≤ s_d of the
  /// quadratic part (measured in s = h + c0).
  NonlinearPenaltyLaw(double k_final, double k_initial, double c0, double s_e, double s_d)
      : k_(k_final), k_initial_(k_initial), c0_(c0), s_e_(s_e), s_d_(s_d) {}

  PressureValue eval(double h, double lambda) const override;
  double max_slope(double h_max) const override { return k_; }
  double h_zero() const override { return -c0_; }
  double stiffness() const override { return k_; }
  std::string describe() const override;

 private:
  double k_, k_initial_, c0_, s_e_, s_d_;
};

}  // namespace inpact::contact
