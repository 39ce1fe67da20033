#pragma once
/// CalculiX's PRESSURE-OVERCLOSURE=TIED: p = k h for every h, a bonded spring with tension
/// included (h is measured from the initial gap, solver/contact_problem.cpp).
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class TiedLaw final : public PressureLaw {
 public:
  explicit TiedLaw(double k) : k_(k) {}

  PressureValue eval(double h, double lambda) const override { return {k_ * h, k_, true}; }
  double max_slope(double h_max) const override { return k_; }
  /// Where the spring is unstressed (it acts on both sides): −c0 with c0 = 0, as the other laws
  /// give it, so that sums with it keep their sign of zero (−0.0).
  double h_zero() const override { return -0.0; }
  double stiffness() const override { return k_; }
  std::string describe() const override;

 private:
  double k_;
};

}  // namespace inpact::contact
