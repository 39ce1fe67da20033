#include "contact/pressure_overclosure/nonlinear_penalty.hpp"

#include <fmt/format.h>

namespace inpact::contact {

PressureValue NonlinearPenaltyLaw::eval(double h, double lambda) const {
  PressureValue v;
  const double s = h + c0_;
  if (s < 0.0) return v;
  v.active = true;
  const double kf = k_, ki = k_initial_, span = s_d_ - s_e_;
  if (s <= s_e_) {
    v.p = ki * s;
    v.dp = ki;
  } else if (s <= s_d_) {
    v.p = ki * s + (kf - ki) * (s - s_e_) * (s - s_e_) / (2.0 * span);
    v.dp = ki + (kf - ki) * (s - s_e_) / span;
  } else {
    v.p = ki * s_d_ + 0.5 * (kf - ki) * span + kf * (s - s_d_);
    v.dp = kf;
  }
  return v;
}

std::string NonlinearPenaltyLaw::describe() const {
  return fmt::format("nonlinear penalty, K_i = {:.4g}, K_f = {:.4g}, quadratic for {:.3g} ≤ h + c0 ≤ {:.3g}",
                     k_initial_, k_, s_e_, s_d_);
}

}  // namespace inpact::contact
