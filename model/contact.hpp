#pragma once
/// Contact definitions as the deck states them: interactions (*SURFACE INTERACTION with
/// *SURFACE BEHAVIOR and *FRICTION), contact pairs, general contact, smoothing and clearances.
/// Defaults that depend on the mesh (penalty stiffness, tolerances) are left unset here and
/// resolved by contact/ (see contact/normal_behavior.hpp), so `inpact check` can show both.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "source_loc.hpp"

namespace inpact::model {

/// PRESSURE-OVERCLOSURE. Tied is CalculiX's bonded law (*SURFACE BEHAVIOR,
/// PRESSURE-OVERCLOSURE=TIED with a stiffness; the tangential stiffness is *FRICTION's stick slope).
enum class PressureOverclosure : std::uint8_t { Hard, Exponential, Linear, Tabular, Tied };

/// How a hard (or softened) contact constraint is enforced. Default: what Abaqus picks for the
/// formulation (penalty for finite-sliding surface-to-surface and general contact, else direct).
enum class EnforcementMethod : std::uint8_t {
  Default,
  Direct,
  PenaltyLinear,
  PenaltyNonlinear,
  AugmentedLagrange
};

/// *SURFACE BEHAVIOR.
struct SurfaceBehavior {
  PressureOverclosure pressure_overclosure = PressureOverclosure::Hard;
  EnforcementMethod method = EnforcementMethod::Default;
  bool no_separation = false;

  // Hard contact with PENALTY (linear or nonlinear) or AUGMENTED LAGRANGE, data line fields.
  std::optional<double> penalty_stiffness;  ///< unset: default from the underlying element stiffness
  double clearance_at_zero_pressure = 0.0;
  double stiffness_scale_factor = 1.0;
  // PENALTY=NONLINEAR only; unset fields take Abaqus's defaults (resolved in contact/).
  std::optional<double> initial_final_stiffness_ratio;
  std::optional<double> upper_quadratic_limit_scale_factor;
  std::optional<double> lower_quadratic_limit_ratio;

  // Softened contact. Units: pressure per overclosure (force per overclosure for node-based
  // surfaces), as for the penalty stiffness.
  double exponential_c0 = 0.0;  ///< EXPONENTIAL: clearance at which pressure is zero (Abaqus meaning)
  double exponential_p0 = 0.0;  ///< EXPONENTIAL: pressure at zero clearance
  std::optional<double> linear_slope;  ///< LINEAR: k (CalculiX: k, σ∞, c0 follow)
  std::optional<double> linear_sigma_inf;  ///< CalculiX LINEAR: tension limit σ∞
  std::optional<double> linear_c0;         ///< CalculiX LINEAR: c0
  /// TABULAR: (pressure, overclosure) pairs in ascending overclosure, pressure increasing; zero
  /// pressure below the first overclosure, the last slope continued beyond the last point.
  std::vector<std::array<double, 2>> table;
  std::optional<double> tied_slope;          ///< CalculiX TIED: k

  SourceLoc loc;
};

/// *FRICTION: isotropic Coulomb friction.
struct Friction {
  double mu = 0.0;
  bool rough = false;     ///< ROUGH: no slip at all
  bool lagrange = false;  ///< LAGRANGE: stick enforced with multipliers instead of elastic slip
  std::optional<double> slip_tolerance;  ///< SLIP TOLERANCE (fraction of characteristic length)
  std::optional<double> elastic_slip;    ///< ELASTIC SLIP (absolute)
  std::optional<double> stick_slope;     ///< CalculiX: stick slope on the data line
  SourceLoc loc;
};

/// *SURFACE INTERACTION with its options.
struct SurfaceInteraction {
  std::string name;
  std::optional<SurfaceBehavior> behavior;  ///< unset: hard contact, default method
  std::optional<Friction> friction;         ///< unset: frictionless
  double out_of_plane_thickness = 1.0;      ///< data line (2D): contact area per unit length
  /// TRACKING THICKNESS: how far COPEN is tracked beyond the contact (unset: Abaqus's own).
  std::optional<double> tracking_thickness;
  SourceLoc loc;
};

enum class ContactDiscretization : std::uint8_t { NodeToSurface, SurfaceToSurface };

/// *CONTACT PAIR data line under its parameters.
struct ContactPair {
  std::string slave;   ///< upper-case surface names
  std::string master;
  std::string interaction;
  ContactDiscretization type = ContactDiscretization::NodeToSurface;
  bool small_sliding = false;
  /// ADJUST: absent; a distance (slave nodes within it are moved onto the master); or a node set.
  std::optional<double> adjust_distance;
  std::string adjust_nset;
  std::string geometric_correction;  ///< name of a *SURFACE SMOOTHING definition
  bool tied = false;  ///< TIED: the surfaces are bonded once adjusted (needs ADJUST)
  /// EXTENSION ZONE: fraction of the end master facet's length the master surface is extended by
  /// (node-to-surface; Abaqus default 0.1).
  double extension_zone = 0.1;
  /// HCRIT: largest penetration allowed in one iteration before the increment is cut back
  /// (unset: half a characteristic slave face length, Abaqus's default).
  std::optional<double> hcrit;
  /// SMOOTH: fraction of a master facet over which finite-sliding node-to-surface smooths the
  /// master normal between facets (Abaqus default 0.2).
  double smooth = 0.2;
  /// CalculiX LINEAR flag: the pair does not switch on nonlinear geometry.
  bool linear = false;
  /// NO THICKNESS: shell surfaces meet at their reference surface, not offset by half the
  /// shell thickness (Abaqus's default, which inpact does not model yet).
  bool no_thickness = false;
  SourceLoc loc;  ///< the data line's slave surface
  /// Where the names given as parameters are written (the values of INTERACTION=, GEOMETRIC
  /// CORRECTION= and ADJUST= on the keyword line): an undefined name is reported there.
  SourceLoc interaction_loc, geometric_correction_loc, adjust_loc;
};

/// One *SURFACE PROPERTY ASSIGNMENT, PROPERTY=GEOMETRIC CORRECTION data line, or one line of a
/// *SURFACE SMOOTHING definition.
struct GeometricCorrection {
  enum class Kind : std::uint8_t { Circumferential, Spherical, Toroidal } kind;
  std::string surface;
  std::array<double, 3> a{0, 0, 0};  ///< axis point (or sphere centre)
  std::array<double, 3> b{0, 0, 0};  ///< second axis point
  double radius = 0.0;               ///< TOROIDAL: distance of the arc centre from the axis
  SourceLoc loc;
};

struct SurfaceSmoothing {
  std::string name;
  std::vector<GeometricCorrection> corrections;
  SourceLoc loc;
};

/// *CONTACT with its sub-options (general contact). Empty surface names mean "all exterior".
struct GeneralContact {
  /// One *CONTACT INCLUSIONS / EXCLUSIONS line. An empty name is the all-inclusive exterior
  /// surface (both empty: ALL EXTERIOR self-contact); self-contact of a surface has
  /// second == first (written `surf,` or `surf, surf`).
  struct Inclusion {
    std::string first, second;
    SourceLoc loc;
  };
  struct PropertyAssignment {
    std::string first, second;  ///< empty: the global assignment
    std::string interaction;
    SourceLoc loc;
    SourceLoc interaction_loc;  ///< the data line's third field, which names the interaction
  };
  bool defined = false;
  std::vector<Inclusion> inclusions;
  std::vector<Inclusion> exclusions;
  std::vector<PropertyAssignment> property_assignments;
  std::vector<GeometricCorrection> geometric_corrections;  ///< *SURFACE PROPERTY ASSIGNMENT
  SourceLoc loc;
};

/// *CLEARANCE: initial clearance (or overclosure, negative) for the slave nodes of a pair.
struct Clearance {
  std::string slave, master;
  std::optional<double> value;  ///< VALUE=: for every slave node
  std::vector<std::pair<std::int32_t, double>> node_values;  ///< data lines: node row, clearance
  SourceLoc loc;
};

/// *CHANGE FRICTION, INTERACTION= in a step, with the *FRICTION that follows it: the friction of
/// the interaction from this step on [K16 *CHANGE FRICTION], [CCX]. RESET returns the model data's.
struct FrictionChange {
  std::string interaction;           ///< upper case
  bool reset = false;                ///< RESET: the model data's *FRICTION again (no *FRICTION follows)
  std::optional<Friction> friction;  ///< the *FRICTION that follows; unset with RESET or when none follows
  /// AMPLITUDE=: how μ and the allowable elastic slip move from their old values to the new ones
  /// over the step; empty: the step's AMPLITUDE (RAMP by default for *STATIC, STEP: at once).
  std::string amplitude;
  SourceLoc loc;              ///< the keyword line
  SourceLoc interaction_loc;  ///< the value of INTERACTION=
  SourceLoc amplitude_loc;    ///< the value of AMPLITUDE=
};

/// *CHANGE SURFACE BEHAVIOR, INTERACTION= (CalculiX) in a step, with the *SURFACE BEHAVIOR that
/// follows it: the normal behaviour of the interaction from this step on [CCX].
struct SurfaceBehaviorChange {
  std::string interaction;                  ///< upper case
  std::optional<SurfaceBehavior> behavior;  ///< unset when no *SURFACE BEHAVIOR follows
  SourceLoc loc, interaction_loc;
};

/// One data line of *MODEL CHANGE, TYPE=CONTACT PAIR, ADD | REMOVE: a *CONTACT PAIR removed from
/// this step on, or reactivated [K16 *MODEL CHANGE], [IG ctc_contactpair_std].
struct ContactPairChange {
  std::string slave, master;  ///< upper case
  bool add = false;           ///< ADD (reactivate); else REMOVE
  SourceLoc loc;              ///< the data line's slave surface
};

/// *CONTACT CONTROLS within a step (applies to one pair, or to all when master/slave empty).
struct ContactControls {
  std::string master, slave;
  std::optional<double> absolute_penetration_tolerance;
  std::optional<double> relative_penetration_tolerance;
  std::optional<double> stiffness_scale_factor;
  /// STIFFNESS SCALE FACTOR=USER ADAPTIVE: reduced penalty stiffness in the early iterations of
  /// the first increment, the full stiffness for its final iterations [AX p.781].
  bool user_adaptive_stiffness = false;
  bool reset = false;
  /// STABILIZE[=factor] (the flag: 1): viscous contact damping of this step only, the pair-wise
  /// form of *CONTACT STABILIZATION (contact/contact_stabilization.hpp) [IG ctc_contactcontrols_std].
  std::optional<double> stabilize;
  std::optional<double> tangent_fraction;        ///< TANGENT FRACTION (default 1 with STABILIZE)
  std::optional<double> stabilize_coefficient;   ///< data line 1 field 1: the damping coefficient c_d
  std::optional<double> stabilize_end_factor;    ///< field 2: the ramp's value at the step end (0)
  std::optional<double> stabilize_range;         ///< field 3: the clearance where damping ends
  SourceLoc loc;
};

/// *CONTACT STABILIZATION (history data) [K16 *CONTACT STABILIZATION], [IG "Stabilization for
/// general contact in Abaqus/Standard"]: viscous damping of the relative motion of nearby
/// surfaces (contact/contact_stabilization.hpp). The parameters apply to the interactions its
/// data lines name (no data line, or a blank first surface: every interaction).
struct ContactStabilizationBlock {
  std::string amplitude;                 ///< AMPLITUDE= (upper case); empty: 1 → 0 linearly over the step
  std::optional<double> range;           ///< RANGE=: the clearance where damping ends (default l_char)
  double reduction_per_increment = 0.1;  ///< REDUCTION PER INCREMENT=
  double scale_factor = 1.0;             ///< SCALE FACTOR=
  double tangent_fraction = 0.0;         ///< TANGENT FRACTION=
  bool reset = false;                    ///< RESET: no carry-over from earlier steps
  /// Data lines: (first, second) surface, upper case; "" first: all; "" second: the first.
  std::vector<std::pair<std::string, std::string>> surfaces;
  std::vector<SourceLoc> surface_locs;   ///< per data line: its first and second field
  SourceLoc loc, amplitude_loc;
};

}  // namespace inpact::model
