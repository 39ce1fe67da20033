#pragma once
/// The normal contact behaviour Abaqus/Standard would use for an interaction in a given
/// formulation: the enforcement method, the penalty stiffness rule, whether Lagrange multipliers
/// are used and the augmented-Lagrange penetration tolerance. Source: [AX] = reference/
/// abaqus-contact-enforcement-and-smoothing.md (§38.1.2 end, table 38.1.21) and
/// parser/KEYWORDS.md Part C. The mesh-dependent scales (k_e, characteristic length) are
/// computed by the functions at the end.
#include <optional>
#include <string>

#include "model/model.hpp"

namespace inpact::contact {

/// Formulation details that change the defaults but are not in every call.
struct NormalBehaviorOptions {
  /// The step's *CONTACT CONTROLS that apply to this pair (pair-specific over global), or null.
  const model::ContactControls* controls = nullptr;
  /// Three-dimensional self-contact with node-to-surface discretisation: Abaqus's default is
  /// augmented Lagrange there ([AX p.782]).
  bool self_contact_3d = false;
};

struct ResolvedNormalBehavior {
  /// The deck's *SURFACE BEHAVIOR, or the default (hard contact, default method) when absent.
  model::SurfaceBehavior deck;
  model::PressureOverclosure law = model::PressureOverclosure::Hard;
  model::EnforcementMethod method = model::EnforcementMethod::Direct;  ///< never Default
  bool method_is_default = true;  ///< chosen by the formulation table, not by the deck
  std::string method_reason;      ///< why this method, for `inpact check`

  /// Penalty-type methods: the penalty stiffness is `given_stiffness` when the deck gives one,
  /// else `default_factor × k_e`, times `scale_factor` either way. PENALTY=NONLINEAR: this is the
  /// final stiffness K_f; K_i = initial_final_ratio × K_f. Units: pressure per overclosure.
  std::optional<double> given_stiffness;
  double default_factor = 0.0;  ///< 10 (linear penalty), 100 (nonlinear K_f), 1000 (augmented)
  double scale_factor = 1.0;    ///< *SURFACE BEHAVIOR factor × *CONTACT CONTROLS factor
  bool user_adaptive_stiffness = false;  ///< *CONTACT CONTROLS, STIFFNESS SCALE FACTOR=USER ADAPTIVE

  // PENALTY=NONLINEAR, with Abaqus's defaults [IG], [ABQPY].
  double initial_final_ratio = 0.01;
  double upper_quadratic_limit = 0.03;       ///< × characteristic length
  double lower_quadratic_ratio = 1.0 / 3.0;  ///< × the upper limit

  /// Augmented Lagrange only: the penetration tolerance is `tolerance` × characteristic length
  /// when relative, `tolerance` itself when absolute. Unset for every other method.
  std::optional<double> tolerance;
  bool tolerance_is_absolute = false;
  bool tolerance_is_default = true;
};

/// What Abaqus/Standard would do for `interaction` (null: no *SURFACE BEHAVIOR, i.e. hard
/// contact) in a pair of the given discretisation and sliding, or in general contact.
/// Default methods (KEYWORDS.md Part C d): node-to-surface → direct (3-D self-contact:
/// augmented Lagrange); finite-sliding surface-to-surface → linear penalty; general contact →
/// linear penalty; small sliding → direct; softened laws → direct only.
ResolvedNormalBehavior resolve_normal_behavior(const model::SurfaceInteraction* interaction,
                                               model::ContactDiscretization discretization,
                                               bool small_sliding, bool general_contact,
                                               const NormalBehaviorOptions& options = {});

/// The penalty stiffness (pressure per overclosure) for an underlying element stiffness `ke`;
/// 0 for direct enforcement.
double penalty_stiffness(const ResolvedNormalBehavior& r, double ke);

/// Table 38.1.21: are Lagrange multipliers used where the contact slope is `slope`? Direct hard
/// contact: always. Penalty and augmented Lagrange on hard contact: when k_penalty > 1000 k_e
/// (the law's slope; `slope` is not needed). Softened laws: where the slope of the
/// pressure-overclosure law (`slope`, its steepest at zero clearance) exceeds 1000 k_e. The
/// analysis decides with this function (contact/resolved_interaction.cpp).
bool uses_lagrange_multipliers(const ResolvedNormalBehavior& r, double ke, double slope = 0.0);

/// The augmented-Lagrange penetration tolerance (a length) for a characteristic interface
/// length `l_char`; nullopt for other methods.
std::optional<double> penetration_tolerance(const ResolvedNormalBehavior& r, double l_char);

/// Mesh scales of a contact surface, from its element faces (nullopt: a node-based surface, or
/// no face lies on an element with an elastic material — the caller falls back to the other
/// surface of the pair).
struct SurfaceScales {
  double element_stiffness = 0.0;      ///< k_e, pressure per length
  double modulus = 0.0;                ///< median constrained modulus M of the facets' elements
  double characteristic_length = 0.0;  ///< median facet size
  std::size_t n_facets = 0;
};

/// k_e and the characteristic length of `surface`. Abaqus computes both but does not publish
/// how (KEYWORDS.md Part C a); inpact's estimators are documented in normal_behavior.cpp.
std::optional<SurfaceScales> surface_scales(const model::Model& model, const model::Surface& surface);

/// k_e of `own` taken with the softer of the two surfaces' materials: own.k_e × M_other / M_own
/// when the other side is softer, own.k_e otherwise. A penalty's error and its round-off
/// (k ε L) are measured against the body that deforms: a stiff slave's k_e on a soft master
/// (E 1e6 apart) gave augmented Lagrange a stiffness whose round-off pressure was 0.25 % of p.
/// The slave's own facets keep the length scale (the contact zone's mesh).
double softer_element_stiffness(const SurfaceScales& own, const SurfaceScales& other);


}  // namespace inpact::contact
