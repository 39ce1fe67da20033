#pragma once
/// Abaqus's rule for temperature-dependent material data: linear between the temperatures of
/// the data, constant outside their range. One bracket per evaluation, shared by every
/// quantity given at the same temperatures.
#include <cstddef>
#include <span>

namespace inpact::solver::elements {

/// value(T) = (1 − weight) · value[lower] + weight · value[upper].
struct TemperatureBracket {
  std::size_t lower = 0, upper = 0;
  double weight = 0.0;
  double blend(double at_lower, double at_upper) const { return (1 - weight) * at_lower + weight * at_upper; }
};

/// The bracket of `temperature` in the increasing `temperatures` (empty or one: no dependence).
inline TemperatureBracket bracket(std::span<const double> temperatures, double temperature) {
  const std::size_t n = temperatures.size();
  if (n < 2 || temperature <= temperatures.front()) return {};
  if (temperature >= temperatures.back()) return {n - 1, n - 1, 0.0};
  std::size_t t = 0;
  while (temperature >= temperatures[t + 1]) ++t;
  return {t, t + 1, (temperature - temperatures[t]) / (temperatures[t + 1] - temperatures[t])};
}

}  // namespace inpact::solver::elements
