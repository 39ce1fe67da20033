#pragma once
/// How the normal contact constraint of one slave node is enforced: one small type per method,
/// each with its status update, its local force and tangent coefficients, its constraint row
/// (methods with multipliers), its pressure and its augmentation. The solver
/// (solver/contact_problem.cpp) owns the kinematics, the assembly and the checks shared by every
/// method (HCRIT, chattering, status changes); it asks the pair's Enforcement for the rest.
///
/// With A the slave node's area and ∇g, ∇²g the gap's linearisation, every method contributes
///   f_c = A c ∇g,   K_c = A k ∇g ∇gᵀ + A c ∇²g      (NormalForce: c = coefficient, k = stiffness)
/// and the methods with a multiplier add its row A (g + h(p)) = 0 with the diagonal −A / p'(h):
///   direct multipliers (direct.hpp)      c = λ, k = 0, h = 0, no diagonal; pressure −λ
///   penalty law (penalty.hpp)            c = −p(h), k = p'(h); pressure p(h), h = −g
///   augmented Lagrange (penalty.hpp)     the penalty law with p = ⟨λ + k (h + c0)⟩, λ ← p
///                                        after Newton converges (the augmentation loop)
///   law with multipliers (law_multipliers.hpp)  a law stiffer than 1000 k_e (table 38.1.21):
///                                        c = multiplier, constraint g + h(p) = 0 with the law's
///                                        inverse h(p), p = −multiplier, diagonal −A / p'(h)
#include <cstdint>
#include <memory>

#include "contact/pressure_overclosure.hpp"

namespace inpact::contact {

struct ResolvedInteraction;

/// What a slave node carries across iterations, increments and steps.
struct SlaveState {
  double lambda = 0.0;  ///< augmented Lagrange: λ (a pressure); direct: the multiplier (pressure −λ)
  /// A penalty-type law stiffer than 1000 k_e, enforced with a Lagrange multiplier (table
  /// 38.1.21): the multiplier of a closed node, pressure −multiplier.
  double multiplier = 0.0;
  bool closed = false;  ///< contact status at the last update
  int flips = 0;        ///< status changes in the current increment attempt
  /// Penetration at the start of the attempt (from the converged state). HCRIT limits what an
  /// attempt adds to it: an initial overclosure (an interference fit) is resolved in the first
  /// increment, and no cutback could reduce it.
  double start_penetration = 0.0;
  /// The master facet of the last update that found one (−1: never): where a node that lost
  /// its master went through it, or slid off it.
  std::int32_t last_facet = -1;
};

/// What the discretisation measured for one slave node at the current iterate.
struct NodeGap {
  bool found = false;  ///< the node faces the master
  double gap = 0.0;    ///< with the pair's offsets; meaningful only when found
  /// The node starts closed whatever its gap now: it touched (or overclosed) its master when
  /// the pair came into force (solver/contact_problem.cpp, starts_closed); set in the first
  /// status update of the pair's first increment only.
  bool starts_closed = false;
};

/// Status thresholds of a pair at one update (round-off of its pressures and lengths).
struct StatusLimits {
  double open_below = 0.0;   ///< a multiplier's pressure below this opens the node
  double close_below = 0.0;  ///< a gap below this closes (or touches)
};

struct StatusUpdate {
  bool closed = false;       ///< the node's new contact status
  bool contributes = false;  ///< the node enters the residual and tangent
};

/// Per unit area: f_c = A coefficient ∇g, K_c = A stiffness ∇g∇gᵀ + A coefficient ∇²g.
struct NormalForce {
  double coefficient = 0.0;
  double stiffness = 0.0;
};

/// The output of a node: its pressure (negative: a bonded node in tension) and status.
struct NodePressure {
  double pressure = 0.0;
  bool closed = false;
};

class Enforcement {
 public:
  virtual ~Enforcement() = default;

  /// Does a closed node carry a Lagrange multiplier (a system row of its own)?
  virtual bool uses_multipliers() const { return false; }
  /// The field of SlaveState holding the node's multiplier (the unknown of its system row).
  virtual double SlaveState::*multiplier() const { return &SlaveState::lambda; }
  /// Pressures below this, in magnitude, are round-off of the method (the open threshold's scale).
  virtual double pressure_round_off() const { return 0.0; }

  /// The new status of node `s` and whether it contributes; updates its multiplier on a change.
  virtual StatusUpdate update_status(SlaveState& s, const NodeGap& g, const StatusLimits& limits) const = 0;
  virtual NormalForce normal_force(const SlaveState& s, const NodeGap& g) const = 0;
  /// dp/dh for the friction's pressure coupling (0 where the pressure is a multiplier).
  virtual double pressure_slope(const SlaveState& s, const NodeGap& g) const { return 0.0; }
  /// The contact pressure friction and augmentation see (never tensile).
  virtual double pressure(const SlaveState& s, const NodeGap& g) const = 0;
  /// CPRESS and the closed status of the output.
  virtual NodePressure output(const SlaveState& s, const NodeGap& g) const = 0;

  /// Methods with multipliers: the row is −A (g + h) with h = constraint_overclosure(), and its
  /// diagonal −A / compliance_slope() when that is > 0.
  virtual double constraint_overclosure(const SlaveState& s) const { return 0.0; }
  virtual double compliance_slope(const SlaveState& s) const { return 0.0; }

  /// Augmented Lagrange: does the augmentation loop apply; the penetration it holds to the
  /// tolerance (past the law's zero-pressure clearance: −g − h_zero), and the update λ ← p.
  virtual bool augmented() const { return false; }
  virtual double h_zero() const { return 0.0; }
  double penetration(const NodeGap& g) const { return -g.gap - h_zero(); }
  void augment(SlaveState& s, const NodeGap& g) const { s.lambda = pressure(s, g); }
  /// USER ADAPTIVE: the factor on the penalty law of the moment (penalty law only).
  virtual void set_adaptive_scale(double) {}
};

/// The enforcement `r` resolved to (resolve_interactions()).
std::unique_ptr<Enforcement> make_enforcement(const ResolvedInteraction& r);

}  // namespace inpact::contact
