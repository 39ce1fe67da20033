#pragma once
/// Softened contact, PRESSURE-OVERCLOSURE=EXPONENTIAL [IG]: with ŝ = h/c0 + 1,
///   p = p0/(e−1) · ŝ (exp(ŝ) − 1)   for h ≥ −c0, else 0,
/// so p(−c0) = 0 and p(0) = p0; the slope grows without bound.
#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class ExponentialLaw final : public PressureLaw {
 public:
  /// Clearance `c0` at which the pressure is zero, pressure `p0` at zero clearance.
  ExponentialLaw(double c0, double p0) : c0_(c0), p0_(p0) {}

  PressureValue eval(double h, double lambda) const override;
  /// The slope at h_max (at −c0 below it): the law is convex.
  double max_slope(double h_max) const override;
  double h_zero() const override { return -c0_; }
  double stiffness() const override { return 0.0; }
  std::string describe() const override;

 protected:
  /// c0: the slope is 0 at −c0, so p over it would put the bracket's top out of reach (exp
  /// overflows, bisection cannot come back in 200 halvings); from −c0 + c0 = 0 (p = p0) the
  /// doubling needs a few steps, exp(ŝ) growing as it does.
  double bracket_width(double p, double lo) const override { return c0_; }

 private:
  double c0_, p0_;
};

}  // namespace inpact::contact
