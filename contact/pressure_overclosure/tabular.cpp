#include "contact/pressure_overclosure/tabular.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace inpact::contact {

PressureValue TabularLaw::eval(double h, double lambda) const {
  PressureValue v;
  if (h_.empty() || h < h_.front()) return v;
  v.active = true;
  const std::size_t n = h_.size();
  if (n == 1) return {p_[0], 0.0, true};
  // Segment i: [h_i, h_{i+1}]; beyond the last point the last segment continues.
  std::size_t i = static_cast<std::size_t>(std::upper_bound(h_.begin(), h_.end(), h) - h_.begin());
  i = std::min(std::max<std::size_t>(i, 1), n - 1) - 1;
  const double slope = (p_[i + 1] - p_[i]) / (h_[i + 1] - h_[i]);
  v.p = std::max(p_[i] + slope * (h - h_[i]), 0.0);
  v.dp = slope;
  return v;
}

double TabularLaw::max_slope(double h_max) const {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < h_.size(); ++i) s = std::max(s, (p_[i + 1] - p_[i]) / (h_[i + 1] - h_[i]));
  return s;
}

std::string TabularLaw::describe() const { return fmt::format("tabular, {} points", h_.size()); }

}  // namespace inpact::contact
