#include "convergence.hpp"

#include <algorithm>
#include <cmath>

namespace inpact::solver {

PerField average_force(const AssemblyResult& assembly, const DofMap& dofs, std::span<const double> f_ext,
                       double contact_sum, std::size_t contact_count) {
  PerField sum{}, count{};
  for (std::size_t f = 0; f < kFields; ++f) {
    sum[f] = assembly.average_force[f] * static_cast<double>(assembly.n_force_entries[f]);
    count[f] = static_cast<double>(assembly.n_force_entries[f]);
  }
  sum[kDisplacementField] += contact_sum;
  count[kDisplacementField] += static_cast<double>(contact_count);
  for (std::size_t d = 0; d < f_ext.size(); ++d)
    if (f_ext[d] != 0.0) {
      const Field field = dofs.field(static_cast<std::int64_t>(d));
      sum[field] += std::abs(f_ext[d]);
      count[field] += 1.0;
    }
  PerField q{};
  for (std::size_t f = 0; f < kFields; ++f) q[f] = count[f] > 0 ? sum[f] / count[f] : 0.0;
  return q;
}

PerField coupled_fields(const PerField& q, double length) {
  if (!(length > 0.0)) return q;
  constexpr double kZeroFlux = 1e-5;
  const double as_force = q[kRotationField] / length, as_moment = q[kDisplacementField] * length;
  PerField coupled = q;
  if (q[kDisplacementField] < kZeroFlux * as_force) coupled[kDisplacementField] = as_force;
  if (q[kRotationField] < kZeroFlux * as_moment) coupled[kRotationField] = as_moment;
  return coupled;
}

FieldMaxima largest_residual(const DofMap& dofs, std::span<const double> r) {
  FieldMaxima worst;
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d) {
    if (dofs.kind(d) != DofMap::Kind::Free) continue;
    const Field field = dofs.field(d);
    const double v = std::abs(r[dofs.equation(d)]);
    if (!(v <= worst.value[field])) {  // also catches NaN
      worst.value[field] = v;
      worst.dof[field] = d;
    }
  }
  return worst;
}

PerField largest_increment(const DofMap& dofs, std::span<const double> u, std::span<const double> u_start) {
  PerField largest{};
  for (std::size_t d = 0; d < u.size(); ++d) {
    double& field = largest[dofs.field(static_cast<std::int64_t>(d))];
    field = std::max(field, std::abs(u[d] - u_start[d]));
  }
  return largest;
}

ConvergenceCheck check_convergence(const IterationMeasures& m, const SolutionControls& controls) {
  // C_ε = 1e-3: Abaqus's contact compatibility tolerance (*CONTROLS, PARAMETERS=FIELD).
  const double gap_tolerance = 1e-3 * m.max_increment[kDisplacementField] + 1e-14;
  const bool corrected = m.iteration > 0;
  ConvergenceCheck c;
  c.criteria[0] = {"contact status", m.contact_status_changed ? 1.0 : 0.0, 0.0, !m.contact_status_changed};
  c.criteria[1] = {"contact compatibility", m.max_gap_error, gap_tolerance, m.max_gap_error <= gap_tolerance};
  c.converged = c.criteria[0].pass && c.criteria[1].pass;
  static constexpr std::array<std::array<const char*, 3>, kFields> kNames{
      {{"linear residual", "residual", "correction"}, {"moment linear residual", "moment residual", "rotation correction"}}};
  for (std::size_t f = 0; f < kFields; ++f) {
    const bool no_force = m.q[f] <= 0.0;  // nothing loads the field: equilibrium is exact or nothing
    const double linear_tolerance = controls.linear_tolerance * m.q[f];
    const double residual_tolerance = controls.residual_tolerance * m.q[f];
    const double correction_tolerance = controls.correction_tolerance * m.max_increment[f];
    Criterion& linear = c.criteria[2 + 3 * f];
    Criterion& residual = c.criteria[3 + 3 * f];
    Criterion& correction = c.criteria[4 + 3 * f];
    linear = {kNames[f][0], m.max_residual[f], linear_tolerance, no_force || m.max_residual[f] <= linear_tolerance};
    residual = {kNames[f][1], m.max_residual[f], residual_tolerance,
                corrected && m.max_residual[f] <= residual_tolerance};
    correction = {kNames[f][2], m.max_correction[f], correction_tolerance,
                  corrected && m.max_correction[f] <= correction_tolerance};
    // Abaqus accepts a residual R_l times smaller without the correction test.
    c.converged = c.converged && (linear.pass || (residual.pass && correction.pass));
  }
  return c;
}

}  // namespace inpact::solver
