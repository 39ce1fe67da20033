#include "contact_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "contact/friction.hpp"
#include "contact/geometric_correction.hpp"
#include "contact/node_to_surface.hpp"
#include "contact/normal_behavior.hpp"
#include "contact/surface_to_surface.hpp"
#include "contact/pressure_overclosure.hpp"

namespace inpact::solver {

namespace {

using model::EnforcementMethod;
using model::PressureOverclosure;

/// A node changing status more often than this within one increment attempt is chattering:
/// the attempt is cut back (inpact's choice; Abaqus does not publish its rule).
constexpr int kMaxStatusChanges = 5;

/// The *CONTACT CONTROLS in force for `pair` in step `step`: the pair's own over the global
/// ones, carried over from earlier steps until RESET.
const model::ContactControls* controls_for(const model::Model& m, std::size_t step, const model::ContactPair& pair) {
  const model::ContactControls *global = nullptr, *specific = nullptr;
  for (std::size_t s = 0; s <= step && s < m.steps.size(); ++s)
    for (const auto& c : m.steps[s].contact_controls) {
      const bool all = c.master.empty() && c.slave.empty();
      const bool mine = c.master == pair.master && c.slave == pair.slave;
      if (c.reset) {
        if (all) global = specific = nullptr;
        if (mine) specific = nullptr;
      }
      if (all) global = &c;
      else if (mine) specific = &c;
    }
  return specific ? specific : global;
}

const model::SurfaceInteraction* interaction_of(const model::Model& m, const model::ContactPair& p) {
  auto it = m.interactions.find(p.interaction);
  return it == m.interactions.end() ? nullptr : &it->second;
}

[[noreturn]] void refuse(const model::Model& m, const model::SourceLoc& loc, const std::string& keyword,
                         const std::string& what) {
  throw AnalysisError(fmt::format("{}: error: {}: {}", m.sources.describe(loc), keyword, what));
}

/// Adds k (n × n, row-major, on global DOFs `dofs`) into the reduced tangent's upper triangle.
void add_matrix(Assembler& assembler, std::span<const std::int64_t> dofs, std::span<const double> k) {
  const DofMap& map = assembler.dofs();
  SparseMatrix& t = assembler.tangent();
  const std::size_t n = dofs.size();
  for (std::size_t a = 0; a < n; ++a)
    for (const auto& ma : map.masters(dofs[a])) {
      const std::int64_t ea = map.equation(ma.dof);
      if (ea < 0) continue;
      for (std::size_t b = 0; b < n; ++b) {
        const double kab = k[a * n + b];
        if (kab == 0.0) continue;
        for (const auto& mb : map.masters(dofs[b])) {
          const std::int64_t eb = map.equation(mb.dof);
          if (eb < ea) continue;
          const std::int64_t pos = t.find(ea, eb);
          if (pos >= 0) t.values[pos] += ma.weight * mb.weight * kab;
        }
      }
    }
}

/// The equations a local unknown feeds, with their weights (the DOF map's masters of a DOF, or
/// a multiplier's own equation).
using LocalEquations = std::vector<std::vector<std::pair<std::int64_t, double>>>;

/// Adds a local matrix k (n × n, row-major, n = eqs.size()) that need not be symmetric: its
/// symmetric part ½(k + kᵀ) into the upper triangle `t`, its skew part ½(k − kᵀ) (when not
/// zero) to `skew`.
template <class Skew>
void add_unsymmetric(SparseMatrix& t, const LocalEquations& eqs, std::span<const double> k, std::vector<Skew>& skew) {
  const std::size_t n = eqs.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a; b < n; ++b) {
      const double sym = a == b ? k[a * n + a] : 0.5 * (k[a * n + b] + k[b * n + a]);
      const double skw = a == b ? 0.0 : 0.5 * (k[a * n + b] - k[b * n + a]);
      if (sym == 0.0 && skw == 0.0) continue;
      for (const auto& [ea, wa] : eqs[a])
        for (const auto& [eb, wb] : eqs[b]) {
          // Entry (ea, eb) gets w (sym + skw), entry (eb, ea) w (sym − skw); when a ≠ b both land
          // in the upper triangle's one position for the symmetric part.
          const double w = wa * wb;
          if (sym != 0.0) {
            const std::int64_t pos = t.find(std::min(ea, eb), std::max(ea, eb));
            if (pos >= 0) t.values[pos] += (ea == eb && a != b ? 2.0 : 1.0) * w * sym;
          }
          if (skw != 0.0 && ea != eb) {
            skew.push_back({ea, eb, w * skw});
            skew.push_back({eb, ea, -w * skw});
          }
        }
    }
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
    if (c.slave != pair.slave || c.master != pair.master) continue;
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

/// One contact pair in force: its geometry, enforcement and the last kinematics.
struct ContactProblem::Pair {
  std::int32_t row = 0;
  const model::ContactPair* deck = nullptr;
  std::unique_ptr<contact::PairKinematics> geometry;
  contact::ResolvedNormalBehavior behavior;
  std::optional<contact::PressureOverclosure> law;  ///< unset: direct hard contact
  std::optional<contact::FrictionLaw> friction;     ///< unset: frictionless
  bool direct = false, augmented = false, softened = false, finite_sliding = true, surface_to_surface = false;
  bool general = false;  ///< a row general contact made
  bool smoothed = false;  ///< geometric correction of either surface
  /// NO SEPARATION (or a TIED pair): a closed node never opens; its pressure may turn tensile.
  bool no_separation = false;
  bool tied_law = false;  ///< CalculiX PRESSURE-OVERCLOSURE=TIED
  /// A penalty-type law with slope > 1000 k_e, enforced with multipliers (table 38.1.21).
  bool stiff = false;
  bool uses_multipliers() const { return direct || stiff; }
  double weight = 1.0;   ///< balanced master-slave: ½ (the slave areas are scaled by it)
  double ke = 0.0, l_char = 0.0, tolerance = 0.0, hcrit = 0.0;
  std::vector<contact::SlaveKinematics> kin;
  std::vector<char> contributes;           ///< per slave node, at the last update
  std::vector<std::int64_t> multiplier;    ///< per slave node: multiplier index or −1
  std::vector<contact::FrictionPoint> fric;  ///< frictional pairs: per slave node, at the last update
  /// *CLEARANCE: per slave node, what is added to the measured gap so that the gap in the
  /// reference configuration is the clearance given (empty: no *CLEARANCE for this pair).
  std::vector<double> gap_offset;

  double gap(std::size_t i) const { return kin[i].found ? kin[i].projection.gap : std::numeric_limits<double>::infinity(); }
  /// USER ADAPTIVE (and not enforced with multipliers): the law's factor of the moment.
  bool user_adaptive = false;
  double adaptive_scale = 1.0;

  /// Penalty-type pressure of slave i (λ: its augmented-Lagrange multiplier).
  contact::PressureValue pressure(std::size_t i, double lambda) const {
    if (!kin[i].found) return {};
    contact::PressureValue v = law->eval(-kin[i].projection.gap, augmented ? lambda : 0.0);
    if (user_adaptive) {
      v.p *= adaptive_scale;
      v.dp *= adaptive_scale;
    }
    return v;
  }
  /// The contact pressure of slave i as the enforcement gives it: direct −λ, a stiff law's −multiplier
  /// (closed nodes; never tensile), else the law at the gap.
  double node_pressure(std::size_t i, const SlaveState& s) const {
    if (direct) return s.closed && kin[i].found ? std::max(-s.lambda, 0.0) : 0.0;
    if (stiff) return s.closed && kin[i].found ? std::max(-s.multiplier, 0.0) : 0.0;
    return pressure(i, s.lambda).p;
  }
  /// A stiff law's node: the overclosure h at which the law gives the pressure p = −multiplier,
  /// and the slope p'(h) there. A tensile p (possible within the iterations) continues the law
  /// linearly below its first pressure, so the constraint stays smooth.
  struct LawPoint {
    double h = 0.0, dp = 0.0;
  };
  LawPoint law_overclosure(const SlaveState& s) const {
    const double p = -s.multiplier;
    const double p_small = 1e-12 * std::max(ke * l_char, std::abs(s.lambda));
    LawPoint out;
    if (p > p_small) {
      out.dp = law->inverse(p, s.lambda, &out.h).dp;
      return out;
    }
    out.dp = law->inverse(p_small, s.lambda, &out.h).dp;
    if (out.dp > 0.0) out.h += (p - p_small) / out.dp;
    return out;
  }

  /// The contact pressure friction sees.
  double friction_pressure(std::size_t i, const SlaveState& s) const { return node_pressure(i, s); }

  /// Friction of slave i off (open, or not yet evaluated): the trial state keeps its slip.
  void clear_friction(std::size_t i, FrictionNodeState& f) {
    f.active = f.slipping = false;
    f.facet = -1;
    f.e = f.tau = {0, 0, 0};
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

  /// The return mapping of closed slave i (kin[i].lin filled) into `f` and fric[i].
  void update_friction(std::size_t i, const SlaveState& s, FrictionNodeState& f, std::span<const contact::Vec3> x) {
    const contact::Projection& pr = kin[i].projection;
    const auto facets = geometry->master().facets();
    if (f.anchor_facet < 0) {  // first touch in this increment: the zero-shear point is here
      f.anchor_facet = pr.facet;
      f.anchor_xi = pr.xi;
    }
    contact::FrictionAnchor anchor{f.anchor_facet, f.anchor_xi};
    fric[i] = contact::friction_point(*friction, facets[static_cast<std::size_t>(pr.facet)], pr, friction_lin(i),
                                      facets[static_cast<std::size_t>(f.anchor_facet)], anchor, f.e0,
                                      friction_pressure(i, s), x);
    const contact::FrictionPoint& fp = fric[i];
    f.active = true;
    f.slipping = fp.slipping;
    f.facet = pr.facet;
    f.xi = pr.xi;
    f.e = fp.elastic_slip;
    f.tau = fp.traction;
    const auto& ds = fp.slip_increment;
    f.slip[0] = f.slip0[0] + pr.t1[0] * ds[0] + pr.t1[1] * ds[1] + pr.t1[2] * ds[2];
    f.slip[1] = f.slip0[1] + pr.t2[0] * ds[0] + pr.t2[1] * ds[1] + pr.t2[2] * ds[2];
  }
};

// --- Setup -------------------------------------------------------------------------------


ContactProblem::ContactProblem(const AnalysisModel& am, std::size_t step_index) : am_(am) {
  const model::Model& m = *am.model;
  const auto& table = am.contact->rows;
  n_pairs_total_ = table.size();
  for (std::size_t row = 0; row < table.size(); ++row) {
    const contact::ContactInteraction& entry = table[row];
    if (entry.first_step > step_index) continue;
    const model::ContactPair& deck = entry.pair;
    const std::string keyword = entry.general ? "*CONTACT" : "*CONTACT PAIR";
    auto p = std::make_unique<Pair>();
    p->row = static_cast<std::int32_t>(row);
    p->deck = &deck;
    const model::SurfaceInteraction* inter = interaction_of(m, deck);
    contact::NormalBehaviorOptions options;
    options.controls = controls_for(m, step_index, deck);
    // Self-contact: augmented Lagrange by default (Abaqus's for 3-D node to surface; inpact's in
    // 2D too, where Abaqus would use multipliers that a two-sided contact would duplicate).
    options.self_contact_3d = deck.slave == deck.master;
    p->behavior = contact::resolve_normal_behavior(inter, deck.type, deck.small_sliding, entry.general, options);
    p->weight = entry.weight;
    p->general = entry.general;
    p->finite_sliding = !deck.small_sliding;
    p->surface_to_surface = deck.type == model::ContactDiscretization::SurfaceToSurface;
    const double thickness = inter ? inter->out_of_plane_thickness : 1.0;
    if (p->surface_to_surface) {
      auto s2s = std::make_unique<contact::SurfaceToSurfacePair>(m, *entry.slave, *entry.master, am.dim, thickness);
      // Smoothing: the pair's *SURFACE SMOOTHING, or general contact's *SURFACE PROPERTY
      // ASSIGNMENT lines (a body's exterior, which has no name in the deck, takes every line
      // whose surface it contains). Validated when the analysis model was built.
      auto deck_name = [&](const model::Surface* s) {
        const auto it = m.mesh.surfaces.find(s->name);
        return it != m.mesh.surfaces.end() && &it->second == s ? s->name : std::string();
      };
      const model::ContactPair* named = entry.general ? nullptr : &deck;
      auto master_c = contact::build_corrections(m, deck_name(entry.master), named);
      auto slave_c = contact::build_corrections(m, deck_name(entry.slave), named);
      p->smoothed = !master_c.empty() || !slave_c.empty();
      if (p->smoothed) s2s->set_geometric_correction(std::move(master_c), std::move(slave_c));
      p->geometry = std::move(s2s);
    } else
      p->geometry = std::make_unique<contact::NodeToSurfacePair>(m, *entry.slave, *entry.master, am.dim, thickness);
    p->geometry->set_area_weight(entry.weight);
    p->geometry->set_self_contact(deck.slave == deck.master);

    // k_e and the characteristic length from the slave surface (the master when the slave is
    // node based), contact/normal_behavior.cpp.
    auto scales = contact::surface_scales(m, *entry.slave);
    if (!scales) scales = contact::surface_scales(m, *entry.master);
    // A balanced two-row interaction (general contact): both rows take the mean of the two
    // surfaces' scales, so they hold one law, see the same gap, and each reports the pressure
    // that acts (with a row's own k_e one surface showed 2/3 p and the other 4/3 p).
    if (entry.general && entry.weight != 1.0 && entry.slave != entry.master) {
      const auto other = contact::surface_scales(m, *entry.master);
      if (scales && other) {
        scales->element_stiffness = 0.5 * (scales->element_stiffness + other->element_stiffness);
        scales->characteristic_length = 0.5 * (scales->characteristic_length + other->characteristic_length);
      }
    }
    p->ke = scales ? scales->element_stiffness : 0.0;
    p->l_char = scales ? scales->characteristic_length : p->geometry->search_radius();

    const auto& b = p->behavior;
    p->softened = b.law != PressureOverclosure::Hard;
    p->direct = (b.method == EnforcementMethod::Direct && !p->softened) || deck.tied;
    // TIED (after ADJUST): direct hard contact that never separates, and no slip (ROUGH).
    // CalculiX's PRESSURE-OVERCLOSURE=TIED: a bonded spring p = k h from the initial gap (its
    // offsets below), tension included, and no slip at the *FRICTION stick slope.
    p->tied_law = b.law == PressureOverclosure::Tied;
    p->no_separation = b.deck.no_separation || deck.tied || p->tied_law;
    p->augmented = b.method == EnforcementMethod::AugmentedLagrange && !deck.tied;
    if (deck.tied) p->softened = false;
    const std::string pair_name = deck.slave + "/" + deck.master;
    if (!p->direct) {
      if (!p->softened && !b.given_stiffness && !scales)
        refuse(m, deck.loc, keyword, fmt::format("pair {}: the default penalty stiffness needs an element-based surface "
                                                 "with an elastic material; give the stiffness on *SURFACE BEHAVIOR", pair_name));
      p->law = contact::PressureOverclosure::from(b, p->ke, p->l_char);
      // Table 38.1.21: Lagrange multipliers above 1000 k_e (the law's slope at zero clearance;
      // exponential: at h = 0; a relative margin: 100 × 10 k_e must not exceed 1000 k_e by
      // round-off). Without k_e (node-based slave and master) there is nothing to compare with.
      const double slope = p->law->max_slope(0.0);
      p->stiff = scales && slope > 1000.0 * p->ke * (1.0 + 1e-12);
      p->user_adaptive = b.user_adaptive_stiffness && !p->stiff;
    }
    if (p->augmented) p->tolerance = *contact::penetration_tolerance(b, p->l_char);
    p->hcrit = p->softened ? std::numeric_limits<double>::infinity() : deck.hcrit.value_or(0.5 * p->l_char);
    // Friction: γ_crit from the same characteristic length (KEYWORDS.md Part C c).
    model::Friction tie;
    if (p->tied_law && inter && inter->friction) tie = *inter->friction;
    tie.rough = true;
    const bool tied = deck.tied || p->tied_law;
    p->friction = contact::resolve_friction(tied ? &tie : inter && inter->friction ? &*inter->friction : nullptr,
                                            p->l_char, p->ke);
    if (p->tied_law && tie.stick_slope) p->friction->fixed_stiffness = *tie.stick_slope;  // CalculiX's λ
    if (p->friction && p->friction->rough && !(p->ke > 0.0))
      refuse(m, inter->friction->loc, "*FRICTION", fmt::format("pair {}: ROUGH friction needs the element stiffness k_e of "
                                                               "an element-based surface with an elastic material", pair_name));
    if (!entry.general) p->gap_offset = clearance_offsets(m, deck, *p->geometry);
    if (p->tied_law) p->gap_offset = tied_offsets(m, *p->geometry);
    // A balanced interaction whose law goes to multipliers (stiffer than 1000 k_e) would hold
    // two multipliers on one gap: its first row takes the whole weight, the second is dropped.
    if (p->stiff && entry.general && entry.weight != 1.0 && entry.slave != entry.master) {
      const bool second = row > 0 && table[row - 1].general && table[row - 1].slave == entry.master &&
                          table[row - 1].master == entry.slave;
      if (second) continue;
      p->weight = 1.0;
      p->geometry->set_area_weight(1.0);
    }
    pairs_.push_back(std::move(p));
  }
}

ContactProblem::~ContactProblem() = default;

bool ContactProblem::empty() const { return pairs_.empty(); }

bool ContactProblem::has_friction() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->friction.has_value(); });
}

bool ContactProblem::has_user_adaptive() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->user_adaptive; });
}

bool ContactProblem::has_augmented_lagrange() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->augmented; });
}

std::vector<std::string> ContactProblem::describe() const {
  std::vector<std::string> out;
  for (const auto& p : pairs_) {
    std::string s = fmt::format("{} {}/{}: {}, {}", p->general ? "general contact" : "contact pair", p->deck->slave,
                                p->deck->master,
                                p->surface_to_surface ? "surface to surface" : "node to surface",
                                p->law ? p->law->describe() : std::string("direct hard contact (Lagrange multipliers)"));
    s += fmt::format("; k_e = {:.4g}, characteristic length {:.4g}", p->ke, p->l_char);
    if (p->augmented) s += fmt::format(", augmented Lagrange, penetration tolerance {:.4g}", p->tolerance);
    if (p->stiff) s += ", Lagrange multipliers (slope > 1000 k_e)";
    if (p->smoothed) s += "; smoothed (geometric correction)";
    if (p->weight != 1.0) s += fmt::format("; weight {:g} (balanced master-slave)", p->weight);
    s += p->friction ? "; " + contact::describe(*p->friction) : std::string("; frictionless");
    out.push_back(std::move(s));
  }
  return out;
}

void check_contact_supported(const model::Model& m, const contact::InteractionTable& table) {
  for (const contact::ContactInteraction& e : table.rows) {
    const model::ContactPair& p = e.pair;
    const std::string kw = e.general ? "*CONTACT" : "*CONTACT PAIR";
    if (p.type == model::ContactDiscretization::SurfaceToSurface && e.slave->kind != model::Surface::Kind::Element)
      refuse(m, p.loc, kw, fmt::format("TYPE=SURFACE TO SURFACE needs an element-based slave surface; {} is node based "
                                       "(use TYPE=NODE TO SURFACE)", p.slave));
    if (p.slave == p.master) {
      contact::NormalBehaviorOptions options;
      options.self_contact_3d = true;
      const auto r = contact::resolve_normal_behavior(interaction_of(m, p), p.type, p.small_sliding, e.general, options);
      if (r.method == EnforcementMethod::Direct)
        refuse(m, p.loc, kw, fmt::format("self-contact of {} with direct enforcement is not analysed (every contact "
                                         "would be constrained twice, once from each side); use AUGMENTED LAGRANGE (the "
                                         "default for self-contact) or PENALTY", p.slave));
    }
    if ((p.adjust_distance || !p.adjust_nset.empty()) && e.step_data)
      refuse(m, p.loc, kw, "ADJUST on a contact pair defined in a step is not analysed by this version of inpact "
                           "yet; define the pair in the model data");
    if ((p.adjust_distance || !p.adjust_nset.empty()) && !m.adjusted)
      refuse(m, p.loc, kw, "ADJUST: the model was not adjusted before the analysis (contact::apply_adjust)");
    if (e.master->kind != model::Surface::Kind::Element)
      refuse(m, p.loc, kw, fmt::format("the master surface {} is node based; a master surface must be made of element faces", p.master));
    const model::SurfaceInteraction* inter = interaction_of(m, p);
    if (!inter) continue;
    if (inter->behavior) {
      const auto& b = *inter->behavior;
      if (b.no_separation && !p.tied) {
        const auto r = contact::resolve_normal_behavior(inter, p.type, p.small_sliding, e.general);
        if (r.method != EnforcementMethod::Direct || r.law != PressureOverclosure::Hard)
          refuse(m, b.loc, "*SURFACE BEHAVIOR", "NO SEPARATION is analysed with direct hard contact only (a closed node "
                                                "keeps its multiplier, which may turn tensile); add DIRECT or drop the "
                                                "penalty or softened law");
      }
    }
  }
}

// --- Iterations --------------------------------------------------------------------------

void ContactProblem::begin_attempt(ContactState& state, int step, int increment, std::span<const double> u_start) {
  state.pairs.resize(n_pairs_total_);
  evaluate(u_start);
  const bool new_increment = state.friction_increment != std::array<int, 2>{step, increment};
  state.friction_increment = {step, increment};
  for (const auto& p : pairs_) {
    auto& s = state.pairs[p->row];
    s.resize(p->geometry->slave().nodes().size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      s[i].flips = 0;
      s[i].start_penetration = p->kin[i].found ? std::max(0.0, -p->gap(i)) : 0.0;
    }
    if (!p->friction) continue;
    if (state.friction.size() < n_pairs_total_) state.friction.resize(n_pairs_total_);
    auto& fs = state.friction[p->row];
    fs.resize(s.size());
    if (!new_increment) continue;
    // Commit the converged trial state as the start of the new increment.
    for (FrictionNodeState& f : fs) {
      f.anchor_facet = f.active ? f.facet : -1;
      f.anchor_xi = f.xi;
      f.e0 = f.active ? f.e : std::array<double, 3>{0, 0, 0};
      f.slip0 = f.slip;
    }
  }
}

void ContactProblem::evaluate(std::span<const double> u) {
  for (auto& p : pairs_) p->adaptive_scale = adaptive_scale_;
  if (evaluated_ && std::equal(u.begin(), u.end(), evaluated_u_.begin(), evaluated_u_.end())) return;
  evaluated_u_.assign(u.begin(), u.end());
  evaluated_ = true;
  const auto x = contact::current_coordinates(am_.model->mesh.nodes, u, am_.dim);
  for (auto& p : pairs_) {
    p->geometry->update(x, p->kin);
    for (std::size_t i = 0; i < p->gap_offset.size(); ++i)
      if (p->kin[i].found) p->kin[i].projection.gap += p->gap_offset[i];
  }
}

ContactIteration ContactProblem::update(std::span<const double> u, ContactState& state, Assembler& assembler) {
  evaluate(u);
  const auto x = contact::current_coordinates(am_.model->mesh.nodes, u, am_.dim);
  const auto& labels = am_.model->mesh.nodes.labels;
  ContactIteration it;
  std::vector<std::int64_t> signature;
  multipliers_.clear();
  for (std::size_t pi = 0; pi < pairs_.size(); ++pi) {
    Pair& p = *pairs_[pi];
    auto& slaves = state.pairs[p.row];
    const std::size_t n = p.kin.size();
    p.contributes.assign(n, 0);
    p.multiplier.assign(n, -1);
    if (p.friction) p.fric.resize(n);
    // Direct: a closed node opens when its pressure −λ turns tensile (beyond round-off of the
    // pair's pressures); an open one closes when it penetrates (or touches within round-off).
    double p_scale = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (slaves[i].closed) p_scale = std::max(p_scale, std::abs(p.stiff ? slaves[i].multiplier : slaves[i].lambda));
    // A stiff law's node touching at zero pressure carries round-off of its slope × length:
    // not a reason to open (it would close again at once: chattering).
    if (p.stiff) p_scale = std::max(p_scale, 1e-4 * p.law->max_slope(0.0) * p.l_char);
    const double open_below = -1e-8 * p_scale, close_below = 1e-9 * p.l_char;
    for (std::size_t i = 0; i < n; ++i) {
      SlaveState& s = slaves[i];
      const double g = p.gap(i);
      bool closed = false;
      if (p.direct) {
        closed = p.kin[i].found && (s.closed ? (p.no_separation || -s.lambda >= open_below) : g < close_below);
        if (!closed) s.lambda = 0.0;
        p.contributes[i] = closed;
        if (closed) it.max_gap_error = std::max(it.max_gap_error, std::abs(g));
      } else if (p.stiff) {
        // As direct, with the law deciding closure: closed while the multiplier's pressure is
        // compressive, closing where the law acts (touching included), from the law's pressure.
        const auto law = p.pressure(i, s.lambda);
        closed = p.kin[i].found && (s.closed ? (p.no_separation || -s.multiplier >= open_below) : law.active);
        if (closed && !s.closed) s.multiplier = -law.p;
        if (!closed) s.multiplier = 0.0;
        p.contributes[i] = closed;
      } else {
        const auto pv = p.pressure(i, s.lambda);
        closed = p.tied_law ? pv.active : pv.p > 0.0;  // a tied node is closed in tension too
        // Damping an augmented-Lagrange node that keeps crossing the law's kink: after two
        // crossings in this attempt its stiffness stays in the tangent while it is open (the
        // force is still the law's), so Newton stops bouncing between the branches at 1000 k_e
        // (the interference fit's faceting noise). Not for plain penalty: there the modified
        // tangent turned Hertz's quadratic convergence linear (22 → 77 iterations).
        // A node touching within round-off (g < 1e-9 l_char) brings the law's first slope too:
        // a penalty law acts only from h + c0 ≥ 0, and a gap of +1e-12 would otherwise leave a
        // body that rests on its contact with no stiffness at all (bench/contact_extremes).
        const bool touching = p.kin[i].found && g < close_below;
        p.contributes[i] = pv.active || touching || (p.augmented && p.kin[i].found && s.flips >= 2);
      }
      if (closed != s.closed) {
        ++it.status_changes;
        if (p.uses_multipliers()) it.blocks_convergence = true;
        // Chattering is a multiplier method's trouble: its status is a discontinuity Newton
        // cannot smooth over. A penalty-type law is continuous (a kink at first pressure), so a
        // node crossing it is an ordinary Newton iteration and the iteration limits apply.
        ++s.flips;
        if (p.uses_multipliers() && s.flips > kMaxStatusChanges && it.failure.empty())
          it.failure = fmt::format("contact chattering: slave node {} of pair {}/{} changed status {} times in this "
                                   "increment", labels[p.kin[i].node], p.deck->slave, p.deck->master, s.flips);
      }
      s.closed = closed;
      if (p.kin[i].found) {
        s.last_facet = p.kin[i].projection.facet;
      } else if (s.closed && s.last_facet >= 0 && it.failure.empty()) {
        // A closed node that lost its master: slid off an edge (fine: it opens), or went through
        // the master in one overshooting iteration (the increment must be cut back). Tell them
        // apart by the side of its last facet's plane it is on.
        const contact::Facet& f = p.geometry->master().facets()[static_cast<std::size_t>(s.last_facet)];
        const contact::FacetGeometry fg = contact::facet_geometry(f, x, 0.0, 0.0);
        const auto& xs = x[static_cast<std::size_t>(p.kin[i].node)];
        const double depth = -((xs[0] - fg.x[0]) * fg.n[0] + (xs[1] - fg.x[1]) * fg.n[1] + (xs[2] - fg.x[2]) * fg.n[2]);
        if (depth > p.hcrit)
          it.failure = fmt::format("slave node {} of pair {}/{} went through the master surface ({:.4g} behind it, "
                                   "more than HCRIT = {:.4g}) and lost it",
                                   labels[p.kin[i].node], p.deck->slave, p.deck->master, depth, p.hcrit);
      }
      if (p.kin[i].found && -g - s.start_penetration > p.hcrit && it.failure.empty())
        it.failure = fmt::format("slave node {} of pair {}/{} penetrates {:.4g} (from {:.4g} at the start of the "
                                 "increment), more than HCRIT = {:.4g}",
                                 labels[p.kin[i].node], p.deck->slave, p.deck->master, -g, s.start_penetration, p.hcrit);
      FrictionNodeState* fs = p.friction ? &state.friction[p.row][i] : nullptr;
      if (fs) p.clear_friction(i, *fs);
      if (!p.contributes[i]) continue;
      p.geometry->linearize(x, p.kin[i], p.finite_sliding);
      if (fs && closed && p.friction_found(i)) {
        p.update_friction(i, s, *fs, x);
        ++friction_evaluations_;
      }
      // The couplings this node adds: its unknowns (and whether a multiplier joins them).
      signature.insert(signature.end(), {static_cast<std::int64_t>(pi), static_cast<std::int64_t>(i), p.uses_multipliers() ? 1 : 0,
                                         static_cast<std::int64_t>(p.kin[i].lin.nodes.size())});
      signature.insert(signature.end(), p.kin[i].lin.nodes.begin(), p.kin[i].lin.nodes.end());
      if (fs && p.surface_to_surface && !p.fric[i].force.empty())
        signature.insert(signature.end(), p.kin[i].friction_lin.nodes.begin(), p.kin[i].friction_lin.nodes.end());
      if (p.uses_multipliers()) {
        p.multiplier[i] = static_cast<std::int64_t>(multipliers_.size());
        multipliers_.push_back({pi, i});
      }
    }
  }
  if (signature != signature_) {
    ExtraCouplings extra;
    for (const auto& p : pairs_)
      for (std::size_t i = 0; i < p->kin.size(); ++i) {
        if (!p->contributes[i]) continue;
        std::vector<std::int64_t> dofs = p->local_dofs(i, am_.dim);
        if (p->multiplier[i] >= 0) extra.multiplier_dofs.push_back(dofs);
        extra.dof_blocks.push_back(std::move(dofs));
      }
    assembler.set_extra_couplings(extra);
    signature_ = std::move(signature);
  }
  return it;
}

void ContactProblem::assemble(const ContactState& state, std::span<double> f_int, Assembler& assembler) {
  const std::int64_t n_eq = assembler.dofs().n_equations();
  const DofMap& map = assembler.dofs();
  std::vector<std::int64_t> dofs;
  std::vector<double> k, kf;
  LocalEquations eqs;
  skew_.clear();
  for (const auto& p : pairs_) {
    const auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (!p->contributes[i]) continue;
      const contact::GapLinearization& lin = p->kin[i].lin;
      const double area = p->kin[i].area;
      const std::size_t n = static_cast<std::size_t>(lin.n_dof);
      dofs.clear();
      for (std::int32_t node : lin.nodes)
        for (int c = 0; c < am_.dim; ++c) dofs.push_back(static_cast<std::int64_t>(node) * am_.dim + c);
      k.assign(n * n, 0.0);
      // Force f_c = s ∇g with s = λA (direct) or −pA (penalty-type); tangent s ∇²g (+ A p' ∇g∇gᵀ).
      double s = 0.0, stiff = 0.0;
      if (p->direct) {
        s = slaves[i].lambda * area;
      } else if (p->stiff) {
        s = slaves[i].multiplier * area;  // the law's stiffness is in the multiplier row's diagonal
      } else {
        const auto pv = p->pressure(i, slaves[i].lambda);
        s = -pv.p * area;
        // (an open node kept for damping, see update(), brings the law's first slope)
        stiff = (pv.active ? pv.dp : p->law->max_slope(0.0)) * area;
      }
      for (std::size_t a = 0; a < n; ++a) {
        f_int[dofs[a]] += s * lin.gradient[a];
        for (std::size_t b = 0; b < n; ++b)
          k[a * n + b] = stiff * lin.gradient[a] * lin.gradient[b] + s * lin.hessian[a * n + b];
      }
      add_matrix(assembler, dofs, k);
      if (p->friction_acts(i)) {
        // Friction: f = A Bᵀ τ; tangent A Bᵀ ∂τ/∂u + A Bᵀ ∂τ/∂p ⊗ ∂p/∂u, with ∂p/∂u = −p' ∇g
        // (penalty-type) or, direct, ∂p/∂λ = −1 in the multiplier's column. Local unknowns: the
        // union of the gap's and the friction kinematics' DOFs (the same list for node to
        // surface), then the multiplier.
        const contact::FrictionPoint& fp = p->fric[i];
        const contact::GapLinearization& flin = p->friction_lin(i);
        const std::vector<std::int64_t> all = p->local_dofs(i, am_.dim);
        auto position = [&](std::int64_t dof) {
          return static_cast<std::size_t>(std::find(all.begin(), all.end(), dof) - all.begin());
        };
        std::vector<std::size_t> fpos;  // friction unknown → union position
        for (std::int32_t node : flin.nodes)
          for (int c = 0; c < am_.dim; ++c) fpos.push_back(position(static_cast<std::int64_t>(node) * am_.dim + c));
        const bool with_multiplier = p->multiplier[i] >= 0;
        const std::size_t nu = all.size(), nl = nu + (with_multiplier ? 1 : 0), nf = fpos.size();
        eqs.assign(nl, {});
        for (std::size_t a = 0; a < nu; ++a)
          for (const auto& ma : map.masters(all[a]))
            if (const std::int64_t e = map.equation(ma.dof); e >= 0) eqs[a].push_back({e, ma.weight});
        if (with_multiplier) eqs[nu].push_back({n_eq + p->multiplier[i], 1.0});
        const double dp_dh = p->uses_multipliers() ? 0.0 : p->pressure(i, slaves[i].lambda).dp;
        kf.assign(nl * nl, 0.0);
        for (std::size_t a = 0; a < nf; ++a) {
          f_int[all[fpos[a]]] += area * fp.force[a];
          for (std::size_t b = 0; b < nf; ++b) kf[fpos[a] * nl + fpos[b]] += area * fp.tangent[a * nf + b];
          for (std::size_t b = 0; b < n; ++b) kf[fpos[a] * nl + b] -= area * fp.coupling[a] * dp_dh * lin.gradient[b];
          if (with_multiplier) kf[fpos[a] * nl + nu] = -area * fp.coupling[a];
        }
        add_unsymmetric(assembler.tangent(), eqs, kf, skew_);
      }
      if (p->multiplier[i] < 0) continue;
      // Constraint column A ∇g at the multiplier's equation (upper triangle: DOF rows < it).
      SparseMatrix& t = assembler.tangent();
      const std::int64_t em = n_eq + p->multiplier[i];
      if (p->stiff) {
        // The law's compliance: ∂(A (g + h(p)))/∂λ = −A h'(p) = −A / p'(h), p = −λ.
        const double dp = p->law_overclosure(slaves[i]).dp;
        const std::int64_t pos = t.find(em, em);
        if (pos >= 0 && dp > 0.0) t.values[pos] -= area / dp;
      }
      for (std::size_t a = 0; a < n; ++a)
        for (const auto& ma : map.masters(dofs[a])) {
          const std::int64_t ea = map.equation(ma.dof);
          if (ea < 0) continue;
          const std::int64_t pos = t.find(ea, em);
          if (pos >= 0) t.values[pos] += ma.weight * area * lin.gradient[a];
        }
    }
  }
}

void ContactProblem::constraint_residual(const ContactState& state, std::span<double> rows) const {
  for (std::size_t m = 0; m < multipliers_.size(); ++m) {
    const auto [pi, i] = multipliers_[m];
    const Pair& p = *pairs_[pi];
    // The overclosure the law gives the node's pressure (direct: none).
    const double h = p.stiff ? p.law_overclosure(state.pairs[p.row][i]).h : 0.0;
    rows[m] = -p.kin[i].area * (p.gap(i) + h);
  }
}

void ContactProblem::apply_correction(std::span<const double> rows, ContactState& state) const {
  for (std::size_t m = 0; m < multipliers_.size(); ++m) {
    const auto [pi, i] = multipliers_[m];
    SlaveState& s = state.pairs[pairs_[pi]->row][i];
    (pairs_[pi]->stiff ? s.multiplier : s.lambda) += rows[m];
  }
}

const SparseMatrix& ContactProblem::unsymmetric_tangent(const SparseMatrix& a) {
  // Mirror the upper triangle (each column comes out sorted: its own rows ≤ j first, then the
  // mirrored rows c > j in increasing c), then add the skew entries.
  std::vector<std::int64_t> count(static_cast<std::size_t>(a.n) + 1, 0);
  for (std::int64_t c = 0; c < a.n; ++c)
    for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
      ++count[c + 1];
      if (a.row_idx[k] != c) ++count[a.row_idx[k] + 1];
    }
  full_.n = a.n;
  full_.upper_only = false;
  full_.col_ptr.assign(static_cast<std::size_t>(a.n) + 1, 0);
  for (std::int64_t c = 0; c < a.n; ++c) full_.col_ptr[c + 1] = full_.col_ptr[c] + count[c + 1];
  full_.row_idx.assign(static_cast<std::size_t>(full_.col_ptr[a.n]), 0);
  full_.values.assign(static_cast<std::size_t>(full_.col_ptr[a.n]), 0.0);
  std::vector<std::int64_t> next(full_.col_ptr.begin(), full_.col_ptr.end() - 1);
  for (std::int64_t c = 0; c < a.n; ++c)
    for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
      const std::int64_t r = a.row_idx[k];
      full_.row_idx[next[c]] = r;
      full_.values[next[c]++] = a.values[k];
      if (r != c) {
        full_.row_idx[next[r]] = c;
        full_.values[next[r]++] = a.values[k];
      }
    }
  for (const SkewEntry& e : skew_)
    if (const std::int64_t pos = full_.find(e.row, e.col); pos >= 0) full_.values[pos] += e.value;
  return full_;
}

// --- Augmentations -----------------------------------------------------------------------

AugmentationCheck ContactProblem::check_augmentation(const ContactState& state) const {
  AugmentationCheck c;
  double worst_ratio = 0.0;
  for (const auto& p : pairs_) {
    if (!p->augmented) continue;
    const auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) {
      if (p->node_pressure(i, slaves[i]) <= 0.0) continue;
      // Penetration past the zero-pressure clearance: h − h_0 = c0 − g.
      const double pen = -p->gap(i) - p->law->h_zero();
      if (pen > p->tolerance) c.converged = false;
      if (pen / p->tolerance > worst_ratio) {
        worst_ratio = pen / p->tolerance;
        c.max_penetration = pen;
        c.tolerance = p->tolerance;
        c.node = p->kin[i].node;
      }
    }
  }
  return c;
}

void ContactProblem::augment(ContactState& state) const {
  for (const auto& p : pairs_) {
    if (!p->augmented) continue;
    auto& slaves = state.pairs[p->row];
    for (std::size_t i = 0; i < p->kin.size(); ++i) slaves[i].lambda = p->node_pressure(i, slaves[i]);
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
      bool closed = false;
      if (p->uses_multipliers()) {
        closed = slaves[i].closed && k.found;
        r.cpress = closed ? -(p->stiff ? slaves[i].multiplier : slaves[i].lambda) : 0.0;
      } else {
        const auto pv = p->pressure(i, slaves[i].lambda);
        r.cpress = pv.p;
        closed = p->tied_law ? pv.active : r.cpress > 0.0;
      }
      r.cstatus = closed ? ContactStatus::Slipping : ContactStatus::Open;  // frictionless: closed = slipping
      r.cnarea = closed ? k.area : 0.0;
      if (k.found)
        for (int c = 0; c < 3; ++c) r.cfn[c] = r.cpress * k.area * k.projection.normal[c];
      if (p->friction) {
        // The trial state of the last update is the converged one (no correction followed it).
        const FrictionNodeState& f = state.friction[p->row][i];
        r.cslip = f.slip;
        if (closed && f.active) {
          r.cstatus = f.slipping ? ContactStatus::Slipping : ContactStatus::Sticking;
          const auto& t1 = k.projection.t1;
          const auto& t2 = k.projection.t2;
          // On the slave: −τ.
          r.cshear[0] = -(t1[0] * f.tau[0] + t1[1] * f.tau[1] + t1[2] * f.tau[2]);
          r.cshear[1] = -(t2[0] * f.tau[0] + t2[1] * f.tau[1] + t2[2] * f.tau[2]);
          for (int c = 0; c < 3; ++c) r.cfs[c] = -k.area * f.tau[c];
        }
      }
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace inpact::solver
