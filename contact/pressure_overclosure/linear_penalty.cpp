#include "contact/pressure_overclosure/linear_penalty.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace inpact::contact {

PressureValue LinearPenaltyLaw::eval(double h, double lambda) const {
  PressureValue v;
  const double trial = lambda + k_ * (h + c0_);
  if (trial > 0.0 || (lambda == 0.0 && h + c0_ >= 0.0)) v = {std::max(trial, 0.0), k_, true};
  return v;
}

std::string LinearPenaltyLaw::describe() const { return fmt::format("linear penalty, k = {:.4g}, c0 = {:g}", k_, c0_); }

}  // namespace inpact::contact
