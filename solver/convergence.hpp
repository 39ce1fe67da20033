#pragma once
/// Abaqus's default convergence criteria ([AX] "Convergence criteria for nonlinear problems"), as
/// a list of small records, and the force they are measured against. The residual, linear and
/// correction tests apply to each field apart (fields.hpp: displacements against forces, rotations
/// against moments), with the field's own q̃, r_max, c_max and Δu_max:
///  - residual:   r_max ≤ R_n q̃, with q̃ the force magnitude averaged over the step so far;
///  - linear:     r_max ≤ R_l q̃ is accepted outright (no correction test), and so is any
///                residual when nothing loads the model (q̃ = 0);
///  - correction: c_max ≤ C_n Δu_max, the largest correction against the largest increment of u;
///  - contact:    no contact status change, and every closed multiplier node on its constraint,
///                |g + h(p)| ≤ C_ε Δu_max + 1e-14 (direct: |g|; C_ε = 1e-3, the contact
///                compatibility tolerance).
/// The residual and correction tests need a correction, so they pass only from iteration 1 on.
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include "assembler.hpp"
#include "dof_map.hpp"
#include "fields.hpp"
#include "solution_controls.hpp"

namespace inpact::solver {

/// One convergence test: the measured value, what it is held against, and whether it passes.
struct Criterion {
  std::string_view name;
  double value = 0.0;
  double tolerance = 0.0;
  bool pass = false;
};

/// q̃'s history over the step, per field: the sum and count of q over its converged increments.
struct TimeAveragedForce {
  PerField sum{};
  int count = 0;
  /// q̃ with the current increment counting with `increment_force`.
  PerField with(const PerField& increment_force) const {
    PerField q;
    for (std::size_t f = 0; f < kFields; ++f) q[f] = (sum[f] + increment_force[f]) / (count + 1);
    return q;
  }
  /// A converged increment joins the average.
  void add(const PerField& increment_force) {
    for (std::size_t f = 0; f < kFields; ++f) sum[f] += increment_force[f];
    ++count;
  }
};

/// The q an increment counts with in q̃, per field: the larger of the q its first iteration met
/// and this iteration's (with the contact forces), as Abaqus measures each iteration against its
/// own forces. The first iteration counts on: a rigid-body move ends with nearly no force at
/// all, and measured against its own round-off it would never converge; against the forces its
/// start met (the moved boundary, or the predictor's moved state) it does. The iterations between
/// do not: a beam's or shell's first correction stretches it by its linearised turn, and the
/// spike of that stretch (a thousand times the load) would loosen the test for the rest of the
/// increment and accept a residual the size of the load; a stiff penalty's first-iteration
/// contact spike (an overclosure times 1000 k_e) alike. Contact forces are in the displacement
/// field.
class IncrementForce {
 public:
  /// The increment's q after an iteration with these q's (without and with contact forces).
  PerField update(const PerField& q_without_contact, const PerField& q_with_contact) {
    // A NaN q (a point that gave up) is caught with the residual; it must not stick in first_.
    const auto finite = [](const PerField& v) { return std::isfinite(v[0]) && std::isfinite(v[1]); };
    if (!first_ && finite(q_without_contact)) first_ = q_without_contact;
    const PerField first = first_.value_or(PerField{});
    PerField q;
    for (std::size_t f = 0; f < kFields; ++f) q[f] = std::max({first[f], q_without_contact[f], q_with_contact[f]});
    return q;
  }

 private:
  std::optional<PerField> first_;
};

/// Abaqus's q of one iteration: the spatial average of the force magnitudes over the model,
/// element nodal forces and applied loads together (without the applied loads the first
/// iteration of a load-driven increment would see no force at all), and the contact forces
/// (`contact_sum` over `contact_count` entries): an interference fit with no applied load has
/// nothing else at its first iteration, and measured against zero it would "converge" with the
/// overclosure in place. Per field of `dofs`; contact forces are in the displacement field.
PerField average_force(const AssemblyResult& assembly, const DofMap& dofs, std::span<const double> f_ext,
                       double contact_sum, std::size_t contact_count);

/// q̃ per field; a field whose own flux vanishes against the other's converted by the model's
/// length scale L (the diagonal of its nodes' bounding box; a moment M on a body of size L is
/// held by forces of the order M/L), below 1e-5 of it as Abaqus's zero-flux ratio ε^α, takes that
/// converted flux instead: the translations of a strip rolled up by end moments alone, the
/// rotations of a beam pulled along its axis, are then measured against the other field's flux
/// rather than against their own round-off. Without rotations q̃ is the forces' alone.
PerField coupled_fields(const PerField& q, double length);

/// Per field, the largest magnitude over the free DOFs' equations, and the DOF it sits on.
struct FieldMaxima {
  PerField value{};
  std::array<std::int64_t, kFields> dof{-1, -1};
};

/// The largest |r|. `r` is the reduced residual (one entry per equation): a free DOF that
/// masters *EQUATION dependents carries their residual too, and only that sum vanishes at
/// equilibrium. NaN counts as the largest.
FieldMaxima largest_residual(const DofMap& dofs, std::span<const double> r);

/// Per field, the largest |u − u_start|: the increment of u the correction is measured against.
PerField largest_increment(const DofMap& dofs, std::span<const double> u, std::span<const double> u_start);

/// What one iteration measured.
struct IterationMeasures {
  int iteration = 0;              ///< 0 before the first correction
  PerField max_residual{};        ///< r_max
  PerField q{};                   ///< q̃
  PerField max_correction{};      ///< c_max, |largest correction| of the last solve
  PerField max_increment{};       ///< Δu_max
  bool contact_status_changed = false;  ///< a contact status changed (or chatters) this iteration
  double max_gap_error = 0.0;           ///< largest |g + h(p)| of a closed multiplier node (direct: |g|)
};

struct ConvergenceCheck {
  /// contact status, contact compatibility, then per field: linear residual, residual,
  /// correction (named "moment linear residual", "moment residual", "rotation correction" in
  /// the rotation field).
  std::array<Criterion, 2 + 3 * kFields> criteria;
  bool converged = false;
};

/// The criteria at `m` under `controls`: converged when contact passes and, in every field,
/// either the linear residual test or both the residual and the correction tests do.
ConvergenceCheck check_convergence(const IterationMeasures& m, const SolutionControls& controls);

}  // namespace inpact::solver
