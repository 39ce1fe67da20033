#include "contact/pressure_overclosure/pressure_law.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::contact {

double PressureLaw::bracket_width(double p, double lo) const {
  return std::max({std::abs(lo), 1e-12, p / std::max(max_slope(lo), 1e-300)});
}

PressureValue PressureLaw::inverse(double p, double lambda, double* h_out) const {
  // Bracket [lo, hi] with p(lo) ≤ p ≤ p(hi), then safeguarded Newton on p(h) − p.
  double lo = onset(lambda);
  double step = bracket_width(p, lo);
  double hi = lo + step;
  for (int i = 0; i < 200 && eval(hi, lambda).p < p; ++i) {
    step *= 2.0;
    hi = lo + step;
  }
  double h = hi;
  PressureValue v = eval(h, lambda);
  for (int it = 0; it < 200; ++it) {
    const double r = v.p - p;
    if (std::abs(r) <= 1e-14 * p) break;
    (r > 0 ? hi : lo) = h;
    double next = v.dp > 0 ? h - r / v.dp : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == h) break;
    h = next;
    v = eval(h, lambda);
  }
  if (h_out) *h_out = h;
  return v;
}

}  // namespace inpact::contact
