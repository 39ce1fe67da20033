#pragma once
/// Contact in the analysis: the pairs in force in a step, each as contact::resolve_interactions
/// resolved it (contact/resolved_interaction.hpp: what `inpact check` prints), measured by its
/// discretisation (contact/pair_kinematics.hpp: node to surface or surface to surface, a gap,
/// area and gap linearisation per slave node either way) and enforced by its method's type
/// (contact/enforcement.hpp: direct multipliers, a penalty-type law, a law with multipliers,
/// augmented Lagrange). This class owns what every method shares: the search and status loop,
/// the checks (HCRIT, chattering, a node through its master), the scatter of the local blocks
/// through the assembler, the multiplier equations (after the DOF map's, see
/// Assembler::set_extra_couplings), the augmentation check and the output values.
///
/// A distributed run shares the slave nodes out by the rank of their rows (slave_node_share.hpp):
/// each rank measures, linearises and assembles its own (the system's entries and the forces,
/// summed over the ranks), and gathers every node's measure and friction state, so that the
/// status, the multipliers, the checks and the output are the same on every rank. So on such a
/// run begin_attempt, update, assemble, results and pair_forces are collective: every rank
/// calls them, in the same order.
///
/// ∇g = [n; −N_a n] over the slave node and its master facet's nodes; ∇²g only for finite
/// sliding; A the slave node's area, held fixed in the linearisation. A status change of a
/// multiplier's node is a severe discontinuity iteration.
///
/// Friction (*FRICTION, pairs with μ > 0 or ROUGH only; contact/friction.hpp): every closed
/// slave node of such a pair adds f = A Bᵀ τ from the elastic-slip return mapping, with the
/// tangent A Bᵀ ∂τ/∂u and the pressure coupling A Bᵀ ∂τ/∂p ⊗ ∂p/∂u, where ∂p/∂u = −p'(h) ∇g
/// (penalty-type) or ∂p/∂λ = −1 (direct: a column at the node's multiplier). The symmetric
/// part goes into the assembler's upper triangle, the skew part is kept apart; Newton then
/// solves with unsymmetric_tangent() and UMFPACK. The slip history lives in ContactState: the
/// anchor (facet, ξ₀), elastic slip e₀ and accumulated slip of the converged state at the start
/// of the increment, committed by begin_attempt() when a new increment starts and left alone
/// by retries and augmentations. A frictionless pair has no friction state and costs nothing.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "analysis_model.hpp"
#include "assembler.hpp"
#include "contact/enforcement.hpp"
#include "contact_results.hpp"
#include "linear/petsc_module.hpp"
#include "iteration_seconds.hpp"

namespace inpact::solver {

class StepConditions;

/// Severe discontinuity iterations allowed in one increment attempt (Abaqus's I_S default, 50:
/// parser/KEYWORDS.md *CONTROLS; *CONTROLS does not change it in inpact yet).
inline constexpr int kMaxSevereIterations = 50;

/// USER ADAPTIVE: the penalty stiffness of the early iterations of the first increment, as a
/// fraction of the full one. Abaqus does not publish its reduction; inpact's choice: 1/100,
/// soft enough that the contact status settles in a few iterations, after which the full
/// stiffness is restored and Newton converges from there.
inline constexpr double kUserAdaptiveScale = 0.01;

/// What a slave node carries across iterations, increments and steps (contact/enforcement.hpp).
using contact::SlaveState;

/// The friction history and trial state of a slave node of a frictional pair.
struct FrictionNodeState {
  // At the start of the increment (the converged state; committed by begin_attempt).
  std::int32_t anchor_facet = -1;    ///< zero-shear point: master facet (−1: not in contact) ...
  std::array<double, 2> anchor_xi{};  ///< ... and parametric point; set on first touch if −1
  std::array<double, 3> e0{};         ///< elastic slip (global components)
  std::array<double, 2> slip0{};      ///< accumulated slip in t1/t2 (CSLIP1/2)
  // At the last update (the trial state).
  bool active = false;                ///< closed, friction acting
  bool slipping = false;
  std::int32_t facet = -1;
  std::array<double, 2> xi{};
  std::array<double, 3> e{};          ///< elastic slip after the return mapping
  std::array<double, 3> tau{};        ///< frictional stress on the master (slave carries −τ)
  std::array<double, 3> trial{};      ///< e_tr, the elastic predictor of the return mapping
  std::array<double, 2> slip{};       ///< accumulated slip including this increment
  /// An analytical master (facet 0 stands for the whole surface): the zero-shear point and the
  /// contact point at the last update, body-frame material points (contact/analytical_pair.hpp).
  std::array<double, 3> anchor_point{}, point{};
};

/// The contact part of the solution state, copied with it when an increment is retried.
struct ContactState {
  std::vector<std::vector<SlaveState>> pairs;  ///< by pair row; empty while the pair is not in force
  /// By pair row; empty for frictionless pairs (and pairs not in force).
  std::vector<std::vector<FrictionNodeState>> friction;
  /// (step, increment) whose start the friction history holds.
  std::array<int, 2> friction_increment{-1, -1};
};

/// Per pair with friction (in pair order), per slave node: the trial slip e_tr of a node that
/// slipped at one update, zero for the others.
using SlippingTrials = std::vector<std::vector<std::array<double, 3>>>;

/// What one update of the contact geometry and status found.
struct ContactIteration {
  int status_changes = 0;          ///< nodes that opened or closed
  bool blocks_convergence = false; ///< a direct (multiplier) node changed status: a severe discontinuity
  double max_gap_error = 0.0;      ///< largest |g + h(p)| of a closed multiplier node (direct: |g|)
  std::string failure;             ///< chattering or HCRIT exceeded: the attempt must be cut back
};

/// The penetration of every slave node of the augmented-Lagrange pairs at one update, per pair
/// (−∞ where no master faces the node): ContactProblem::overshoot_fraction's "before".
struct AugmentedPenetrations {
  std::vector<std::vector<double>> pairs;
};

/// The augmented-Lagrange check after Newton converged.
struct AugmentationCheck {
  bool converged = true;       ///< every penetration within its tolerance
  double max_penetration = 0.0;
  double tolerance = 0.0;      ///< of the pair holding the worst penetration
  std::int64_t node = -1;      ///< its slave node row
};

/// Throws AnalysisError (citing the deck) for contact this version does not analyse:
/// surface-to-surface pairs with a node-based slave, node-based masters, ADJUST on step pairs
/// (or on a model contact::apply_adjust has not seen). What depends on the resolved method
/// (NO SEPARATION other than with direct hard contact, self-contact with direct enforcement) is
/// refused by contact::resolve_interactions.
void check_contact_supported(const model::Model& model, const contact::InteractionTable& table);

class ContactProblem {
 public:
  /// The pairs in force in step `step_index` (model pairs and those of steps up to it).
  ContactProblem(const AnalysisModel& am, std::size_t step_index);
  ~ContactProblem();
  ContactProblem(const ContactProblem&) = delete;

  bool empty() const;
  bool has_augmented_lagrange() const;
  /// One line per pair in force: contact::describe() of its resolved record (the step's messages).
  std::vector<std::string> describe() const;

  /// Threads the surfaces' update and the nodes' linearisation may run on (surface to surface:
  /// across slave facets); the results do not depend on how many.
  void set_threads(int threads);

  bool has_friction() const;
  /// Sizes `state` for the pairs in force and resets the status-change counters. When
  /// (step, increment) differs from the one `state` was last begun for, a new increment starts
  /// from the converged state: the friction history is committed from its trial values.
  /// `u_start`: the converged displacements the attempt starts from (penetrations there are
  /// the baseline of the HCRIT check).
  /// The first increment of a step also resets what a step change leaves behind: a pair not in
  /// force in the previous step (*MODEL CHANGE, ADD) starts with every node open and no friction
  /// history; a pair whose enforcement changed (*CHANGE SURFACE BEHAVIOR) starts its multipliers
  /// from zero. A pair whose friction changed keeps its slip history.
  void begin_attempt(ContactState& state, int step, int increment, std::span<const double> u_start);
  /// *CHANGE FRICTION's ramp: the friction law of each changed pair at step time t (the end of
  /// the increment about to be solved), from `conditions`' amplitudes.
  void set_step_time(const StepConditions& conditions, double t);
  /// The contact forces (their part of f_int, per global DOF) of the pairs in force whose rows are
  /// in `rows`, at the last update (a converged state): what *MODEL CHANGE, REMOVE releases.
  std::vector<double> pair_forces(std::span<const std::size_t> rows, const ContactState& state) const;
  /// Search, projection and contact status at displacement u; rebuilds the assembler's pattern
  /// when the contact couplings or the multipliers changed.
  ContactIteration update(std::span<const double> u, ContactState& state, Assembler& assembler);
  /// Adds the contact forces to f_int (full DOF vector) and their tangent to the assembler's
  /// matrix (after the elements), for the geometry of the last update.
  void assemble(const ContactState& state, std::span<double> f_int, Assembler& assembler);
  /// The multiplier rows of the residual, r_m = −A (g + h(p)) with h(p) the overclosure the law
  /// gives the node's pressure p = −multiplier (direct: h = 0) (`rows`: the equations after the
  /// DOF map's).
  void constraint_residual(const ContactState& state, std::span<double> rows) const;
  /// λ += Δλ from the solution's multiplier rows.
  void apply_correction(std::span<const double> rows, ContactState& state) const;
  /// For a singular first solve: the pairs whose first update of their first increment found
  /// no slave node touching (nothing closed, nothing stiffened), each with its nearest slave
  /// node and gap, as "; contact pair S/M touches nowhere ..." — a body that only such a pair
  /// was to hold is free, and no smaller increment changes that. Empty when every pair just
  /// started holds something, or none just started.
  std::string untouched_at_start() const;
  /// Did the last assemble() leave an unsymmetric part (friction with a pressure coupling; on a
  /// distributed run, on any rank)?
  bool unsymmetric() const { return unsymmetric_; }
  /// The full (both triangles) tangent: the assembler's symmetric upper triangle `upper`
  /// mirrored, plus the skew part of the last assemble(). For UMFPACK (and PETSc's GMRES).
  const SparseMatrix& unsymmetric_tangent(const SparseMatrix& upper);
  /// Friction return mappings evaluated so far (0 for a frictionless model: tests), by this rank.
  std::int64_t friction_evaluations() const { return friction_evaluations_; }

  /// *CONTACT CONTROLS, STIFFNESS SCALE FACTOR=USER ADAPTIVE: does a pair ask for a reduced
  /// penalty stiffness in the first increment of this step?
  bool has_user_adaptive() const;
  /// The factor on the penalty law of USER ADAPTIVE pairs (pressure and slope): kUserAdaptiveScale
  /// while the first increment finds its contact status, 1 for its final iterations.
  void set_user_adaptive_scale(double scale);

  /// Contact stabilization (contact/contact_stabilization.hpp): does a pair in force damp?
  bool has_damping() const;
  /// The damping of one increment attempt: `u_start` the converged displacements at the
  /// increment's start (augmentations restart Newton elsewhere, the increment's start stays),
  /// ending at step time t (the rule's s_ampl there) after dt, the step's increment number
  /// `increment` (s_incr) of a step of `period`.
  void set_damping(const StepConditions& conditions, std::span<const double> u_start, double t, double dt,
                   int increment, double period);
  /// Σ f_stab·Δu of the last assemble() (at a converged state: the increment's share of ALLSD).
  double damping_dissipated() const { return damping_dissipated_; }

  /// The step's end: a warning naming the deepest slave node when it penetrates its master by
  /// more than kTrustedDepthFraction of its pair's characteristic length at the last update,
  /// else nothing. At a facet's depth the search cannot tell a penetration from the far side of
  /// a body, and the area it loses carries no pressure: the answer may be wrong.
  std::optional<std::string> deep_penetration_warning() const;

  /// A distributed run, once the step's slave nodes are shared out: how many each rank holds,
  /// pair by pair (the log and the .sta); else nothing.
  std::optional<std::string> share_summary() const;

  /// Augmented Lagrange: are all penetrations (c0 − g of closed nodes) within the tolerance?
  AugmentationCheck check_augmentation(const ContactState& state) const;
  /// The augmented-Lagrange pairs' penetrations at the last update.
  AugmentedPenetrations augmented_penetrations() const;
  /// The fraction of the last Newton correction that takes no node of an augmented-Lagrange
  /// pair that was open `before` it deeper into its master than the deepest node of the pair
  /// was (1 % of the pair's penetration tolerance while no node of it penetrates beyond
  /// round-off); 1 when the whole correction does not.
  double overshoot_fraction(const AugmentedPenetrations& before) const;
  /// The trial slips of the last update: ContactProblem::slip_reversal_fraction's "before".
  SlippingTrials slipping_trials(const ContactState& state) const;
  /// The fraction of the last Newton correction at which no node that slipped `before` it and
  /// slips after it (with a force) has turned its slip around: where its trial slip e_tr becomes
  /// perpendicular to the one before (e_tr moves nearly linearly along a correction), at least
  /// 1 %. A node that at 1 % already slips the other way as far as it slipped before does not
  /// limit; 1 when none limits.
  double slip_reversal_fraction(const SlippingTrials& before, const ContactState& state) const;
  /// λ ← ⟨λ + k (h + c0)⟩ for every slave node of an augmented-Lagrange pair.
  void augment(ContactState& state) const;

  /// Output values at displacement u (a converged state).
  ContactResults results(std::span<const double> u, const ContactState& state);

  /// Wall time in begin_attempt(), update(), evaluate() and assemble() so far (their fields of IterationSeconds).
  const IterationSeconds& seconds() const { return seconds_; }

 private:
  struct Pair;
  /// Search, projection and gap of every slave node at u; a call at the u of the last one
  /// (the output of a converged state, whose last iteration evaluated it) keeps its results.
  /// On a distributed run each rank measures its own slave nodes (SlaveNodeShare) and every
  /// rank then has every node's measure (gather_measures).
  void evaluate(std::span<const double> u);
  void gather_measures(Pair& p) const;
  /// A distributed run's first measure (whole on every rank): each pair's slave nodes shared
  /// out by the cost of their measure (SlaveNodeShare), for the rest of the step. Each
  /// measured facet's points thus keep their whole history, as on one rank. (A step whose
  /// contact forms later is shared by the nodes facing the master at its start: unevenly,
  /// but correctly.)
  void share_slave_nodes();
  /// A distributed run: the contact forces of every rank's nodes (shared_forces_) into f_int on
  /// every rank, with the damping's dissipation and the unsymmetric flag.
  void sum_over_ranks(std::span<double> f_int);
  /// update() of slave i: its status, and the checks every method shares (chattering, HCRIT).
  void mark_step_change(Pair& p, const AnalysisModel& am, std::size_t step_index);
  void start_step(const Pair& p, ContactState& state) const;
  /// update()'s first pass over pair pi: every node's status (update_node), friction cleared,
  /// damping and multipliers; the nodes of this rank that act (contribute or damp).
  std::vector<std::size_t> update_statuses(std::size_t pi, ContactState& state, std::span<const contact::Vec3> x,
                                           ContactIteration& it);
  void update_node(Pair& p, std::size_t i, SlaveState& s, const contact::StatusLimits& limits,
                   std::span<const contact::Vec3> x, ContactIteration& it) const;
  /// A closed node that lost its master: did it go through it by more than HCRIT?
  void check_lost_master(const Pair& p, std::size_t i, const SlaveState& s, std::span<const contact::Vec3> x,
                         ContactIteration& it) const;
  std::string node_name(const Pair& p, std::size_t i) const;
  /// Appends what slave i of pair pi couples to the pattern's signature.
  void add_couplings(std::size_t pi, std::size_t i, std::vector<std::int64_t>& signature);
  /// Rebuilds the assembler's pattern when the couplings differ from the last ones.
  void set_pattern(std::vector<std::int64_t> signature, Assembler& assembler);
  void assemble_friction(const Pair& p, std::size_t i, const SlaveState& s, std::span<double> f_int,
                         Assembler& assembler);
  void assemble_constraint_column(const Pair& p, std::size_t i, const SlaveState& s,
                                  std::span<const std::int64_t> dofs, Assembler& assembler) const;
  void friction_results(const Pair& p, std::size_t i, const FrictionNodeState& f, bool closed,
                        ContactNodeResult& r) const;
  /// The damping of slave i into f_int and the tangent (its symmetric part).
  void assemble_damping(const Pair& p, std::size_t i, std::span<double> f_int, Assembler& assembler);
  const AnalysisModel& am_;
  RankWorld world_;
  bool shared_ = false;  ///< share_slave_nodes() done (a distributed run)
  std::size_t n_pairs_total_ = 0;
  std::vector<std::unique_ptr<Pair>> pairs_;
  std::vector<std::int64_t> signature_;  ///< couplings the assembler's pattern holds
  /// Multiplier m (equation n_eq + m): pair index into pairs_, slave index.
  std::vector<std::pair<std::size_t, std::size_t>> multipliers_;
  /// Skew part of the contact tangent, ½(K − Kᵀ) entries (row, column equation, value).
  std::vector<Assembler::SkewEntry> skew_;
  bool unsymmetric_ = false;  ///< unsymmetric(): skew_ not empty on some rank
  std::vector<double> shared_forces_;  ///< a distributed run's scratch: this rank's contact forces, then two flags
  Assembler::LocalEquations friction_eqs_;  ///< assemble_friction's scratch
  std::vector<double> friction_k_;
  SparseMatrix full_;
  std::int64_t friction_evaluations_ = 0;
  std::vector<double> evaluated_u_;  ///< the u of the last evaluate()
  bool evaluated_ = false;
  IterationSeconds seconds_;
  std::vector<double> damping_u_start_;  ///< set_damping()'s u_start
  double damping_dissipated_ = 0.0;
};

}  // namespace inpact::solver
