#pragma once
/// Abaqus's default convergence criteria for a displacement field ([AX] "Convergence criteria
/// for nonlinear problems"), as a list of small records, and the force they are measured against:
///  - residual:   r_max ≤ R_n q̃, with q̃ the force magnitude averaged over the step so far;
///  - linear:     r_max ≤ R_l q̃ is accepted outright (no correction test), and so is any
///                residual when nothing loads the model (q̃ = 0);
///  - correction: c_max ≤ C_n Δu_max, the largest correction against the largest increment of u;
///  - contact:    no contact status change, and every closed multiplier node on its constraint,
///                |g + h(p)| ≤ C_ε Δu_max + 1e-14 (direct: |g|; C_ε = 1e-3, the contact
///                compatibility tolerance).
/// The residual and correction tests need a correction, so they pass only from iteration 1 on.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>

#include "assembler.hpp"
#include "dof_map.hpp"
#include "solution_controls.hpp"

namespace inpact::solver {

/// One convergence test: the measured value, what it is held against, and whether it passes.
struct Criterion {
  std::string_view name;
  double value = 0.0;
  double tolerance = 0.0;
  bool pass = false;
};

/// q̃'s history over the step: the sum and count of q over its converged increments.
struct TimeAveragedForce {
  double sum = 0.0;
  int count = 0;
  /// q̃ with the current increment counting with `increment_force`.
  double with(double increment_force) const { return (sum + increment_force) / (count + 1); }
  /// A converged increment joins the average.
  void add(double increment_force) {
    sum += increment_force;
    ++count;
  }
};

/// The q an increment counts with in q̃: the largest element-and-load q of its iterations so far
/// (a rigid-body move ends with nearly no force at all; measured against its own round-off it
/// would never converge, against the forces its first iteration met, it does), or this
/// iteration's q with the contact forces, if larger. Contact forces count only in the iteration
/// that has them: a stiff penalty's first-iteration spike (an overclosure times 1000 k_e) would
/// otherwise loosen the test for the whole increment and accept a residual the size of a node's
/// force.
class IncrementForce {
 public:
  /// The increment's q after an iteration with these q's (without and with contact forces).
  double update(double q_without_contact, double q_with_contact) {
    largest_ = std::max(largest_, q_without_contact);
    return std::max(largest_, q_with_contact);
  }

 private:
  double largest_ = 0.0;
};

/// Abaqus's q of one iteration: the spatial average of the force magnitudes over the model,
/// element nodal forces and applied loads together (without the applied loads the first
/// iteration of a load-driven increment would see no force at all), and the contact forces
/// (`contact_sum` over `contact_count` entries): an interference fit with no applied load has
/// nothing else at its first iteration, and measured against zero it would "converge" with the
/// overclosure in place.
double average_force(const AssemblyResult& assembly, std::span<const double> f_ext, double contact_sum,
                     std::size_t contact_count);

/// Largest |r| over the equations, and the DOF it sits on. `r` is the reduced residual (one
/// entry per equation): a free DOF that masters *EQUATION dependents carries their residual
/// too, and only that sum vanishes at equilibrium. NaN counts as the largest.
std::pair<double, std::int64_t> largest_residual(const DofMap& dofs, std::span<const double> r);

/// Largest |u − u_start|: the increment of u the correction is measured against.
double largest_increment(std::span<const double> u, std::span<const double> u_start);

/// What one iteration measured.
struct IterationMeasures {
  int iteration = 0;            ///< 0 before the first correction
  double max_residual = 0.0;    ///< r_max
  double q = 0.0;               ///< q̃
  double max_correction = 0.0;  ///< c_max, |largest correction| of the last solve
  double max_increment = 0.0;   ///< Δu_max
  bool contact_status_changed = false;  ///< a contact status changed (or chatters) this iteration
  double max_gap_error = 0.0;           ///< largest |g + h(p)| of a closed multiplier node (direct: |g|)
};

struct ConvergenceCheck {
  /// contact status, contact compatibility, linear residual, residual, correction.
  std::array<Criterion, 5> criteria;
  bool converged = false;
};

/// The criteria at `m` under `controls`: converged when contact passes and either the linear
/// residual test or both the residual and the correction tests do.
ConvergenceCheck check_convergence(const IterationMeasures& m, const SolutionControls& controls);

}  // namespace inpact::solver
