#include "pressure_overclosure.hpp"

#include <stdexcept>
#include <vector>

#include "contact/pressure_overclosure/exponential.hpp"
#include "contact/pressure_overclosure/linear_penalty.hpp"
#include "contact/pressure_overclosure/linear_softened.hpp"
#include "contact/pressure_overclosure/nonlinear_penalty.hpp"
#include "contact/pressure_overclosure/tabular.hpp"
#include "contact/pressure_overclosure/tied.hpp"

namespace inpact::contact {

using Law = model::PressureOverclosure;
using model::EnforcementMethod;

std::shared_ptr<const PressureLaw> PressureOverclosure::zero_law() {
  static const std::shared_ptr<const PressureLaw> zero = std::make_shared<const LinearPenaltyLaw>(0.0, 0.0);
  return zero;
}

// The one place that maps a resolved *SURFACE BEHAVIOR to a law.
PressureOverclosure PressureOverclosure::from(const ResolvedNormalBehavior& r, double ke, double l_char) {
  using std::make_shared;
  const model::SurfaceBehavior& b = r.deck;
  const double c0 = b.clearance_at_zero_pressure;
  switch (r.law) {
    case Law::Hard:
      if (r.method == EnforcementMethod::PenaltyLinear || r.method == EnforcementMethod::AugmentedLagrange)
        return {Kind::LinearPenalty, make_shared<const LinearPenaltyLaw>(penalty_stiffness(r, ke), c0)};
      if (r.method == EnforcementMethod::PenaltyNonlinear) {
        // KEYWORDS.md *SURFACE BEHAVIOR: d + c0 = r_u L_char, e + c0 = r_l (d + c0).
        const double k_final = penalty_stiffness(r, ke), s_d = r.upper_quadratic_limit * l_char;
        const double k_initial = r.initial_final_ratio * k_final, s_e = r.lower_quadratic_ratio * s_d;
        return {Kind::NonlinearPenalty, make_shared<const NonlinearPenaltyLaw>(k_final, k_initial, c0, s_e, s_d)};
      }
      throw std::invalid_argument("direct hard contact has no pressure-overclosure law");
    case Law::Exponential:
      return {Kind::Exponential, make_shared<const ExponentialLaw>(b.exponential_c0, b.exponential_p0)};
    case Law::Linear: return {Kind::Linear, make_shared<const LinearSoftenedLaw>(b.linear_slope.value_or(0.0))};
    case Law::Tabular: {
      std::vector<double> h, p;
      for (const auto& [p_i, h_i] : b.table) {
        p.push_back(p_i);
        h.push_back(h_i);
      }
      return {Kind::Tabular, make_shared<const TabularLaw>(std::move(h), std::move(p))};
    }
    case Law::Tied: return {Kind::Tied, make_shared<const TiedLaw>(b.tied_slope.value_or(0.0))};
  }
  throw std::invalid_argument("unknown pressure-overclosure law");
}

}  // namespace inpact::contact
