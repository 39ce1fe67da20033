#pragma once
/// Every contact interaction of a step resolved into the values the analysis enforces: the
/// method and why, the law, k_e, the penalty stiffness, the characteristic length, the
/// augmented-Lagrange tolerance, HCRIT, friction, gap offsets, the weight of a balanced row and
/// smoothing. One function (resolve_interactions) makes these records and one (describe) prints
/// them: `inpact check`, `inpact run` (its messages), the results file and the .dat header all
/// show the same text, so a datacheck cannot disagree with the analysis.
///
/// Resolution order for one row of the interaction table (interaction_table.hpp):
///   1. the step's *CONTACT CONTROLS for the pair (pair-specific over global, carried over from
///      earlier steps until RESET);
///   2. the normal behaviour Abaqus would choose (normal_behavior.hpp; self-contact: augmented
///      Lagrange by default);
///   3. k_e and the characteristic length from the slave surface (the master when the slave is
///      node based), k_e with the softer of the two surfaces' moduli; a balanced two-row
///      general-contact interaction takes the mean of both surfaces' scales, so both rows hold
///      one law and report the pressure that acts;
///   4. the law (pressure_overclosure.hpp) and the enforcement (enforcement.hpp): direct
///      multipliers, a penalty-type law, a law stiffer than 1000 k_e with multipliers (table
///      38.1.21), augmented Lagrange; a balanced interaction whose law needs multipliers keeps
///      its first row with the whole weight (two multipliers on one gap would be redundant);
///   5. HCRIT (half the characteristic length unless given; none for softened laws), friction
///      (friction.hpp) with γ_crit from the same length, the gap offsets (*CLEARANCE, or
///      CalculiX's TIED law binding each node where it starts).
/// The interaction a row refers to is the one in force in the step (step_changes.hpp: the latest
/// *CHANGE FRICTION and *CHANGE SURFACE BEHAVIOR up to it); a *CONTACT PAIR that *MODEL CHANGE
/// removed has no record in that step.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/contact_stabilization.hpp"
#include "contact/friction.hpp"
#include "contact/interaction_table.hpp"
#include "contact/normal_behavior.hpp"
#include "contact/pressure_overclosure.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// How the normal constraint of a row is enforced, as the analysis does it.
enum class EnforcementKind : std::uint8_t {
  DirectMultipliers,   ///< hard contact, one Lagrange multiplier per closed slave node
  PenaltyLaw,          ///< a penalty-type or softened law, no multipliers
  LawWithMultipliers,  ///< a law with slope > 1000 k_e, its compliance on the multiplier's diagonal
  AugmentedLagrange,   ///< the linear penalty law with a multiplier λ updated by augmentations
};

/// What is added to each slave node's measured gap.
enum class GapOffsets : std::uint8_t {
  None,
  Clearance,   ///< *CLEARANCE: the reference gap becomes the clearance given
  InitialGap,  ///< CalculiX's TIED law: the reference gap becomes zero
};

/// *CHANGE FRICTION in this step, Abaqus's transition [K16 *CHANGE FRICTION]: μ and the allowable
/// elastic slip go from the previous step's values to the new ones as the step's amplitude (RAMP:
/// t/T; or AMPLITUDE=) goes from 0 to 1, a(t): μ(t) = μ₀ + a(t) (μ₁ − μ₀), the same for γ_crit
/// (inpact's reading of "transitions ... occur according to the amplitude", UNCONFIRMED for a
/// named amplitude). Every other property changes at once. With *STEP, AMPLITUDE=STEP, or when
/// μ and γ_crit do not change, there is no ramp (CalculiX changes at once too).
struct FrictionRamp {
  std::optional<FrictionLaw> from;  ///< the law at the end of the previous step (unset: frictionless)
  std::string amplitude;            ///< AMPLITUDE= of *CHANGE FRICTION; empty: the step's ramp t/T
};

/// One row of the interaction table as step `step` enforces it.
struct ResolvedInteraction {
  std::size_t row = 0;    ///< into InteractionTable::rows
  std::size_t step = 0;   ///< 0-based
  std::string name;       ///< "SLAVE/MASTER"
  bool general = false, self_contact = false, surface_to_surface = false, finite_sliding = true;
  /// False for the second row of a balanced interaction enforced with multipliers (its first
  /// row carries the whole weight).
  bool in_force = true;

  ResolvedNormalBehavior behavior;
  EnforcementKind enforcement = EnforcementKind::DirectMultipliers;
  std::optional<PressureOverclosure> law;  ///< unset: direct hard contact
  bool augmented = false;       ///< λ augmentations (augmented Lagrange, with or without multipliers)
  bool no_separation = false;   ///< a closed node never opens (NO SEPARATION, TIED pairs and law)
  bool tied_pair = false;       ///< *CONTACT PAIR, TIED: direct, never separating, ROUGH
  bool tied_law = false;        ///< CalculiX PRESSURE-OVERCLOSURE=TIED: closed in tension too
  bool user_adaptive = false;   ///< USER ADAPTIVE stiffness in the first increment (no multipliers)

  double ke = 0.0;              ///< representative element stiffness (0: none, node-based surfaces)
  double l_char = 0.0;          ///< characteristic interface length
  bool scales_from_mesh = false;  ///< k_e and l_char from element faces (else l_char is the search radius)
  double tolerance = 0.0;       ///< augmented Lagrange: the penetration tolerance (a length)
  double hcrit = 0.0;           ///< largest penetration one attempt may add (∞: softened laws)
  std::optional<FrictionLaw> friction;  ///< unset: frictionless (at the end of the step, with a ramp)
  std::optional<FrictionRamp> friction_ramp;  ///< set when a *CHANGE FRICTION of this step ramps μ, γ_crit
  GapOffsets offsets = GapOffsets::None;
  double weight = 1.0;          ///< balanced master-slave or self-contact: ½
  double thickness = 1.0;       ///< out-of-plane thickness of a 2-D interaction
  bool smoothed = false;        ///< geometric correction of either surface
  /// *CONTACT STABILIZATION or *CONTACT CONTROLS, STABILIZE in force (contact_stabilization.hpp).
  std::optional<StabilizationRule> stabilization;

  /// The friction law at amplitude value a (0: the step start, 1: the new values): `friction`
  /// without a ramp.
  std::optional<FrictionLaw> friction_at(double a) const;
};

/// Contact data that contradicts the mesh or asks for what the analysis cannot give (a default
/// penalty stiffness without an elastic element-based surface, ROUGH friction without k_e,
/// self-contact with direct enforcement, NO SEPARATION with a penalty law). The caller reports
/// it as `file:line:col: error: KEYWORD: what()`.
struct InteractionError : std::runtime_error {
  InteractionError(const std::string& what, model::SourceLoc where, std::string kw)
      : std::runtime_error(what), loc(where), keyword(std::move(kw)) {}
  model::SourceLoc loc;
  std::string keyword;
};

/// The rows of `table` in force in step `step` (0-based), resolved. Throws InteractionError.
std::vector<ResolvedInteraction> resolve_interactions(const model::Model& model, const InteractionTable& table,
                                                      std::size_t step);

/// Does *CLEARANCE `c` name `pair` (its slave and master)?
inline bool clearance_names(const model::Clearance& c, const model::ContactPair& pair) {
  return c.slave == pair.slave && c.master == pair.master;
}

/// The name a surface has in the deck ("" for a body exterior general contact made): what the
/// smoothing lines are matched with (geometric_correction.hpp corrections_for).
std::string deck_surface_name(const model::Model& model, const model::Surface* surface);

/// The records of every step, index = step.
std::vector<std::vector<ResolvedInteraction>> resolve_all_steps(const model::Model& model,
                                                                const InteractionTable& table);

/// The one text of a record (check, run, results file, .dat): what is enforced, with values.
std::string describe(const ResolvedInteraction& r);

/// describe() of every record in force, in row order.
std::vector<std::string> describe(const std::vector<ResolvedInteraction>& records);

}  // namespace inpact::contact
