#include "half_cycle_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace inpact::solver::elements {

namespace {

/// The curve's shape for a given γ: α(ε) = C g(ε) + α_1 e(ε), g = (1 − e^{−γε})/γ, e = e^{−γε}.
struct Shape {
  double g, e;
};
Shape shape(double gamma, double eq) {
  if (gamma == 0.0) return {eq, 1.0};
  return {-std::expm1(-gamma * eq) / gamma, std::exp(-gamma * eq)};
}

/// The best C for γ and the sum of squares that remains.
HalfCycleFit best_modulus(double gamma, std::span<const double> eq, std::span<const double> alpha) {
  double gg = 0.0, gr = 0.0;
  for (std::size_t i = 1; i < eq.size(); ++i) {
    const Shape s = shape(gamma, eq[i]);
    gg += s.g * s.g;
    gr += s.g * (alpha[i] - alpha[0] * s.e);
  }
  HalfCycleFit fit{gr / gg, gamma, 0.0};
  for (std::size_t i = 1; i < eq.size(); ++i) {
    const Shape s = shape(gamma, eq[i]);
    const double r = alpha[i] - fit.modulus * s.g - alpha[0] * s.e;
    fit.rms += r * r;
  }
  return fit;  // rms holds the sum of squares until the end
}

}  // namespace

HalfCycleFit fit_half_cycle(std::span<const double> eq, std::span<const double> alpha) {
  if (eq.size() < 2 || eq.size() != alpha.size() || eq[0] != 0.0)
    throw std::invalid_argument("fit_half_cycle: at least two rows, the first at zero plastic strain");
  HalfCycleFit best = best_modulus(0.0, eq, alpha);
  if (eq.size() > 2) {
    // γ spans 1e-3 to 1e4 over the strain range: from linear to saturated at the first row.
    const double scale = 1.0 / eq.back();
    const int n = 280;
    double step = std::pow(10.0, 7.0 / n), at = 1e-3 * scale, best_at = 0.0;
    for (int k = 0; k <= n; ++k, at *= step) {
      const HalfCycleFit f = best_modulus(at, eq, alpha);
      if (f.rms < best.rms) best = f, best_at = at;
    }
    if (best_at > 0.0) {  // golden sections in log γ around the best grid point
      double lo = std::log(best_at / step), hi = std::log(best_at * step);
      const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
      for (int it = 0; it < 100 && hi - lo > 1e-13; ++it) {
        const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
        if (best_modulus(std::exp(a), eq, alpha).rms < best_modulus(std::exp(b), eq, alpha).rms) hi = b;
        else lo = a;
      }
      const HalfCycleFit f = best_modulus(std::exp(0.5 * (lo + hi)), eq, alpha);
      if (f.rms < best.rms) best = f;
    }
  }
  best.rms = std::sqrt(best.rms / static_cast<double>(eq.size() - 1));
  return best;
}

}  // namespace inpact::solver::elements
