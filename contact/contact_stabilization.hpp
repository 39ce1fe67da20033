#pragma once
/// Contact stabilization, as Abaqus/Standard has it [IG "Stabilization for general contact in
/// Abaqus/Standard"; IG ctc_contactcontrols_std "Automatic stabilization of rigid body motions
/// in contact problems"]: viscous damping of the relative motion of nearby surfaces,
///     σ_stab = s_const s_ampl s_incr s_gap c_d v_N,   τ_stab = s_const s_ampl s_incr s_gap s_tang c_d v_T,
/// with v = Δu_rel/Δt in a static step (Δu_rel over the increment), so the damping acts as a
/// stiffness k = s c_d/Δt on the increment's relative displacement. Both deck forms make one
/// StabilizationRule per interaction and step (resolve_stabilization):
///   *CONTACT STABILIZATION: s_const = SCALE FACTOR (1), s_tang = TANGENT FRACTION (0),
///     s_ampl = AMPLITUDE or 1 → 0 linearly over the step, s_incr = (REDUCTION PER INCREMENT)^(n−1)
///     with n the increment of the step (default 0.1), RANGE the clearance of s_gap = 0;
///   *CONTACT CONTROLS, STABILIZE=s: s_const = s, s_tang = TANGENT FRACTION (1), s_ampl from 1
///     at the step start linearly to the data line's end factor (0), no s_incr, c_d from its data
///     line when given, its range; this step only.
/// s_gap is 1 for a closed (or penetrating) node and falls linearly from 1 at zero clearance to
/// 0 at the range (inpact's reading of "the clearance at which the stabilization becomes zero").
///
/// The automatic damping coefficient: Abaqus states c_d = φ k_rep T, "a fixed, small fraction φ
/// times a representative stiffness of the elements underlying the contact surfaces times the
/// step's time period" and does not publish φ. inpact: k_rep = k_e (the interaction's element
/// stiffness, pressure per length, contact/normal_behavior.hpp) and φ = kContactDampingFraction:
/// over an increment of the whole step (Δt = T) the damping stiffness is 1e-3 k_e, 1e-4 of
/// Abaqus's default penalty stiffness 10 k_e, so it holds a free body without competing with
/// contact once it touches; it grows as T/Δt when the increment is cut back.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "contact/interaction_table.hpp"
#include "contact/vec3.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// φ of c_d = φ k_e T (see above; inpact's choice).
inline constexpr double kContactDampingFraction = 1e-3;

/// One interaction's contact stabilization in one step.
struct StabilizationRule {
  bool pairwise = false;            ///< *CONTACT CONTROLS, STABILIZE (else *CONTACT STABILIZATION)
  double coefficient = 0.0;         ///< c_d (pressure × time per length)
  bool coefficient_given = false;   ///< from the *CONTACT CONTROLS data line (else φ k_e T)
  double scale = 1.0;               ///< s_const
  double tangent_fraction = 0.0;    ///< s_tang
  double range = 0.0;               ///< clearance at which s_gap reaches 0
  double end_factor = 0.0;          ///< s_ampl at the step end without an amplitude
  std::string amplitude;            ///< AMPLITUDE= (s_ampl(t)); empty: the linear ramp
  double reduction_per_increment = 1.0;  ///< s_incr = r^(n−1); 1: none

  /// s_const s_ampl s_incr for the increment n (1-based) ending at step time t of period T;
  /// `amplitude_value`: the named amplitude at t (used only when `amplitude` is set).
  double scale_at(double t, double period, int increment, double amplitude_value) const;
};

/// The rule in force for row `row` of `table` in step `step` (0-based), or none. k_e and l_char
/// are the row's (the default range is l_char). Throws InteractionError when the automatic
/// coefficient has no k_e to scale from.
std::optional<StabilizationRule> resolve_stabilization(const model::Model& model, const InteractionTable& table,
                                                       std::size_t row, std::size_t step, double ke, double l_char);

/// The text `inpact check` and the run print for a rule.
std::string describe(const StabilizationRule& rule);

/// s_gap: 1 at g <= 0, linear to 0 at g = range; and its slope ds/dg.
double gap_factor(double gap, double range);
double gap_factor_slope(double gap, double range);

/// The damping of one slave node: its relative displacement over the increment measured by the
/// gap gradient B_n = ∇g (slave and master blocks, `dim` components each) and the tangential
/// rows B_tα (block b: (∇g_b·n) t_α, so a rigid translation has none), with the stiffness
/// k = s c_d / Δt on the normal part and s_tang k on the tangential part:
///     f = A k s_gap(g) [ (B_n·Δu) B_n + s_tang Σ_α (B_tα·Δu) B_tα ]
/// `tangent`: ∂f/∂u for the kinematics (B, n, t) held fixed, with g moving as B_n·u (the
/// s_gap slope term included), dense row-major n×n; `dissipated`: f·Δu.
struct DampingContribution {
  std::vector<double> force, tangent;
  double dissipated = 0.0;
};
struct DampingInput {
  std::span<const double> gradient;  ///< B_n
  Vec3 normal{}, t1{}, t2{};
  int dim = 3;
  std::span<const double> du;        ///< u − u_start on the same unknowns
  double area = 0.0, gap = 0.0, range = 0.0;
  double stiffness = 0.0;            ///< k = s c_d / Δt
  double tangent_fraction = 0.0;
};
void damping_contribution(const DampingInput& in, DampingContribution& out);

}  // namespace inpact::contact
