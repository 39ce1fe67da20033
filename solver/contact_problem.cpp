#include "contact_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis_error.hpp"
#include "slave_node_share.hpp"
#include "shell_contact_offsets.hpp"
#include "two_sided_exterior.hpp"
#include "model/element_types.hpp"
#include "step_conditions.hpp"
#include "contact/analytical_pair.hpp"
#include "contact/enforcement.hpp"
#include "contact/friction.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/node_to_surface.hpp"
#include "contact/resolved_interaction.hpp"
#include "contact/surface_to_surface.hpp"

namespace inpact::solver {

namespace {

[[noreturn]] void refuse(const model::Model& m, const model::SourceLoc& loc, const std::string& keyword,
                         const std::string& what) {
  throw AnalysisError(fmt::format("{}: error: {}: {}", m.sources.describe(loc), keyword, what));
}

/// *CLEARANCE of a pair: per slave node (slave().nodes() order), clearance − the gap measured
/// on the reference coordinates, so the initial gap is the clearance given and changes with
/// the displacements from there [K16 §3.21]. Empty when no *CLEARANCE names the pair; nodes
/// it does not name (TABULAR) keep their measured gap. Later *CLEARANCE lines win.
std::vector<double> clearance_offsets(const model::Model& m, const model::ContactPair& pair,
                                      contact::PairKinematics& geometry) {
  std::vector<double> wanted(geometry.slave().nodes().size(), std::numeric_limits<double>::quiet_NaN());
  bool any = false;
  for (const model::Clearance& c : m.clearances) {
    if (!contact::clearance_names(c, pair)) continue;
    any = true;
    if (c.value) std::fill(wanted.begin(), wanted.end(), *c.value);
    for (const auto& [row, value] : c.node_values)
      if (const std::int32_t i = geometry.slave().local_index(row); i >= 0) wanted[static_cast<std::size_t>(i)] = value;
  }
  if (!any) return {};
  std::vector<contact::SlaveKinematics> kin;
  geometry.update(contact::reference_coordinates(m.mesh.nodes), kin);
  std::vector<double> offset(wanted.size(), 0.0);
  for (std::size_t i = 0; i < offset.size(); ++i)
    if (kin[i].found && !std::isnan(wanted[i])) offset[i] = wanted[i] - kin[i].projection.gap;
  return offset;
}

/// CalculiX's TIED law binds each slave node where it starts: offsets that make every found
/// node's reference gap zero.
std::vector<double> tied_offsets(const model::Model& m, contact::PairKinematics& geometry) {
  std::vector<contact::SlaveKinematics> kin;
  geometry.update(contact::reference_coordinates(m.mesh.nodes), kin);
  std::vector<double> offset(kin.size(), 0.0);
  for (std::size_t i = 0; i < kin.size(); ++i)
    if (kin[i].found) offset[i] = -kin[i].projection.gap;
  return offset;
}

}  // namespace

/// A gap below this fraction of the characteristic length is contact within round-off: every
/// method closes (or, penalty-type, stiffens) such a node at every update (status_limits).
constexpr double kTouchingTolerance = 1e-9;

/// The initial contact status: a slave node within this fraction of the pair's characteristic
/// length of its master (or overclosed) when the pair comes into force starts closed
/// (ContactProblem::Pair::starts_closed). Round-off of the mesh's coordinates, not a clearance:
/// a deck that writes its nodes with 8 significant digits misplaces a node on a surface by
/// about 1e-8 of the model's size, which is up to 1e-6 l_char for a model of 100 facets across.
constexpr double kStartClosedTolerance = 1e-6;

/// A multiplier's row is its node's weighted gap, ∫ W g over the part of the node's facets that
/// overlaps the master. Where that part is a sliver of width δ at a master edge (a node of the
/// next row of facets beyond a flat punch's edge, its W vanishing there), the row is ~(δ/h)² of
/// an ordinary one and all but a combination of its neighbours' rows (the rest roughly (δ/h)³):
/// on a flat-on-flat contact such a node touches within round-off and closes, and the
/// saddle-point system is numerically singular. Rigid punch, C3D8, DIRECT: a sliver 5e-7 wide on
/// facets 0.5 wide (overlap 3e-13 of the nodal area) gave multipliers of 1e19 on it and ±1e7 on
/// its neighbours, and the punch's nodes chattered; an overlap of 1e-9 still gave 6e12 and
/// chattered; limits from 1e-6 to 0.1 all ran the deck in one increment. Below this fraction of
/// its nodal area a node gets no multiplier (the pressure there is carried by its neighbours'
/// multipliers, whose rows cover the sliver too); penalty-type laws keep such a node (its
/// stiffness is small, not singular).
constexpr double kMinMultiplierOverlap = 1e-3;

/// One contact pair in force: its geometry, enforcement and the last kinematics.
struct ContactProblem::Pair {
  std::int32_t row = 0;
  const model::ContactPair* deck = nullptr;
  const contact::ResolvedInteraction* resolved = nullptr;  ///< what check printed for this step
  std::unique_ptr<contact::PairKinematics> geometry;
  SlaveNodeShare share;  ///< a distributed run: which slave nodes this rank measures and assembles
  std::unique_ptr<contact::Enforcement> enforcement;
  std::optional<contact::FrictionLaw> friction;     ///< unset: frictionless
  bool finite_sliding = true, surface_to_surface = false;
  double l_char = 0.0, hcrit = 0.0;
  std::vector<contact::SlaveKinematics> kin;
  std::vector<char> contributes;           ///< per slave node, at the last update
  std::vector<std::int64_t> multiplier;    ///< per slave node: multiplier index or −1
  std::vector<contact::FrictionPoint> fric;  ///< frictional pairs: per slave node (this rank's), at the last update
  /// *CLEARANCE or the TIED law: per slave node, what is added to the measured gap (empty: none).
  std::vector<double> gap_offset;
  /// Per slave node: starts_closed() when the pair came into force (at the step's start).
  std::vector<char> closed_at_start;
  /// The next update() is the first of an attempt of the pair's first increment: the nodes of
  /// closed_at_start start closed there.
  bool start_pending = false;
  /// The last update() was that one: node_gap() says which nodes start closed until the next.
  bool starting = false;
  /// Not in force in the previous step (a *MODEL CHANGE, ADD, or a pair entering): its nodes
  /// start open, without friction history.
  bool enters = false;
  /// In force in the previous step with another enforcement: its multipliers start from zero
  /// (direct's λ is −p, augmented Lagrange's λ is +p).
  bool new_enforcement = false;
  /// Contact stabilization of this attempt: k = s c_d/Δt (0: none), and per slave node whether
  /// it damps at the last update (closed, or open within the rule's range).
  double damping_stiffness = 0.0;
  std::vector<char> damped;

  bool uses_multipliers() const { return enforcement->uses_multipliers(); }
  bool damps(std::size_t i, const SlaveState& s) const {
    return damping_stiffness > 0.0 && kin[i].found && (s.closed || kin[i].projection.gap < resolved->stabilization->range);
  }

  /// The initial contact status (Abaqus's): slave i starts the pair's first increment closed when
  /// it touches or overcloses its master at the start, its gap g0 <= kStartClosedTolerance l_char.
  /// g0 is the gap (with the pair's offsets), and for surface to surface without offsets also the
  /// node's own closest-point gap: the weighted gap of a node touching at the edge of the contact
  /// to be is positive (the open facets around it), yet the bodies touch there. A node that
  /// starts closed brings its constraint (multipliers) or its law's first slope and the force
  /// that closes its gap (penalty-type) into the first system, so a body held only by that
  /// contact and driven by a force is not free in it; after that first update its status is the
  /// method's own (a multiplier opens in tension, a penalty node acts only where it penetrates).
  /// Evaluated on `x`, the coordinates at the start, after update() of the kinematics there.
  /// Nodes touching within round-off (g < kTouchingTolerance l_char) are left to the methods,
  /// which close them anyway: this rule extends theirs, it does not change it.
  bool starts_closed(std::size_t i, std::span<const contact::Vec3> x) const {
    const contact::SlaveKinematics& k = kin[i];
    if (!k.found || k.projection.gap < kTouchingTolerance * l_char) return false;
    const double tolerance = kStartClosedTolerance * l_char;
    if (k.projection.gap <= tolerance) return true;
    if (!surface_to_surface || !gap_offset.empty() || !k.friction_found) return false;
    const contact::Vec3& xs = x[static_cast<std::size_t>(k.node)];
    const contact::Vec3 r{xs[0] - k.projection.x_master[0], xs[1] - k.projection.x_master[1],
                          xs[2] - k.projection.x_master[2]};
    return r[0] * k.projection.facet_normal[0] + r[1] * k.projection.facet_normal[1] +
               r[2] * k.projection.facet_normal[2] <= tolerance;
  }
  double gap(std::size_t i) const { return kin[i].found ? kin[i].projection.gap : std::numeric_limits<double>::infinity(); }
  /// A multiplier method leaves out a node whose facets overlap the master by a sliver
  /// (kMinMultiplierOverlap): it faces nothing for it.
  contact::NodeGap node_gap(std::size_t i) const {
    const bool found = kin[i].found && (!uses_multipliers() || kin[i].overlap >= kMinMultiplierOverlap);
    return {found, gap(i), starting && closed_at_start[i]};
  }
  /// The contact pressure of slave i as the enforcement gives it (never tensile).
  double node_pressure(std::size_t i, const SlaveState& s) const { return enforcement->pressure(s, node_gap(i)); }

  /// Friction of slave i off (open, or not yet evaluated): the trial state keeps its slip.
  void clear_friction(std::size_t i, FrictionNodeState& f) {
    f.active = f.slipping = false;
    f.facet = -1;
    f.e = f.tau = f.trial = {0, 0, 0};
    f.slip = f.slip0;
    fric[i] = {};
  }

  /// The kinematics friction acts with: the node's own projection (surface to surface: not the
  /// weighted gap's).
  const contact::GapLinearization& friction_lin(std::size_t i) const {
    return surface_to_surface ? kin[i].friction_lin : kin[i].lin;
  }
  bool friction_found(std::size_t i) const { return surface_to_surface ? kin[i].friction_found : kin[i].found; }
  bool friction_acts(std::size_t i) const { return friction && !fric[i].force.empty(); }

  /// The DOFs slave i couples (for the assembler's pattern): the gap's unknowns, then those of
  /// the friction kinematics not among them (surface to surface only; node to surface: the same).
  std::vector<std::int64_t> local_dofs(std::size_t i, int dim) const {
    std::vector<std::int32_t> nodes = kin[i].lin.nodes;
    if (surface_to_surface && friction_acts(i))
      for (std::int32_t r : kin[i].friction_lin.nodes)
        if (std::find(nodes.begin(), nodes.end(), r) == nodes.end()) nodes.push_back(r);
    std::vector<std::int64_t> dofs;
    for (std::int32_t node : nodes)
      for (int c = 0; c < dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * dim + c);
    return dofs;
  }

  /// The rigid analytical master's geometry, or null (its friction anchors to material points).
  const contact::AnalyticalPair* analytical() const { return dynamic_cast<const contact::AnalyticalPair*>(geometry.get()); }

  /// Slave i's zero-shear point is where it touches now (first touch, or friction beginning on a
  /// closed node): its projection's facet and ξ, or an analytical master's material point.
  void anchor_here(std::size_t i, FrictionNodeState& f) const {
    const contact::Projection& pr = kin[i].projection;
    if (const auto* a = analytical()) {
      f.anchor_facet = 0;
      f.anchor_point = a->material_point(i);
      return;
    }
    f.anchor_facet = pr.facet;
    f.anchor_xi = pr.xi;
  }

  /// The return mapping of closed slave i (kin[i].lin filled) into `f` and fric[i].
  void update_friction(std::size_t i, const SlaveState& s, FrictionNodeState& f, std::span<const contact::Vec3> x) {
    const contact::Projection& pr = kin[i].projection;
    if (f.anchor_facet < 0) anchor_here(i, f);  // first touch in this increment: the zero-shear point is here
    if (const auto* a = analytical()) {
      contact::Vec3 dx;
      std::vector<double> D;
      a->friction_motion(x, i, f.anchor_point, dx, D);
      fric[i] = contact::friction_point(*friction, pr, dx, D, f.e0, node_pressure(i, s));
      f.point = a->material_point(i);
    } else {
      const auto facets = geometry->master().facets();
      contact::FrictionAnchor anchor{f.anchor_facet, f.anchor_xi};
      fric[i] = contact::friction_point(*friction, facets[static_cast<std::size_t>(pr.facet)], pr, friction_lin(i),
                                        facets[static_cast<std::size_t>(f.anchor_facet)], anchor, f.e0,
                                        node_pressure(i, s), x, !surface_to_surface && !resolved->smoothed);
    }
    const contact::FrictionPoint& fp = fric[i];
    f.active = true;
    f.slipping = fp.slipping;
    f.facet = analytical() ? 0 : pr.facet;
    f.xi = pr.xi;
    f.e = fp.elastic_slip;
    f.tau = fp.traction;
    f.trial = fp.trial_slip;
    const auto& ds = fp.slip_increment;
    f.slip[0] = f.slip0[0] + pr.t1[0] * ds[0] + pr.t1[1] * ds[1] + pr.t1[2] * ds[2];
    f.slip[1] = f.slip0[1] + pr.t2[0] * ds[0] + pr.t2[1] * ds[1] + pr.t2[2] * ds[2];
  }
};

// --- Setup -------------------------------------------------------------------------------

namespace {

/// The pair's discretisation with its smoothing: the pair's *SURFACE SMOOTHING, or general
/// contact's *SURFACE PROPERTY ASSIGNMENT lines (a body's exterior, which has no name in the
/// deck, takes every line whose surface it contains). Validated when the analysis model was built.
std::unique_ptr<contact::PairKinematics> pair_geometry(const AnalysisModel& am, const contact::ContactInteraction& entry,
                                                       const contact::ResolvedInteraction& r) {
  const model::Model& m = *am.model;
  std::unique_ptr<contact::PairKinematics> geometry;
  if (entry.master->kind == model::Surface::Kind::Analytical) {
    auto analytical = std::make_unique<contact::AnalyticalPair>(m, *entry.slave, *entry.master, am.dim, r.thickness,
                                                                r.surface_to_surface);
    if (!entry.general) analytical->set_extension_zone(entry.pair.extension_zone);
    geometry = std::move(analytical);
  } else if (r.surface_to_surface) {
    auto s2s = std::make_unique<contact::SurfaceToSurfacePair>(m, *entry.slave, *entry.master, am.dim, r.thickness);
    if (r.smoothed) {
      const model::ContactPair* named = entry.general ? nullptr : &entry.pair;
      s2s->set_geometric_correction(contact::build_corrections(m, contact::deck_surface_name(m, entry.master), named),
                                    contact::build_corrections(m, contact::deck_surface_name(m, entry.slave), named));
    }
    geometry = std::move(s2s);
  } else {
    auto nts = std::make_unique<contact::NodeToSurfacePair>(m, *entry.slave, *entry.master, am.dim, r.thickness);
    if (!entry.general) nts->set_extension_zone(entry.pair.extension_zone);
    geometry = std::move(nts);
  }
  geometry->set_area_weight(r.weight);
  geometry->set_self_contact(r.self_contact);
  return geometry;
}

}  // namespace

namespace {

/// Pair p's record in the previous step, or null when it was not in force there.
const contact::ResolvedInteraction* previous_record(const AnalysisModel& am, std::size_t step_index, std::size_t row) {
  if (step_index == 0) return nullptr;
  for (const contact::ResolvedInteraction& r : am.interactions.at(step_index - 1))
    if (r.row == row && r.in_force) return &r;
  return nullptr;
}

}  // namespace

void ContactProblem::mark_step_change(Pair& p, const AnalysisModel& am, std::size_t step_index) {
  const contact::ResolvedInteraction* prev = previous_record(am, step_index, static_cast<std::size_t>(p.row));
  p.enters = step_index > 0 && !prev;
  p.new_enforcement = prev && (prev->enforcement != p.resolved->enforcement || prev->augmented != p.resolved->augmented);
}

ContactProblem::ContactProblem(const AnalysisModel& am, std::size_t step_index) : am_(am), world_(rank_world()) {
  const model::Model& m = *am.model;
  n_pairs_total_ = am.contact->rows.size();
  for (const contact::ResolvedInteraction& r : am.interactions.at(step_index)) {
    if (!r.in_force) continue;
    const contact::ContactInteraction& entry = am.contact->rows[r.row];
    auto p = std::make_unique<Pair>();
    p->row = static_cast<std::int32_t>(r.row);
    p->deck = &entry.pair;
    p->resolved = &r;
    p->geometry = pair_geometry(am, entry, r);
    p->enforcement = contact::make_enforcement(r);
    p->friction = r.friction_at(0.0);  // a *CHANGE FRICTION ramp moves it (set_step_time)
    mark_step_change(*p, am, step_index);
    p->finite_sliding = r.finite_sliding;
    p->surface_to_surface = r.surface_to_surface;
    p->l_char = r.l_char;
    p->hcrit = r.hcrit;
    if (r.offsets == contact::GapOffsets::Clearance) p->gap_offset = clearance_offsets(m, entry.pair, *p->geometry);
    if (r.offsets == contact::GapOffsets::InitialGap) p->gap_offset = tied_offsets(m, *p->geometry);
    // (a clearance or a tied start sets the gap itself: the shells' faces do not shift it again)
    if (r.offsets == contact::GapOffsets::None && !entry.general)
      p->gap_offset = shell_thickness_offsets(m, entry.pair, *p->geometry);
    pairs_.push_back(std::move(p));
  }
}

ContactProblem::~ContactProblem() = default;

bool ContactProblem::empty() const { return pairs_.empty(); }

void ContactProblem::set_threads(int threads) {
  for (auto& p : pairs_) p->geometry->set_threads(threads);  // (their update and linearisation)
}

bool ContactProblem::has_friction() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->friction.has_value(); });
}

bool ContactProblem::has_user_adaptive() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->resolved->user_adaptive; });
}

bool ContactProblem::has_augmented_lagrange() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->enforcement->augmented(); });
}

std::vector<std::string> ContactProblem::describe() const {
  std::vector<std::string> out;
  for (const auto& p : pairs_) out.push_back(contact::describe(*p->resolved));
  return out;
}

namespace {

/// An element-based surface with a face on a shell element (whose faces lie off its nodes).
bool on_shells(const model::Model& m, const model::Surface& s) {
  return std::any_of(s.faces.begin(), s.faces.end(), [&](const model::Face& f) {
    return model::is_shell(model::element_type(m.mesh.elements.type[static_cast<std::size_t>(f.element)]));
  });
}

}  // namespace

void check_contact_supported(const model::Model& m, const contact::InteractionTable& table) {
  check_two_sided_bodies_in_exterior(m);
  for (const contact::ContactInteraction& e : table.rows) {
    const model::ContactPair& p = e.pair;
    const std::string kw = e.general ? "*CONTACT" : "*CONTACT PAIR";
    if (e.slave->kind == model::Surface::Kind::Analytical)
      refuse(m, p.loc, kw, fmt::format("the analytical surface {} can only be a master surface", p.slave));
    if ((p.adjust_distance || !p.adjust_nset.empty()) && e.step_data)
      refuse(m, p.loc, kw, "ADJUST on a contact pair defined in a step is not analysed by this version of inpact "
                           "yet; define the pair in the model data");
    if ((p.adjust_distance || !p.adjust_nset.empty()) && !m.adjusted)
      refuse(m, p.loc, kw, "ADJUST: the model was not adjusted before the analysis (contact::apply_adjust)");
    if (e.master->kind == model::Surface::Kind::Node)
      refuse(m, p.loc, kw, fmt::format("the master surface {} is node based; a master surface must be made of element faces", p.master));
    for (const model::Surface* s : {e.slave, e.master})
      if (on_shells(m, *s) && e.general)
        refuse(m, p.loc, kw, fmt::format("surface {} lies on shell elements: general contact with shells is not "
                                         "supported yet; use *CONTACT PAIR (contact on the shells' faces, or with NO "
                                         "THICKNESS at their nodes)",
                                         s->name));
    if (!e.general && e.master->kind == model::Surface::Kind::Element) check_shell_master(m, p, *e.master);
  }
}

// --- Iterations --------------------------------------------------------------------------

void ContactProblem::begin_attempt(ContactState& state, int step, int increment, std::span<const double> u_start) {
  const ScopedSeconds clock(seconds_.contact_begin);
  state.pairs.resize(n_pairs_total_);
  evaluate(u_start);
  const bool new_increment = state.friction_increment != std::array<int, 2>{step, increment};
  state.friction_increment = {step, increment};
  std::vector<contact::Vec3> x_start;
  for (const auto& p : pairs_) {
    auto& s = state.pairs[p->row];
    // Once per attempt of a step's first increment (not again at its augmentations).
    if (increment == 1 && new_increment) start_step(*p, state);
    // A pair without slave states has not converged an increment yet: it has just come into
    // force (each attempt of its first increment starts from the state before it).
    p->start_pending = s.empty();
    s.resize(p->geometry->slave().nodes().size());
    if (p->start_pending) {
      if (x_start.empty()) x_start = contact::current_coordinates(am_.model->mesh.nodes, u_start, am_.dim);
      p->closed_at_start.assign(s.size(), 0);
      for (std::size_t i = 0; i < s.size(); ++i) p->closed_at_start[i] = p->starts_closed(i, x_start);
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
      s[i].flips = 0;
      s[i].start_penetration = p->kin[i].found ? std::max(0.0, -p->gap(i)) : 0.0;
    }
    if (!p->friction) {
      // A frictionless step (*CHANGE FRICTION): its slip is not tracked, so a later friction
      // starts a new history.
      if (static_cast<std::size_t>(p->row) < state.friction.size()) state.friction[p->row].clear();
      continue;
    }
    if (state.friction.size() < n_pairs_total_) state.friction.resize(n_pairs_total_);
    auto& fs = state.friction[p->row];
    const std::size_t had = fs.size();
    fs.resize(s.size());
    if (new_increment)  // commit the converged trial state as the start of the new increment
      for (FrictionNodeState& f : fs) {
        f.anchor_facet = f.active ? f.facet : -1;
        f.anchor_xi = f.xi;
        f.anchor_point = f.point;
        f.e0 = f.active ? f.e : std::array<double, 3>{0, 0, 0};
        f.slip0 = f.slip;
      }
    // Friction that begins on a node already closed (a pair frictionless until this step): its
    // zero-shear point is where the node is at the start of the increment.
    for (std::size_t i = had; i < fs.size(); ++i)
      if (s[i].closed && p->friction_found(i)) p->anchor_here(i, fs[i]);
  }
}

void ContactProblem::start_step(const Pair& p, ContactState& state) const {
  auto& s = state.pairs[p.row];
  if (p.enters) {  // reactivated: open nodes, no friction history [IG ctc_contactpair_std]
    s.clear();
    if (static_cast<std::size_t>(p.row) < state.friction.size()) state.friction[p.row].clear();
  } else if (p.new_enforcement) {
    for (SlaveState& n : s) n.lambda = n.multiplier = 0.0;
  }
}

void ContactProblem::set_step_time(const StepConditions& conditions, double t) {
  for (auto& p : pairs_)
    if (const auto& ramp = p->resolved->friction_ramp)
      p->friction = p->resolved->friction_at(conditions.amplitude_value(ramp->amplitude, t));
}

std::vector<double> ContactProblem::pair_forces(std::span<const std::size_t> rows, const ContactState& state) const {
  std::vector<double> f(static_cast<std::size_t>(am_.n_dof()), 0.0);
  for (const auto& p : pairs_) {
    if (std::find(rows.begin(), rows.end(), static_cast<std::size_t>(p->row)) == rows.end()) continue;
    const auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (!p->contributes[i] || !p->share.owns(i)) continue;
      // As assemble(): f_c = A c ∇g, and friction's A Bᵀ τ over its own kinematics.
      const contact::GapLinearization& lin = p->kin[i].lin;
      const double area = p->kin[i].area;
      const double c = p->enforcement->normal_force(slaves[i], p->node_gap(i)).coefficient * area;
      std::size_t a = 0;
      for (std::int32_t node : lin.nodes)
        for (int d = 0; d < am_.dim; ++d, ++a) f[static_cast<std::size_t>(node) * am_.dim + d] += c * lin.gradient[a];
      if (!p->friction_acts(i)) continue;
      a = 0;
      for (std::int32_t node : p->friction_lin(i).nodes)
        for (int d = 0; d < am_.dim; ++d, ++a) f[static_cast<std::size_t>(node) * am_.dim + d] += area * p->fric[i].force[a];
    }
  }
  world_.sum(f);
  return f;
}

void ContactProblem::set_user_adaptive_scale(double scale) {
  for (auto& p : pairs_) p->enforcement->set_adaptive_scale(scale);
}

void ContactProblem::evaluate(std::span<const double> u) {
  if (evaluated_ && std::equal(u.begin(), u.end(), evaluated_u_.begin(), evaluated_u_.end())) return;
  const ScopedSeconds clock(seconds_.contact_geometry);
  evaluated_u_.assign(u.begin(), u.end());
  evaluated_ = true;
  const auto x = contact::current_coordinates(am_.model->mesh.nodes, u, am_.dim);
  for (auto& p : pairs_) {
    p->geometry->update(x, p->kin);
    for (std::size_t i = 0; i < p->gap_offset.size(); ++i)
      if (p->kin[i].found) p->kin[i].projection.gap += p->gap_offset[i];
  }
  if (!world_.distributed()) return;
  if (!shared_) return share_slave_nodes();  // (this measure was whole on every rank)
  // (after every pair's measure: a rank that owns more of one pair than of another does not
  // wait for the others pair by pair)
  for (auto& p : pairs_) gather_measures(*p);
}

namespace {

/// What every rank needs of a slave node's measure: SlaveKinematics without its linearisations.
struct MeasuredNode {
  contact::Projection projection;
  double area = 0.0, overlap = 1.0;
  std::int32_t node = -1;
  bool found = false, friction_found = false;
};

}  // namespace

/// A slave node facing its master (found) costs the projections of its facets' points onto the
/// candidate facets and, smoothed, their rays onto the idealised surface: some 1e4 instructions
/// a point (the default job's profile); one facing nothing costs a search that finds no facet,
/// a few hundred. Twenty to one is a round figure between them.
constexpr double kFacingNodeCost = 20.0;

std::optional<std::string> ContactProblem::share_summary() const {
  if (!shared_) return std::nullopt;
  std::string out = fmt::format("contact's slave nodes shared over the {} ranks in patches of even cost (a node facing "
                                "the master counted {:g} times one facing nothing), per rank:",
                                world_.size, kFacingNodeCost);
  for (const auto& p : pairs_)
    out += fmt::format(" {}/{} {};", p->deck->slave, p->deck->master, fmt::join(p->share.count_of_rank(), "+"));
  out.pop_back();
  return out;
}

void ContactProblem::share_slave_nodes() {
  const auto& coords = am_.model->mesh.nodes.coords;
  for (auto& p : pairs_) {
    std::vector<std::array<double, 3>> points;
    std::vector<double> cost;
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      points.push_back(coords[static_cast<std::size_t>(p->geometry->slave().nodes()[i])]);
      cost.push_back(p->kin[i].found ? kFacingNodeCost : 1.0);
    }
    p->share = SlaveNodeShare(world_, points, cost);
    p->geometry->set_measured_nodes(p->share.owned_mask());
  }
  shared_ = true;
}

void ContactProblem::gather_measures(Pair& p) const {
  p.share.gather<MeasuredNode>(
      p.kin,
      [](const contact::SlaveKinematics& k) {
        return MeasuredNode{k.projection, k.area, k.overlap, k.node, k.found, k.friction_found};
      },
      [](const MeasuredNode& r, contact::SlaveKinematics& k) {
        k.projection = r.projection;
        k.area = r.area;
        k.overlap = r.overlap;
        k.node = r.node;
        k.found = r.found;
        k.friction_found = r.friction_found;
      });
}

namespace {

/// A node changing status more often than this within one increment attempt is chattering:
/// the attempt is cut back (inpact's choice; Abaqus does not publish its rule).
constexpr int kMaxStatusChanges = 5;

/// A multiplier's node opens when its pressure turns tensile beyond round-off of the pair's
/// pressures; an open node closes when it penetrates (or touches within round-off of l_char).
contact::StatusLimits status_limits(const contact::Enforcement& e, std::span<const SlaveState> slaves, double l_char) {
  const auto field = e.multiplier();
  double p_scale = 0.0;
  for (const SlaveState& s : slaves)
    if (s.closed) p_scale = std::max(p_scale, std::abs(s.*field));
  p_scale = std::max(p_scale, e.pressure_round_off());
  return {-1e-8 * p_scale, kTouchingTolerance * l_char};
}

}  // namespace

void ContactProblem::update_node(Pair& p, std::size_t i, SlaveState& s, const contact::StatusLimits& limits,
                                 std::span<const contact::Vec3> x, ContactIteration& it) const {
  const contact::StatusUpdate status = p.enforcement->update_status(s, p.node_gap(i), limits);
  p.contributes[i] = status.contributes;
  // A multiplier's constraint g + h(p) = 0 (direct: g = 0) at this iterate: Newton's contact
  // compatibility check.
  if (status.closed && p.uses_multipliers())
    it.max_gap_error = std::max(it.max_gap_error, std::abs(p.gap(i) + p.enforcement->constraint_overclosure(s)));
  if (status.closed != s.closed) {
    ++it.status_changes;
    if (p.uses_multipliers()) it.blocks_convergence = true;
    // Chattering is a multiplier method's trouble: its status is a discontinuity Newton
    // cannot smooth over. A penalty-type law is continuous (a kink at first pressure), so a
    // node crossing it is an ordinary Newton iteration and the iteration limits apply.
    ++s.flips;
    if (p.uses_multipliers() && s.flips > kMaxStatusChanges && it.failure.empty())
      it.failure = fmt::format("contact chattering: {} changed status {} times in this increment", node_name(p, i),
                               s.flips);
  }
  s.closed = status.closed;
  if (p.kin[i].found) s.last_facet = p.kin[i].projection.facet;
  else if (s.closed && s.last_facet >= 0 && it.failure.empty()) check_lost_master(p, i, s, x, it);
  const double g = p.gap(i);
  if (p.kin[i].found && -g - s.start_penetration > p.hcrit && it.failure.empty())
    it.failure = fmt::format("{} penetrates {:.4g} (from {:.4g} at the start of the increment), more than HCRIT = {:.4g}",
                             node_name(p, i), -g, s.start_penetration, p.hcrit);
}

void ContactProblem::check_lost_master(const Pair& p, std::size_t i, const SlaveState& s,
                                       std::span<const contact::Vec3> x, ContactIteration& it) const {
  // A closed node that lost its master: slid off an edge (fine: it opens), or went through the
  // master in one overshooting iteration (the increment must be cut back). Tell them apart by
  // the side of its last facet's plane it is on.
  const contact::Facet& f = p.geometry->master().facets()[static_cast<std::size_t>(s.last_facet)];
  const contact::FacetGeometry fg = contact::facet_geometry(f, x, 0.0, 0.0);
  const auto& xs = x[static_cast<std::size_t>(p.kin[i].node)];
  const double depth = -((xs[0] - fg.x[0]) * fg.n[0] + (xs[1] - fg.x[1]) * fg.n[1] + (xs[2] - fg.x[2]) * fg.n[2]);
  if (depth > p.hcrit)
    it.failure = fmt::format("{} went through the master surface ({:.4g} behind it, more than HCRIT = {:.4g}) and lost it",
                             node_name(p, i), depth, p.hcrit);
}

std::string ContactProblem::node_name(const Pair& p, std::size_t i) const {
  return fmt::format("slave node {} of pair {}/{}", am_.model->mesh.nodes.labels[p.kin[i].node], p.deck->slave,
                     p.deck->master);
}

void ContactProblem::add_couplings(std::size_t pi, std::size_t i, std::vector<std::int64_t>& signature) {
  const Pair& p = *pairs_[pi];
  // The couplings this node adds: its unknowns (and whether a multiplier joins them).
  signature.insert(signature.end(), {static_cast<std::int64_t>(pi), static_cast<std::int64_t>(i),
                                     p.uses_multipliers() && p.contributes[i] ? 1 : 0,
                                     static_cast<std::int64_t>(p.kin[i].lin.nodes.size())});
  signature.insert(signature.end(), p.kin[i].lin.nodes.begin(), p.kin[i].lin.nodes.end());
  if (p.friction && p.surface_to_surface && !p.fric[i].force.empty())
    signature.insert(signature.end(), p.kin[i].friction_lin.nodes.begin(), p.kin[i].friction_lin.nodes.end());
}

void ContactProblem::set_pattern(std::vector<std::int64_t> signature, Assembler& assembler) {
  if (signature == signature_) return;
  ExtraCouplings extra;
  for (const auto& p : pairs_)
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (!p->contributes[i] && !p->damped[i]) continue;
      if (!p->share.owns(i)) {  // (another rank's couplings)
        if (p->multiplier[i] >= 0) extra.multiplier_dofs.emplace_back();
        continue;
      }
      std::vector<std::int64_t> dofs = p->local_dofs(i, am_.dim);
      if (p->multiplier[i] >= 0) extra.multiplier_dofs.push_back(dofs);
      extra.dof_blocks.push_back(std::move(dofs));
    }
  assembler.set_extra_couplings(extra);
  signature_ = std::move(signature);
}

ContactIteration ContactProblem::update(std::span<const double> u, ContactState& state, Assembler& assembler) {
  const ScopedSeconds clock(seconds_.contact_update, &seconds_.contact_updates);
  evaluate(u);
  const auto x = contact::current_coordinates(am_.model->mesh.nodes, u, am_.dim);
  ContactIteration it;
  std::vector<std::int64_t> signature;
  multipliers_.clear();
  for (std::size_t pi = 0; pi < pairs_.size(); ++pi) {
    Pair& p = *pairs_[pi];
    // Status of every node, the linearisation of those that act (on the pair's threads), then
    // their friction and couplings.
    const std::vector<std::size_t> acting = update_statuses(pi, state, x, it);
    p.geometry->linearize_nodes(x, p.kin, acting, p.finite_sliding);
    for (std::size_t i = 0; i < p.kin.size(); ++i) {
      if (!p.contributes[i] && !p.damped[i]) continue;
      if (!p.share.owns(i)) {  // (its multiplier is an equation of the system all the same)
        if (p.multiplier[i] >= 0) signature.insert(signature.end(), {static_cast<std::int64_t>(pi), static_cast<std::int64_t>(i), -1});
        continue;
      }
      const SlaveState& s = state.pairs[p.row][i];
      if (p.friction && s.closed && p.friction_found(i) && p.contributes[i]) {
        p.update_friction(i, s, state.friction[p.row][i], x);
        ++friction_evaluations_;
      }
      add_couplings(pi, i, signature);
    }
  }
  for (const auto& p : pairs_)  // (each rank's friction states, once every pair is done)
    if (p->friction) p->share.gather(state.friction[p->row]);
  set_pattern(std::move(signature), assembler);
  return it;
}

std::vector<std::size_t> ContactProblem::update_statuses(std::size_t pi, ContactState& state,
                                                         std::span<const contact::Vec3> x, ContactIteration& it) {
  Pair& p = *pairs_[pi];
  auto& slaves = state.pairs[p.row];
  const std::size_t n = p.kin.size();
  p.contributes.assign(n, 0);
  p.damped.assign(n, 0);
  p.multiplier.assign(n, -1);
  if (p.friction) p.fric.resize(n);
  const contact::StatusLimits limits = status_limits(*p.enforcement, slaves, p.l_char);
  p.starting = std::exchange(p.start_pending, false);
  std::vector<std::size_t> acting;  // this rank's nodes that contribute or damp
  for (std::size_t i = 0; i < n; ++i) {
    SlaveState& s = slaves[i];
    update_node(p, i, s, limits, x, it);
    if (p.friction) p.clear_friction(i, state.friction[p.row][i]);
    p.damped[i] = p.damps(i, s);
    if (!p.contributes[i] && !p.damped[i]) continue;
    if (p.uses_multipliers() && p.contributes[i]) {
      p.multiplier[i] = static_cast<std::int64_t>(multipliers_.size());
      multipliers_.push_back({pi, i});
    }
    if (p.share.owns(i)) acting.push_back(i);
  }
  return acting;
}

void ContactProblem::assemble(const ContactState& state, std::span<double> f_int, Assembler& assembler) {
  const ScopedSeconds clock(seconds_.contact_assembly);
  std::vector<std::int64_t> dofs;
  std::vector<double> k;
  skew_.clear();
  damping_dissipated_ = 0.0;
  // A distributed run: this rank's nodes' forces apart, summed over the ranks below.
  std::span<double> forces = f_int;
  if (world_.distributed()) {
    shared_forces_.assign(f_int.size() + 2, 0.0);
    forces = std::span(shared_forces_).first(f_int.size());
  }
  for (const auto& p : pairs_) {
    const auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (!p->share.owns(i)) continue;
      if (p->damped[i]) assemble_damping(*p, i, forces, assembler);
      if (!p->contributes[i]) continue;
      const contact::GapLinearization& lin = p->kin[i].lin;
      const double area = p->kin[i].area;
      const std::size_t n = static_cast<std::size_t>(lin.n_dof);
      dofs.clear();
      for (std::int32_t node : lin.nodes)
        for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * am_.dim + c);
      // f_c = A c ∇g, K_c = A k ∇g∇gᵀ + A c ∇²g (contact/enforcement.hpp).
      const contact::NormalForce nf = p->enforcement->normal_force(slaves[i], p->node_gap(i));
      const double s = nf.coefficient * area, stiff = nf.stiffness * area;
      k.assign(n * n, 0.0);
      for (std::size_t a = 0; a < n; ++a) {
        forces[dofs[a]] += s * lin.gradient[a];
        for (std::size_t b = 0; b < n; ++b)
          k[a * n + b] = stiff * lin.gradient[a] * lin.gradient[b] + s * lin.hessian[a * n + b];
      }
      assembler.add_local_matrix(dofs, k);
      if (p->friction_acts(i)) assemble_friction(*p, i, slaves[i], forces, assembler);
      if (p->multiplier[i] >= 0) assemble_constraint_column(*p, i, slaves[i], dofs, assembler);
    }
  }
  unsymmetric_ = !skew_.empty();
  if (world_.distributed()) sum_over_ranks(f_int);
}

void ContactProblem::sum_over_ranks(std::span<double> f_int) {
  // (with the damping's dissipation and whether a rank's friction is unsymmetric: Newton solves
  // the unsymmetric system on every rank or on none)
  const std::size_t n = f_int.size();
  shared_forces_[n] = damping_dissipated_;
  shared_forces_[n + 1] = unsymmetric_ ? 1.0 : 0.0;
  world_.sum(shared_forces_);
  for (std::size_t d = 0; d < n; ++d) f_int[d] += shared_forces_[d];
  damping_dissipated_ = shared_forces_[n];
  unsymmetric_ = shared_forces_[n + 1] > 0.0;
}

void ContactProblem::assemble_friction(const Pair& p, std::size_t i, const SlaveState& s, std::span<double> f_int,
                                       Assembler& assembler) {
  // Friction: f = A Bᵀ τ; tangent A Bᵀ ∂τ/∂u + A Bᵀ ∂τ/∂p ⊗ ∂p/∂u, with ∂p/∂u = −p' ∇g
  // (penalty-type) or, with multipliers, ∂p/∂λ = −1 in the multiplier's column. Local
  // unknowns: the union of the gap's and the friction kinematics' DOFs (the same list for node
  // to surface), then the multiplier.
  const DofMap& map = assembler.dofs();
  const contact::GapLinearization& lin = p.kin[i].lin;
  const double area = p.kin[i].area;
  const std::size_t n = static_cast<std::size_t>(lin.n_dof);
  const contact::FrictionPoint& fp = p.fric[i];
  const contact::GapLinearization& flin = p.friction_lin(i);
  const std::vector<std::int64_t> all = p.local_dofs(i, am_.dim);
  auto position = [&](std::int64_t dof) {
    return static_cast<std::size_t>(std::find(all.begin(), all.end(), dof) - all.begin());
  };
  std::vector<std::size_t> fpos;  // friction unknown → union position
  for (std::int32_t node : flin.nodes)
    for (int c = 0; c < am_.dim; ++c) fpos.push_back(position(static_cast<std::int64_t>(node) * am_.dim + c));
  const bool with_multiplier = p.multiplier[i] >= 0;
  const std::size_t nu = all.size(), nl = nu + (with_multiplier ? 1 : 0), nf = fpos.size();
  Assembler::LocalEquations& eqs = friction_eqs_;  // (buffers reused from node to node)
  eqs.resize(nl);
  for (auto& e : eqs) e.clear();
  for (std::size_t a = 0; a < nu; ++a)
    for (const auto& ma : map.masters(all[a]))
      if (const std::int64_t e = map.equation(ma.dof); e >= 0) eqs[a].push_back({e, ma.weight});
  if (with_multiplier) eqs[nu].push_back({map.n_equations() + p.multiplier[i], 1.0});
  const double dp_dh = p.enforcement->pressure_slope(s, p.node_gap(i));
  std::vector<double>& kf = friction_k_;
  kf.assign(nl * nl, 0.0);
  for (std::size_t a = 0; a < nf; ++a) {
    f_int[all[fpos[a]]] += area * fp.force[a];
    for (std::size_t b = 0; b < nf; ++b) kf[fpos[a] * nl + fpos[b]] += area * fp.tangent[a * nf + b];
    for (std::size_t b = 0; b < n; ++b) kf[fpos[a] * nl + b] -= area * fp.coupling[a] * dp_dh * lin.gradient[b];
    if (with_multiplier) kf[fpos[a] * nl + nu] = -area * fp.coupling[a];
  }
  assembler.add_unsymmetric_matrix(eqs, kf, skew_);
}

void ContactProblem::assemble_constraint_column(const Pair& p, std::size_t i, const SlaveState& s,
                                                std::span<const std::int64_t> dofs, Assembler& assembler) const {
  // Constraint column A ∇g at the multiplier's equation, and a law's compliance on its diagonal:
  // ∂(A (g + h(p)))/∂λ = −A h'(p) = −A / p'(h), p = −λ.
  const double area = p.kin[i].area;
  const double dp = p.enforcement->compliance_slope(s);
  assembler.add_multiplier_column(assembler.dofs().n_equations() + p.multiplier[i], dofs, area, p.kin[i].lin.gradient,
                                  dp > 0.0 ? -(area / dp) : 0.0);
}

void ContactProblem::constraint_residual(const ContactState& state, std::span<double> rows) const {
  for (std::size_t m = 0; m < multipliers_.size(); ++m) {
    const auto [pi, i] = multipliers_[m];
    const Pair& p = *pairs_[pi];
    // The overclosure the law gives the node's pressure (direct: none).
    const double h = p.enforcement->constraint_overclosure(state.pairs[p.row][i]);
    rows[m] = -p.kin[i].area * (p.gap(i) + h);
  }
}

void ContactProblem::apply_correction(std::span<const double> rows, ContactState& state) const {
  for (std::size_t m = 0; m < multipliers_.size(); ++m) {
    const auto [pi, i] = multipliers_[m];
    SlaveState& s = state.pairs[pairs_[pi]->row][i];
    s.*(pairs_[pi]->enforcement->multiplier()) += rows[m];
  }
}

const SparseMatrix& ContactProblem::unsymmetric_tangent(const SparseMatrix& a) {
  mirror_upper(a, full_);
  for (const Assembler::SkewEntry& e : skew_)
    if (const std::int64_t pos = full_.find(e.row, e.col); pos >= 0) full_.values[pos] += e.value;
  return full_;
}

std::string ContactProblem::untouched_at_start() const {
  std::string out;
  for (const auto& p : pairs_) {
    // (A stabilized pair holds the body by its damping: a smaller increment may well help.)
    if (!p->starting || p->resolved->stabilization ||
        std::any_of(p->contributes.begin(), p->contributes.end(), [](char c) { return c != 0; }))
      continue;
    std::size_t nearest = p->kin.size();
    for (std::size_t i = 0; i < p->kin.size(); ++i)
      if (p->kin[i].found && (nearest == p->kin.size() || p->gap(i) < p->gap(nearest))) nearest = i;
    out += fmt::format("; contact pair {}/{} touches nowhere at the start (no slave node within {:.3g} of {}", p->deck->slave,
                       p->deck->master, kStartClosedTolerance * p->l_char, p->deck->master);
    out += nearest < p->kin.size()
               ? fmt::format("; the nearest, node {}, is {:.4g} away)", am_.model->mesh.nodes.labels[p->kin[nearest].node],
                             p->gap(nearest))
               : fmt::format("; none faces it)");
    out += ": a body only this contact holds is free; close the gap (ADJUST, *CLEARANCE), hold the body until it "
           "touches, or damp its motion with *CONTACT STABILIZATION";
  }
  return out;
}

// --- Augmentations -----------------------------------------------------------------------

AugmentationCheck ContactProblem::check_augmentation(const ContactState& state) const {
  AugmentationCheck c;
  double worst_ratio = 0.0;
  for (const auto& p : pairs_) {
    if (!p->enforcement->augmented()) continue;
    const auto& slaves = state.pairs[p->row];
    const double tolerance = p->resolved->tolerance;
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (p->node_pressure(i, slaves[i]) <= 0.0) continue;
      const double pen = p->enforcement->penetration(p->node_gap(i));
      if (pen > tolerance) c.converged = false;
      if (pen / tolerance > worst_ratio) {
        worst_ratio = pen / tolerance;
        c.max_penetration = pen;
        c.tolerance = tolerance;
        c.node = p->kin[i].node;
      }
    }
  }
  return c;
}

namespace {

/// The penetration, as a fraction of the characteristic length, beyond which the end of a step
/// warns. Surface to surface takes a point behind a facing master facet as penetrating only
/// within half that facet's size (surface_to_surface.cpp, project_onto_facing), and facets
/// range about the median size; a quarter of it keeps the warning ahead of that rule.
/// Enforcement within its defaults stays far below: penalty p/(10 k_e) is about 1e-3 of the
/// length at a strain of 1 %, augmented Lagrange's tolerance 5 % at most.
constexpr double kTrustedDepthFraction = 0.25;

}  // namespace

std::optional<std::string> ContactProblem::deep_penetration_warning() const {
  const Pair* deepest_pair = nullptr;
  std::size_t deepest_node = 0;
  double deepest = 0.0;  // as a fraction of the pair's l_char
  for (const auto& p : pairs_)
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (!p->kin[i].found || !(p->l_char > 0.0)) continue;
      const double depth = -p->kin[i].projection.gap / p->l_char;
      if (depth > deepest) {
        deepest = depth;
        deepest_pair = p.get();
        deepest_node = i;
      }
    }
  if (!deepest_pair || deepest <= kTrustedDepthFraction) return std::nullopt;
  return fmt::format("warning: {} penetrates its master by {:.4g}, {:.0f} % of the characteristic length {:.4g}: at such depths "
                     "contact cannot tell a penetration from the far side of a body, and the contact area and pressure "
                     "may be wrong; the contact stiffness is too soft for this load",
                     node_name(*deepest_pair, deepest_node), -deepest_pair->kin[deepest_node].projection.gap,
                     100.0 * deepest, deepest_pair->l_char);
}

AugmentedPenetrations ContactProblem::augmented_penetrations() const {
  AugmentedPenetrations out;
  for (const auto& p : pairs_) {
    if (!p->enforcement->augmented()) continue;
    auto& pens = out.pairs.emplace_back(p->kin.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < p->kin.size(); ++i)
      if (p->kin[i].found) pens[i] = p->enforcement->penetration(p->node_gap(i));
  }
  return out;
}

namespace {

/// The smallest fraction of a correction overshoot_fraction() and slip_reversal_fraction() keep:
/// Newton must still move.
constexpr double kMinCorrectionFraction = 1e-2;
/// The penetration, as a fraction of the pair's tolerance, a node may reach in one correction
/// while no node of its pair penetrates beyond round-off: such a pair must be able to close one.
constexpr double kFreePenetrationFraction = 1e-2;

}  // namespace

double ContactProblem::overshoot_fraction(const AugmentedPenetrations& before) const {
  const AugmentedPenetrations after = augmented_penetrations();
  if (after.pairs.size() != before.pairs.size()) return 1.0;
  double fraction = 1.0;
  std::size_t row = 0;
  for (const auto& p : pairs_) {
    if (!p->enforcement->augmented()) continue;
    const auto& b = before.pairs[row];
    const auto& a = after.pairs[row++];
    if (a.size() != b.size()) continue;
    // A node that closes may go as deep as the deepest one of its pair was: no deeper pressure
    // than the pair already carries (at 1000 k_e, 1 % of the tolerance is tens of times the
    // depth of a pressure like p0: a body held by a force alternated between sinking into a
    // ring of such nodes and being thrown off by them).
    // (A penetration within round-off of touching is none.)
    double deepest = 0.0;
    for (double h : b) deepest = std::max(deepest, h);
    if (deepest <= kTouchingTolerance * p->l_char) deepest = kFreePenetrationFraction * p->resolved->tolerance;
    // Only nodes that were open overshoot: their stiffness was not in the tangent. Gaps change
    // nearly linearly along one correction: interpolate where such a node reaches the depth.
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] > deepest && b[i] < 0.0 && std::isfinite(b[i]))
        fraction = std::min(fraction, (deepest - b[i]) / (a[i] - b[i]));
  }
  return std::max(fraction, kMinCorrectionFraction);
}

namespace {

/// A node whose slip carries a force: with μ p = 0 (a pair's friction ramped to nothing, a
/// closed node without pressure) no force flips when its slip turns.
bool slips_with_force(const FrictionNodeState& f) {
  return f.active && f.slipping && f.tau[0] * f.tau[0] + f.tau[1] * f.tau[1] + f.tau[2] * f.tau[2] > 0.0;
}

}  // namespace

SlippingTrials ContactProblem::slipping_trials(const ContactState& state) const {
  SlippingTrials out;
  for (const auto& p : pairs_) {
    if (!p->friction) continue;
    const auto& nodes = state.friction[p->row];
    auto& trials = out.emplace_back(nodes.size(), std::array<double, 3>{});
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (slips_with_force(nodes[i])) trials[i] = nodes[i].trial;
  }
  return out;
}

double ContactProblem::slip_reversal_fraction(const SlippingTrials& before, const ContactState& state) const {
  double fraction = 1.0;
  std::size_t row = 0;
  for (const auto& p : pairs_) {
    if (!p->friction) continue;
    if (row >= before.size()) return 1.0;
    const auto& trials = before[row++];
    const auto& nodes = state.friction[p->row];
    if (trials.size() != nodes.size()) continue;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (!slips_with_force(nodes[i])) continue;
      const auto& b = trials[i];
      const auto& a = nodes[i].trial;
      const double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
      const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      if (!(bb > 0.0 && ab < 0.0)) continue;
      // e_tr(f) = b + f (a − b) is perpendicular to b at f = b·b / (b·b − a·b). Below the floor
      // the cut stops at the floor; a node already as far out the other way there as it was
      // (|e_tr| ≥ |b|, beyond its stick zone) slips the other way at the floor too: cutting
      // gains nothing, so it does not limit.
      const double f = bb / (bb - ab);
      if (f >= kMinCorrectionFraction) {
        fraction = std::min(fraction, f);
        continue;
      }
      double at_floor = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double e = b[c] + kMinCorrectionFraction * (a[c] - b[c]);
        at_floor += e * e;
      }
      if (at_floor < bb) fraction = std::min(fraction, kMinCorrectionFraction);
    }
  }
  return fraction;
}

void ContactProblem::augment(ContactState& state) const {
  for (const auto& p : pairs_) {
    if (!p->enforcement->augmented()) continue;
    auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) p->enforcement->augment(slaves[i], p->node_gap(i));
  }
}

// --- Output ------------------------------------------------------------------------------

ContactResults ContactProblem::results(std::span<const double> u, const ContactState& state) {
  evaluate(u);
  ContactResults out;
  for (const auto& p : pairs_) {
    const auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      const auto& k = p->kin[i];
      ContactNodeResult r;
      r.pair = p->row;
      r.node = k.node;
      r.copen = k.found ? k.projection.gap : std::numeric_limits<double>::quiet_NaN();
      const contact::NodePressure np = p->enforcement->output(slaves[i], p->node_gap(i));
      r.cpress = np.pressure;
      r.cstatus = np.closed ? ContactStatus::Slipping : ContactStatus::Open;  // frictionless: closed = slipping
      r.cnarea = np.closed ? k.area : 0.0;
      if (k.found)
        for (int c = 0; c < 3; ++c) r.cfn[c] = r.cpress * k.area * k.projection.normal[c];
      if (p->friction) friction_results(*p, i, state.friction[p->row][i], np.closed, r);
      out.push_back(r);
    }
  }
  return out;
}

void ContactProblem::friction_results(const Pair& p, std::size_t i, const FrictionNodeState& f, bool closed,
                                      ContactNodeResult& r) const {
  // The trial state of the last update is the converged one (no correction followed it).
  const auto& k = p.kin[i];
  r.cslip = f.slip;
  if (!closed || !f.active) return;
  r.cstatus = f.slipping ? ContactStatus::Slipping : ContactStatus::Sticking;
  const auto& t1 = k.projection.t1;
  const auto& t2 = k.projection.t2;
  // On the slave: −τ.
  r.cshear[0] = -(t1[0] * f.tau[0] + t1[1] * f.tau[1] + t1[2] * f.tau[2]);
  r.cshear[1] = -(t2[0] * f.tau[0] + t2[1] * f.tau[1] + t2[2] * f.tau[2]);
  for (int c = 0; c < 3; ++c) r.cfs[c] = -k.area * f.tau[c];
}

// --- Contact stabilization ---------------------------------------------------------------

bool ContactProblem::has_damping() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->resolved->stabilization.has_value(); });
}

void ContactProblem::set_damping(const StepConditions& conditions, std::span<const double> u_start, double t, double dt,
                                 int increment, double period) {
  damping_u_start_.assign(u_start.begin(), u_start.end());
  for (auto& p : pairs_) {
    const auto& rule = p->resolved->stabilization;
    if (!rule) continue;
    const double a = rule->amplitude.empty() ? 0.0 : conditions.amplitude_value(rule->amplitude, t);
    p->damping_stiffness = std::max(0.0, rule->scale_at(t, period, increment, a)) * rule->coefficient / dt;
  }
}

void ContactProblem::assemble_damping(const Pair& p, std::size_t i, std::span<double> f_int, Assembler& assembler) {
  // σ_stab = k s_gap Δu_rel on the node's gap kinematics (contact::damping_contribution); the
  // tangent's skew part (the tangential rows' s_gap slope) is left out: the scatter is symmetric.
  const contact::SlaveKinematics& kin = p.kin[i];
  const contact::StabilizationRule& rule = *p.resolved->stabilization;
  std::vector<std::int64_t> dofs;
  for (std::int32_t node : kin.lin.nodes)
    for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * am_.dim + c);
  std::vector<double> du(dofs.size());
  for (std::size_t a = 0; a < dofs.size(); ++a)
    du[a] = evaluated_u_[dofs[a]] - damping_u_start_[dofs[a]];  // evaluated_u_: the u of this update
  contact::DampingInput in{.gradient = kin.lin.gradient, .normal = kin.projection.normal, .t1 = kin.projection.t1,
                           .t2 = kin.projection.t2, .dim = am_.dim, .du = du, .area = kin.area,
                           .gap = kin.projection.gap, .range = rule.range, .stiffness = p.damping_stiffness,
                           .tangent_fraction = rule.tangent_fraction};
  contact::DampingContribution out;
  contact::damping_contribution(in, out);
  const std::size_t n = dofs.size();
  for (std::size_t a = 0; a < n; ++a) {
    f_int[dofs[a]] += out.force[a];
    for (std::size_t b = a + 1; b < n; ++b) out.tangent[a * n + b] = out.tangent[b * n + a] =
        0.5 * (out.tangent[a * n + b] + out.tangent[b * n + a]);
  }
  assembler.add_local_matrix(dofs, out.tangent);
  damping_dissipated_ += out.dissipated;
}

}  // namespace inpact::solver
