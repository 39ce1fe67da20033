#include "convergence.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::solver {

double average_force(const AssemblyResult& assembly, std::span<const double> f_ext, double contact_sum,
                     std::size_t contact_count) {
  double sum = assembly.average_force * static_cast<double>(assembly.n_force_entries) + contact_sum;
  std::size_t count = assembly.n_force_entries + contact_count;
  for (double f : f_ext)
    if (f != 0.0) {
      sum += std::abs(f);
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

std::pair<double, std::int64_t> largest_residual(const DofMap& dofs, std::span<const double> r) {
  double worst = 0.0;
  std::int64_t at = -1;
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d) {
    if (dofs.kind(d) != DofMap::Kind::Free) continue;
    const double v = std::abs(r[dofs.equation(d)]);
    if (!(v <= worst)) {  // also catches NaN
      worst = v;
      at = d;
    }
  }
  return {worst, at};
}

double largest_increment(std::span<const double> u, std::span<const double> u_start) {
  double largest = 0.0;
  for (std::size_t d = 0; d < u.size(); ++d) largest = std::max(largest, std::abs(u[d] - u_start[d]));
  return largest;
}

ConvergenceCheck check_convergence(const IterationMeasures& m, const SolutionControls& controls) {
  // C_ε = 1e-3: Abaqus's contact compatibility tolerance (*CONTROLS, PARAMETERS=FIELD).
  const double gap_tolerance = 1e-3 * m.max_increment + 1e-14;
  const bool no_force = m.q <= 0.0;  // nothing loads the model: equilibrium is exact or nothing
  const bool corrected = m.iteration > 0;
  const double linear_tolerance = controls.linear_tolerance * m.q;
  const double residual_tolerance = controls.residual_tolerance * m.q;
  const double correction_tolerance = controls.correction_tolerance * m.max_increment;
  ConvergenceCheck c;
  c.criteria = {{
      {"contact status", m.contact_status_changed ? 1.0 : 0.0, 0.0, !m.contact_status_changed},
      {"contact compatibility", m.max_gap_error, gap_tolerance, m.max_gap_error <= gap_tolerance},
      {"linear residual", m.max_residual, linear_tolerance, no_force || m.max_residual <= linear_tolerance},
      {"residual", m.max_residual, residual_tolerance, corrected && m.max_residual <= residual_tolerance},
      {"correction", m.max_correction, correction_tolerance, corrected && m.max_correction <= correction_tolerance},
  }};
  const auto& [status, compatibility, linear, residual, correction] = c.criteria;
  // Abaqus accepts a residual R_l times smaller without the correction test.
  c.converged = status.pass && compatibility.pass && (linear.pass || (residual.pass && correction.pass));
  return c;
}

}  // namespace inpact::solver
