#pragma once
/// Softened contact, PRESSURE-OVERCLOSURE=LINEAR [IG]: p = k h for h ≥ 0, else 0.
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class LinearSoftenedLaw final : public PressureLaw {
 public:
  explicit LinearSoftenedLaw(double k) : k_(k) {}

  PressureValue eval(double h, double lambda) const override;
  double max_slope(double h_max) const override { return k_; }
  double h_zero() const override { return 0.0; }
  double stiffness() const override { return k_; }
  std::string describe() const override;

 private:
  double k_;
};

}  // namespace inpact::contact
