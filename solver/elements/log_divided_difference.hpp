#pragma once
/// Divided differences of ln, for the derivatives of the tensor logarithm of a symmetric
/// positive definite tensor in its eigenbasis (Daleckii–Krein): the first derivative multiplies
/// component ab by ln[c_a, c_b], the second sums ln[c_a, c_k, c_b] over k. Both stay accurate
/// where eigenvalues coincide (an undeformed point, a uniaxial stretch).
#include <algorithm>
#include <cmath>

namespace inpact::solver::elements {

/// ln[a, b] = (ln a − ln b)/(a − b) for a, b > 0; near a = b its series, whose limit is 1/b.
inline double log_divided_difference(double a, double b) {
  const double x = (a - b) / b;
  if (std::abs(x) < 1e-5) return (1 - x / 2 + x * x / 3) / b;
  return std::log1p(x) / (a - b);
}

/// ln[a, b, c] = (ln[a, b] − ln[b, c])/(a − c), symmetric in its arguments. When all three lie
/// within 1e-4 of their mean m, the expansion about m: −1/(2m²) − h₂/(4m⁴), h₂ the sum of the
/// products d_i d_j (i ≤ j) of the deviations d = x − m (the first-order term vanishes), exact to
/// (1e-4)³ relative; otherwise the largest gap a − c keeps the quotient well conditioned.
inline double log_second_divided_difference(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  const double m = (a + b + c) / 3;
  if (a - c < 1e-4 * m) {
    const double da = a - m, db = b - m, dc = c - m;
    const double h2 = da * da + db * db + dc * dc + da * db + da * dc + db * dc;
    return -1 / (2 * m * m) - h2 / (4 * m * m * m * m);
  }
  return (log_divided_difference(a, b) - log_divided_difference(b, c)) / (a - c);
}

}  // namespace inpact::solver::elements
