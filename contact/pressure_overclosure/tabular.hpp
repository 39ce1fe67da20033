#pragma once
/// Softened contact, PRESSURE-OVERCLOSURE=TABULAR [IG]: piecewise linear through the points
/// (h_i, p_i) in ascending overclosure; 0 below h_0, the last segment's slope beyond the last
/// point. A single point gives the constant p_0 from h_0 on.
#include <utility>
#include <vector>

#include "contact/pressure_overclosure/pressure_law.hpp"

namespace inpact::contact {

class TabularLaw final : public PressureLaw {
 public:
  /// Overclosures `h` (ascending) and their pressures `p`, of the same length.
  TabularLaw(std::vector<double> h, std::vector<double> p) : h_(std::move(h)), p_(std::move(p)) {}

  PressureValue eval(double h, double lambda) const override;
  /// The steepest segment (0 with fewer than two points); `h_max` is not needed.
  double max_slope(double h_max) const override;
  double h_zero() const override { return h_.empty() ? 0.0 : h_.front(); }
  double stiffness() const override { return 0.0; }
  std::string describe() const override;

 private:
  std::vector<double> h_, p_;
};

}  // namespace inpact::contact
