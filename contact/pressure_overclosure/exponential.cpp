#include "contact/pressure_overclosure/exponential.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace inpact::contact {

PressureValue ExponentialLaw::eval(double h, double lambda) const {
  PressureValue v;
  if (h < -c0_) return v;
  const double s = h / c0_ + 1.0, a = p0_ / (std::numbers::e - 1.0);
  v.p = a * s * (std::exp(s) - 1.0);
  v.dp = a / c0_ * ((std::exp(s) - 1.0) + s * std::exp(s));
  v.active = true;
  return v;
}

double ExponentialLaw::max_slope(double h_max) const { return eval(std::max(h_max, -c0_), 0.0).dp; }

std::string ExponentialLaw::describe() const { return fmt::format("exponential, c0 = {:g}, p0 = {:g}", c0_, p0_); }

}  // namespace inpact::contact
