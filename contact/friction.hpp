#pragma once
/// Isotropic Coulomb friction of one slave node of node-to-surface contact, enforced by
/// stiffness (Abaqus/Standard's default "elastic slip" penalty method).
///
/// Sources: Abaqus Theory Manual §5.2.3 "Coulomb friction" (2017:
/// https://abaqus-docs.mit.edu/2017/English/SIMACAETHERefMap/simathe-c-coulombfric.htm ;
/// 6.6: https://classes.engineering.wustl.edu/2009/spring/mase5513/abaqus/docs/v6.6/books/stm/ch05s02ath135.html):
/// no slip while τ_eq = |τ| < τ_crit = μ p; "by default, the condition of no relative motion is
/// approximated by stiff elastic behavior. The stiffness is chosen such that the relative motion
/// from the position of zero shear stress is bounded by γ_crit" (the allowable elastic slip), i.e.
/// τ = k_s γ_el with the stick stiffness k_s = τ_crit / γ_crit = μ p / γ_crit; in slip the stress
/// lies on the limit, in the direction of the elastic predictor, and the pressure contributions
/// to the linearisation are unsymmetric. parser/KEYWORDS.md *FRICTION and Part C (c):
/// γ_crit = SLIP TOLERANCE (0.005) × the characteristic contact surface length, or ELASTIC SLIP.
///
/// Kinematics (inpact's discretisation, node-to-surface). The zero-shear point ("anchor") is
/// the material point (facet, ξ₀) of the master where the slave node was projected at the start
/// of the increment, or where it first touched in this increment. Over the increment the slave
/// moves relative to it by
///   Δx = x_s − x_anchor(ξ₀)   (current coordinates),   Δs = P_T Δx,
/// P_T = t1 t1ᵀ + t2 t2ᵀ (projection.hpp's basis; 2D: t1 t1ᵀ). Since x_s − x_m(ξ) = g n is
/// normal, Δs is the tangential increment of the projected point x_m(ξ) − x_anchor(ξ₀), the
/// slip measured on the master surface. Linearisation and force distribution use
///   B = P_T [I; −N_1(ξ) I; …; −N_k(ξ) I]   over the slave and the current facet's nodes,
/// i.e. the anchor taken as the material point under the slave, to distribute the force: the
/// master's share always acts at the contact point (action = reaction), and B stays defined at
/// facet edges and vertices. The tangent is the derivative of that force (checked against
/// central differences, tests/contact/test_friction_tangent.cpp): ∂(Bᵀτ) = Dᵀ ∂τ + (∂D)ᵀ τ, with
/// ∂e_tr = P_T ∂Δx + ∂P_T (e₀ + Δx) — the anchor's own −N_a(ξ₀) on its facet, the turn of the
/// tangent plane with the facet's normal (at fixed ξ and as ξ slides, interior contact) — and
/// (∂D)ᵀτ = −τ ⊗ N_a,α ∂ξ_α/∂u, the contact point sliding over the master (lin.dxi). Left out:
/// the turn of a normal that is not the facet's own (edges, vertices, surface to surface's
/// weighted normal, a smoothed master), and an anchor on another facet than the current one.
///
/// Return mapping (backward Euler, the elastic predictor of the Theory Manual), e₀ the elastic
/// slip at the start of the increment:
///   e_tr = P_T e₀ + Δs,  k = μ p / γ_crit (or a fixed k: ROUGH, CalculiX's stick slope)
///   stick  k |e_tr| ≤ μ p:  e = e_tr,          τ = k e
///   slip   otherwise:       m = e_tr/|e_tr|,   τ = μ p m,   e = (μ p / k) m  (|e| = γ_crit)
/// τ is the frictional stress the slave exerts on the master (it points along the slip); the
/// slave carries −τ. Internal forces f = A Bᵀ τ; tangent, at fixed pressure, on a master that
/// neither moves nor turns
///   stick  A k BᵀB,   slip  A (μ p / |e_tr|) Bᵀ (P_T − m mᵀ) B   (and the terms above),
/// plus the pressure coupling A Bᵀ (∂τ/∂p) ⊗ ∂p/∂u with ∂τ/∂p = (μ/γ_crit) e (stick) or μ m
/// (slip): unsymmetric (the caller adds it; ∂p/∂u depends on the normal enforcement).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "contact/facet.hpp"
#include "contact/projection.hpp"
#include "model/model.hpp"

namespace inpact::contact {

/// *FRICTION of a pair, resolved against the pair's mesh scales.
struct FrictionLaw {
  double mu = 0.0;
  bool rough = false;             ///< ROUGH: no slip at all (stick with `fixed_stiffness`)
  double gamma_crit = 0.0;        ///< allowable elastic slip (a length)
  double fixed_stiffness = 0.0;   ///< > 0: τ = k e with this k (ROUGH; CalculiX's stick slope λ)
  bool gamma_is_absolute = false; ///< ELASTIC SLIP given
  bool lagrange = false;          ///< LAGRANGE: stick to kLagrangeSlipFraction of the length

  /// Stick stiffness k (stress per length) at pressure p, and dk/dp.
  double stiffness(double p) const { return fixed_stiffness > 0.0 ? fixed_stiffness : mu * p / gamma_crit; }
  double dstiffness_dp() const { return fixed_stiffness > 0.0 ? 0.0 : mu / gamma_crit; }
};

/// Multiple of the pair's element stiffness k_e used as the ROUGH stick stiffness: inpact's
/// choice (Abaqus enforces ROUGH with Lagrange multipliers under direct hard contact and "by
/// penalty" otherwise without publishing the stiffness; KEYWORDS.md Part C c). 1000 k_e is the
/// largest stiffness table 38.1.21 still enforces without multipliers.
inline constexpr double kRoughStiffnessFactor = 1000.0;

/// *FRICTION, LAGRANGE (sticking by multipliers in Abaqus): inpact's allowable elastic slip, as a
/// fraction of the characteristic contact length — 1e-6, against the default SLIP TOLERANCE of
/// 0.005 (a stick stiffness 5000 times larger). A documented approximation of exact sticking.
inline constexpr double kLagrangeSlipFraction = 1e-6;

/// The law of `friction` (null: no *FRICTION) for a characteristic length `l_char` and element
/// stiffness `ke`; nullopt when the contact is frictionless (no *FRICTION, or μ = 0 without
/// ROUGH). LAGRANGE is not resolved here (the solver refuses it).
std::optional<FrictionLaw> resolve_friction(const model::Friction* friction, double l_char, double ke);

/// One line for the step's messages and `inpact check`.
std::string describe(const FrictionLaw& law);

/// Where the slave node's zero-shear position lies on the master: a facet and a parametric point.
struct FrictionAnchor {
  std::int32_t facet = -1;  ///< index into the master facets; −1: none (not in contact)
  std::array<double, 2> xi{0.0, 0.0};
};

/// The return mapping of one slave node at one iteration.
struct FrictionPoint {
  bool slipping = false;
  Vec3 trial_slip{};       ///< e_tr, the elastic predictor
  Vec3 slip_increment{};   ///< Δs, tangential motion relative to the master since the anchor
  Vec3 elastic_slip{};     ///< e after the return mapping
  Vec3 traction{};         ///< τ, on the master (the slave carries −τ)
  int n_dof = 0;
  std::vector<double> force;     ///< Bᵀ τ (n_dof): the internal force per unit area
  std::vector<double> tangent;   ///< Bᵀ ∂τ/∂u at fixed pressure (n_dof × n_dof, row-major)
  std::vector<double> coupling;  ///< Bᵀ ∂τ/∂p (n_dof): times ∂p/∂u gives the pressure coupling
};

/// The friction of a slave node at projection `p` on master facet `facet` (with the gap's
/// linearisation `lin`: its node list, on the same coordinates `x`), anchored at `anchor` on
/// `anchor_facet`; `e0`: the elastic slip at the start of the increment; `pressure` ≥ 0.
/// `facet_normal`: the contact normal is the facet's own at ξ (node to surface; surface to surface
/// turns friction's tangent plane with the weighted normal, whose change the tangent leaves out).
FrictionPoint friction_point(const FrictionLaw& law, const Facet& facet, const Projection& p,
                             const GapLinearization& lin, const Facet& anchor_facet, const FrictionAnchor& anchor,
                             const Vec3& e0, double pressure, std::span<const Vec3> x, bool facet_normal = true);

/// Friction against a rigid master that is not made of facets (an analytical surface,
/// analytical_pair.hpp): `dx` = x_s − the zero-shear point's current position, `D` = ∂Δx/∂u over
/// the unknowns of the pair's gap linearisation (3 × n row-major: the slave node, then the
/// master's material point under the slave moving with its body), `p` the contact point's
/// tangent basis. The same return mapping and force distribution as above; the tangent leaves
/// out the turn of the tangent plane (E = P_T D) and the slide of the contact point over the
/// master (no (∂D)ᵀ τ).
FrictionPoint friction_point(const FrictionLaw& law, const Projection& p, const Vec3& dx, std::span<const double> D,
                             const Vec3& e0, double pressure);

}  // namespace inpact::contact
