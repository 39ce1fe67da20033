#include "contact/pressure_overclosure/linear_softened.hpp"

#include <fmt/format.h>

namespace inpact::contact {

PressureValue LinearSoftenedLaw::eval(double h, double lambda) const {
  if (h < 0.0) return {};
  return {k_ * h, k_, true};
}

std::string LinearSoftenedLaw::describe() const { return fmt::format("linear softened, k = {:g}", k_); }

}  // namespace inpact::contact
