#include "step_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "analysis_error.hpp"
#include "elements/face_loads.hpp"
#include "rotation_moments.hpp"

namespace inpact::solver {

namespace {

using Key = ConditionHistory::DloadKey;

/// Whether a step starts its definitions of one kind afresh: OP=NEW on any of its blocks of that
/// kind removes what earlier steps defined, not what the step's other blocks define (Abaqus/CAE
/// writes OP=NEW on each of a step's blocks; CalculiX reads it on the first).
template <class Block>
bool renews(const std::vector<Block>& blocks) {
  return std::any_of(blocks.begin(), blocks.end(), [](const Block& b) { return b.op == model::Op::New; });
}

/// *BOUNDARY blocks applied to a map of DOF definitions; OP=NEW empties it first and records
/// the DOFs it released. A DOF given twice takes the later value.
void apply_boundaries(const AnalysisModel& am, const std::vector<model::BoundaryBlock>& blocks,
                      std::map<std::int64_t, ConditionHistory::Value>& defs, std::vector<std::int64_t>* released) {
  if (renews(blocks)) {
    if (released)
      for (const auto& [d, v] : defs) released->push_back(d);
    defs.clear();
  }
  for (const auto& b : blocks) {
    for (const auto& e : b.entries)
      for (std::int32_t node : e.nodes)
        for (int dof = e.first_dof; dof <= e.last_dof; ++dof) {
          const std::int64_t d = am.dof_index(node, dof);  // −1: a DOF the node does not have
          if (d >= 0) defs[d] = {e.value, b.fixed ? "" : b.amplitude, e.value, b.fixed};
        }
  }
}

}  // namespace

ConditionHistory initial_history(const AnalysisModel& am) {
  ConditionHistory h;
  apply_boundaries(am, am.model->boundaries, h.boundary, nullptr);
  const bool gradients = !am.initial_temperature_gradient.empty();
  for (const auto& t : am.model->initial_temperatures)
    for (std::int32_t n : t.nodes) {
      h.temperature[n] = {t.value, "", t.value};
      const double g = t.gradient.value_or(0.0);  // a later line without it: 0, as in a step
      if (gradients) h.temperature_gradient[n] = {g, "", g};
    }
  h.reactions.assign(am.n_dof(), 0.0);
  return h;
}

std::vector<std::int64_t> StepConditions::loaded_dofs() const {
  std::vector<std::int64_t> out;
  for (const auto& [d, v] : target_.cload)
    if (v.value != 0.0) out.push_back(d);
  return out;
}

StepConditions::StepConditions(const AnalysisModel& am, const model::Step& step, const ConditionHistory& previous,
                               double step_start_time)
    : am_(am), step_(step), start_time_(step_start_time), previous_(previous), target_(previous) {
  std::vector<std::int64_t> released;
  apply_boundaries(am, step.boundaries, target_.boundary, &released);
  for (std::int64_t d : released)
    if (!target_.boundary.count(d) && d < static_cast<std::int64_t>(previous.reactions.size()))
      released_reaction_[d] = previous.reactions[d];

  apply_cloads(step.cloads);
  apply_dloads(step.dloads);
  const bool temperatures_renewed = renews(step.temperatures);
  if (temperatures_renewed) {
    target_.temperature.clear();
    target_.temperature_gradient.clear();
  }
  for (const auto& b : step.temperatures) {
    for (const auto& e : b.entries)
      for (std::int32_t n : e.nodes) {
        target_.temperature[n] = {e.value, b.amplitude, e.value};
        // A line without the gradient gives it 0 where one was in force.
        const double g = e.gradient.value_or(0.0);
        if (e.gradient || target_.temperature_gradient.count(n) || previous_.temperature_gradient.count(n))
          target_.temperature_gradient[n] = {g, b.amplitude, g};
      }
  }
  if (temperatures_renewed) return_removed_temperatures();

  prescribed_.assign(am.n_dof(), 0);
  for (const auto& [d, v] : target_.boundary) prescribed_[d] = 1;
  for (const auto& [k, v] : previous_.dload) add_dload_shape(k);
  for (const auto& [k, v] : target_.dload) add_dload_shape(k);
  if (step_.nlgeom && am_.dim == 3) turning_nodes_ = rotation_nodes(am_);
  turning_moments_ = moments_at_turning_nodes();
}

bool StepConditions::moments_at_turning_nodes() const {
  const auto at_rotation_node = [&](std::int64_t d) {
    return std::binary_search(turning_nodes_.begin(), turning_nodes_.end(), static_cast<std::int32_t>(d / am_.dim));
  };
  for (const auto* loads : {&previous_.cload, &target_.cload})
    for (const auto& [d, v] : *loads)
      if (at_rotation_node(d)) return true;
  return std::any_of(released_reaction_.begin(), released_reaction_.end(),
                     [&](const auto& kv) { return at_rotation_node(kv.first); });
}

/// A step's *CLOAD blocks: a DOF they load replaces its load of earlier steps; a DOF loaded
/// twice in the step carries the sum (Abaqus and CalculiX), so the two need one amplitude (a
/// deck error otherwise: `inpact check` builds the conditions too).
void StepConditions::apply_cloads(const std::vector<model::CloadBlock>& blocks) {
  if (renews(blocks)) target_.cload.clear();
  std::set<std::int64_t> loaded_in_step;
  for (const auto& b : blocks)
    for (const auto& e : b.entries)
      for (std::int32_t node : e.nodes) {
        const std::int64_t d = am_.dof_index(node, e.dof);
        if (d < 0) continue;
        if (loaded_in_step.insert(d).second) {
          target_.cload[d] = {e.magnitude, b.amplitude, e.magnitude};
          continue;
        }
        ConditionHistory::Value& v = target_.cload[d];
        if (v.amplitude != b.amplitude)
          throw AnalysisError(fmt::format("{}: error: *CLOAD: node {} DOF {} is loaded earlier in this step with {}; "
                                          "loads at one DOF in one step add up and need one amplitude",
                                          am_.model->sources.describe(e.loc),
                                          am_.model->mesh.nodes.labels[static_cast<std::size_t>(node)], e.dof,
                                          v.amplitude.empty() ? "the step's own amplitude" : "AMPLITUDE=" + v.amplitude));
        v.value += e.magnitude;
      }
}

/// A step's *DLOAD and *DSLOAD blocks, by the same rule per element face or body load:
/// gravities add as vectors, CENTRIF and ROTA about one axis by their magnitudes. OP=NEW of
/// *DLOAD removes the earlier *DLOADs, of *DSLOAD the *DSLOADs.
void StepConditions::apply_dloads(const std::vector<model::DloadBlock>& blocks) {
  for (const bool surface_load : {false, true})
    if (std::any_of(blocks.begin(), blocks.end(),
                    [&](const auto& b) { return b.surface_load == surface_load && b.op == model::Op::New; }))
      std::erase_if(target_.dload, [&](const auto& kv) { return kv.first.surface_load == surface_load; });
  std::set<Key> loaded_in_step;
  for (const auto& b : blocks)
    for (const auto& e : b.entries)
      for (std::size_t i = 0; i < e.elements.size(); ++i) {
        const Key key{e.elements[i], model::dload_slot(e, i), b.surface_load};
        double magnitude = e.magnitude;
        if (model::scales_with_density(e.kind)) magnitude *= am_.elements[e.elements[i]].density;
        if (loaded_in_step.insert(key).second) {
          target_.dload[key] = {magnitude, e.direction, e.point, b.amplitude, magnitude};
          continue;
        }
        ConditionHistory::DloadValue& v = target_.dload[key];
        const bool rotation = key.key == 300 || key.key == 400;
        if (v.amplitude != b.amplitude || (rotation && (v.direction != e.direction || v.point != e.point)))
          throw AnalysisError(fmt::format("{}: error: {}: element {} has this load earlier in this step {}",
                                          am_.model->sources.describe(e.loc), b.surface_load ? "*DSLOAD" : "*DLOAD",
                                          am_.model->mesh.elements.labels[static_cast<std::size_t>(e.elements[i])],
                                          v.amplitude != b.amplitude
                                              ? "with another amplitude; loads that add up need one"
                                              : "about another axis; two rotations of one element in one step are not "
                                                "supported"));
        if (key.key == 200) {  // g1 d1 + g2 d2: the sum's length and direction
          std::array<double, 3> g{};
          for (int c = 0; c < 3; ++c) g[c] = v.value * v.direction[c] + magnitude * e.direction[c];
          v.value = std::hypot(g[0], g[1], g[2]);
          for (int c = 0; c < 3; ++c) v.direction[c] = v.value > 0.0 ? g[c] / v.value : 0.0;
        } else {
          v.value += magnitude;
        }
        v.end_value = v.value;
      }
}

namespace {

/// The nodal forces of a unit load in a surface slot (below 100): a face pressure, or a traction on
/// a shell edge (model::edge_load_slot).
std::vector<double> unit_surface_load(const ElementSetup& setup, std::span<const elements::Vec3> coords, int slot) {
  if (model::is_edge_load_slot(slot))
    return elements::edge_traction_load(*setup.type, coords, model::slot_edge(slot), model::slot_edge_traction(slot), 1.0);
  return elements::pressure_load(*setup.type, coords, slot, 1.0, setup.section);
}

}  // namespace

void StepConditions::add_dload_shape(const Key& key) {
  if (dload_shape_.count(key) || rotation_moments_.count(key)) return;
  const ElementSetup& setup = am_.elements[key.element];
  if (setup.type->family == model::ElementFamily::Spring) return;  // springs have no mass: GRAV, CENTRIF add nothing
  // Rigid elements have no volume (inpact gives rigid bodies no mass): only pressure loads them.
  if (model::is_rigid(*setup.type) && key.key >= 100) return;
  const auto coords = am_.coords(key.element);
  if (key.key == 300 || key.key == 400) {
    const auto moments = elements::volume_moments(*setup.type, coords, setup.section);
    const auto nodes = am_.model->mesh.elements.nodes_of(key.element);
    auto& m = rotation_moments_[key];
    for (std::size_t a = 0; a < nodes.size(); ++a) m.emplace_back(nodes[a], moments[a]);
    return;
  }
  std::vector<double> f;
  if (key.key < 100) {
    f = unit_surface_load(setup, coords, key.key);
  } else {
    // Body forces per unit magnitude: the direction is applied in external_force.
    elements::Vec3 unit{0, 0, 0};
    if (key.key < 200) unit[key.key - 100] = 1.0;
    f = key.key < 200 ? elements::body_force_load(*setup.type, coords, unit, setup.section) : std::vector<double>{};
  }
  auto& shape = dload_shape_[key];
  const auto nodes = am_.model->mesh.elements.nodes_of(key.element);
  if (key.key == 200) {
    // Gravity: one shape per axis, folded with the direction when evaluated.
    for (int axis = 0; axis < am_.dim; ++axis) {
      elements::Vec3 unit{0, 0, 0};
      unit[axis] = 1.0;
      const auto g = elements::body_force_load(*setup.type, coords, unit, setup.section);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        shape.emplace_back(static_cast<std::int64_t>(nodes[a]) * am_.dim + axis, g[a * am_.dim + axis]);
    }
    return;
  }
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int c = 0; c < am_.dim; ++c)
      if (f[a * am_.dim + c] != 0.0) shape.emplace_back(static_cast<std::int64_t>(nodes[a]) * am_.dim + c, f[a * am_.dim + c]);
}

double StepConditions::ramp(double t) const {
  if (step_.amplitude == model::Step::DefaultAmplitude::Step) return 1.0;
  const double period = step_.static_procedure ? step_.static_procedure->time_period : 1.0;
  return std::clamp(t / period, 0.0, 1.0);
}

double StepConditions::amplitude(const std::string& name, double t) const {
  const model::Amplitude& a = am_.model->amplitudes.at(name);
  const double time = a.time == model::Amplitude::Time::Total ? start_time_ + t : t;
  const auto& p = a.points;
  if (p.empty()) return 0.0;
  if (time <= p.front()[0]) return p.front()[1];
  if (time >= p.back()[0]) return p.back()[1];
  auto it = std::upper_bound(p.begin(), p.end(), time, [](double v, const auto& pt) { return v < pt[0]; });
  const auto& hi = *it;
  const auto& lo = *(it - 1);
  const double xi = (time - lo[0]) / (hi[0] - lo[0]);
  const double w = a.definition == model::Amplitude::Definition::SmoothStep
                       ? xi * xi * xi * (10 - 15 * xi + 6 * xi * xi)
                       : xi;
  return lo[1] + (hi[1] - lo[1]) * w;
}

template <class V>
double StepConditions::value_at(const V* prev, const V* target, double t) const {
  if (target && !target->amplitude.empty()) return target->value * amplitude(target->amplitude, t);
  const double start = prev ? prev->end_value : 0.0;
  const double end = target ? target->value : 0.0;
  return start + (end - start) * ramp(t);
}

std::array<double, 3> StepConditions::gravity_at(const ConditionHistory::DloadValue* prev,
                                                 const ConditionHistory::DloadValue* target, double t) const {
  std::array<double, 3> g{0, 0, 0};
  if (target && !target->amplitude.empty()) {
    const double a = target->value * amplitude(target->amplitude, t);
    for (int c = 0; c < 3; ++c) g[c] = a * target->direction[c];
    return g;
  }
  const double r = ramp(t);
  for (int c = 0; c < 3; ++c) {
    const double start = prev ? prev->end_value * prev->direction[c] : 0.0;
    const double end = target ? target->value * target->direction[c] : 0.0;
    g[c] = start + (end - start) * r;
  }
  return g;
}

void StepConditions::apply_prescribed(double t, std::span<const double> u_start, std::span<double> u) const {
  for (const auto& [d, def] : target_.boundary) {
    if (def.fixed) {
      u[d] = step_start_value_.try_emplace(d, u_start[d]).first->second;
    } else if (!def.amplitude.empty()) {
      u[d] = def.value * amplitude(def.amplitude, t);
    } else {
      // From wherever the DOF was at the step start (a new BC on a free DOF starts there).
      const double start = step_start_value_.try_emplace(d, u_start[d]).first->second;
      u[d] = start + (def.value - start) * ramp(t);
    }
  }
}

void StepConditions::external_force(double t, std::span<double> f) const { external_force(t, {}, f); }

bool StepConditions::has_follower_pressure() const {
  if (!step_.nlgeom) return false;
  for (const auto* loads : {&previous_.dload, &target_.dload})
    for (const auto& [k, v] : *loads)
      if (k.key < 100) return true;
  return false;
}

std::vector<std::pair<std::int64_t, double>> StepConditions::follower_shape(const Key& key,
                                                                            std::span<const double> u) const {
  const ElementSetup& setup = am_.elements[key.element];
  auto coords = am_.coords(key.element);
  const auto nodes = am_.model->mesh.elements.nodes_of(key.element);
  const std::size_t dim = static_cast<std::size_t>(am_.dim);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t c = 0; c < dim; ++c) coords[a][c] += u[static_cast<std::size_t>(nodes[a]) * dim + c];
  const auto f = unit_surface_load(setup, coords, key.key);
  std::vector<std::pair<std::int64_t, double>> shape;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t c = 0; c < dim; ++c)
      shape.emplace_back(static_cast<std::int64_t>(static_cast<std::size_t>(nodes[a]) * dim + c), f[a * dim + c]);
  return shape;
}

void StepConditions::external_force(double t, std::span<const double> u, std::span<double> f) const {
  std::fill(f.begin(), f.end(), 0.0);
  auto find = [](const auto& map, const auto& key) -> const auto* {
    auto it = map.find(key);
    return it == map.end() ? nullptr : &it->second;
  };
  auto each_key = [](const auto& a, const auto& b, auto&& fn) {
    for (const auto& [k, v] : a) fn(k);
    for (const auto& [k, v] : b)
      if (!a.count(k)) fn(k);
  };
  each_key(previous_.cload, target_.cload,
           [&](std::int64_t d) { f[d] += value_at(find(previous_.cload, d), find(target_.cload, d), t); });
  // A removed boundary condition's reaction ramps down to zero; at a turning node it is a spatial
  // moment (end_state's reactions are, under NLGEOM in 3D), turned with the loads below.
  for (const auto& [d, r] : released_reaction_) f[d] += r * (1.0 - ramp(t));
  // (f holds the concentrated loads and released reactions alone so far: the moments at the
  // rotation nodes)
  if (!u.empty() && has_turning_moments()) moments_to_conjugate(u, turning_nodes_, f);
  each_key(previous_.dload, target_.dload, [&](const Key& k) {
    const auto* prev = find(previous_.dload, k);
    const auto* target = find(target_.dload, k);
    if (k.key == 200) {  // gravity: one shape per axis, each scaled by its component
      const auto shape = dload_shape_.find(k);
      if (shape == dload_shape_.end()) return;  // springs and rigid elements have no mass
      const auto g = gravity_at(prev, target, t);
      for (const auto& [d, w] : shape->second) f[d] += g[static_cast<std::size_t>(d % am_.dim)] * w;
      return;
    }
    const double v = value_at(prev, target, t);
    if (v == 0.0) return;
    const auto& dir = (target ? target : prev)->direction;
    if (k.key == 300 || k.key == 400) {
      // (a CENTRIF or ROTA redefined with another axis takes the new axis for the whole step)
      add_rotation_force(k, v, dir, (target ? target : prev)->point, f);
      return;
    }
    if (k.key < 100 && !u.empty()) {  // follower pressure
      for (const auto& [d, w] : follower_shape(k, u)) f[d] += v * w;
      return;
    }
    for (const auto& [d, w] : dload_shape_.at(k)) f[d] += v * w;
  });
  if (!previous_.released_forces.empty()) {
    // The removed pairs' and elements' forces, linearly to zero whatever the step's amplitude
    // [IG]: as loads they act against f_int's part they were, f_ext = −(1 − t/T) f_r.
    const double period = step_.static_procedure ? step_.static_procedure->time_period : 1.0;
    const double left = 1.0 - std::clamp(t / period, 0.0, 1.0);
    for (std::size_t d = 0; d < f.size(); ++d) f[d] -= left * previous_.released_forces[d];
  }
}

/// With r_a = ∫N_a x dV − x0 ∫N_a dV (both loads are linear in x, so integrated exactly):
///  - CENTRIF, f_a = ρω² (I − nnᵀ) r_a: the centrifugal force ρω² times the distance vector from
///    the axis;
///  - ROTA, f_a = −ρα n × r_a: the d'Alembert force of the rotary acceleration α about n, as
///    the centrifugal force is the d'Alembert force of ω (Abaqus Theory Manual, "Centrifugal,
///    Coriolis and rotary acceleration loads").
/// On the reference geometry: the change of the load with the displacement (spin softening) is
/// not included.
void StepConditions::add_rotation_force(const Key& key, double v, const std::array<double, 3>& axis,
                                        const std::array<double, 3>& point, std::span<double> f) const {
  for (const auto& [node, m] : rotation_moments_.at(key)) {
    std::array<double, 3> r{};
    for (int i = 0; i < 3; ++i) r[i] = m.first[i] - point[i] * m.volume;
    std::array<double, 3> load{};
    if (key.key == 300) {
      const double along = r[0] * axis[0] + r[1] * axis[1] + r[2] * axis[2];
      for (int i = 0; i < 3; ++i) load[i] = r[i] - along * axis[i];
    } else {
      load = {-(axis[1] * r[2] - axis[2] * r[1]), -(axis[2] * r[0] - axis[0] * r[2]), -(axis[0] * r[1] - axis[1] * r[0])};
    }
    for (int i = 0; i < am_.dim; ++i) f[static_cast<std::int64_t>(node) * am_.dim + i] += v * load[i];
  }
}

/// The change at step time t of a nodal field given by `previous` and `target` (the state before
/// the step and the step's own), from `initial` (empty: 0), into out[0 .. n).
void StepConditions::nodal_change(const std::map<std::int32_t, ConditionHistory::Value>& previous,
                                  const std::map<std::int32_t, ConditionHistory::Value>& target, std::span<const double> initial,
                                  double t, std::span<double> out) const {
  for (std::size_t n = 0; n < out.size(); ++n) {
    const auto key = static_cast<std::int32_t>(n);
    auto p = previous.find(key);
    auto q = target.find(key);
    const auto* prev = p == previous.end() ? nullptr : &p->second;
    const auto* now = q == target.end() ? nullptr : &q->second;
    if (!prev && !now) continue;
    // A node with only an initial value keeps it (a change of 0).
    const double value = now ? value_at(prev, now, t) : prev->end_value;
    out[n] = value - (initial.empty() ? 0.0 : initial[n]);
  }
}

/// [K *TEMPERATURE, OP]: "a temperature that is removed via OP=NEW is reset to the value given on
/// the INITIAL CONDITIONS option or to zero if no initial temperature was defined", following the
/// step's own amplitude (a ramp in a static step), not the AMPLITUDE of the new lines. The
/// gradient through a shell's thickness likewise.
void StepConditions::return_removed_temperatures() {
  auto reset = [](const std::map<std::int32_t, ConditionHistory::Value>& before,
                  std::map<std::int32_t, ConditionHistory::Value>& now, std::span<const double> initial) {
    for (const auto& [n, v] : before)
      if (!now.count(n)) {
        const double back = initial.empty() ? 0.0 : initial[static_cast<std::size_t>(n)];
        now[n] = {back, "", back};
      }
  };
  reset(previous_.temperature, target_.temperature, am_.initial_temperature);
  reset(previous_.temperature_gradient, target_.temperature_gradient, am_.initial_temperature_gradient);
}

std::vector<double> StepConditions::temperature_change(double t) const {
  if (previous_.temperature.empty() && target_.temperature.empty()) return {};
  const std::size_t n = am_.n_nodes();
  const bool gradients = !previous_.temperature_gradient.empty() || !target_.temperature_gradient.empty();
  std::vector<double> dt(gradients ? 2 * n : n, 0.0);
  nodal_change(previous_.temperature, target_.temperature, am_.initial_temperature, t, std::span(dt).first(n));
  if (gradients)
    nodal_change(previous_.temperature_gradient, target_.temperature_gradient, am_.initial_temperature_gradient, t,
                 std::span(dt).subspan(n));
  return dt;
}

ConditionHistory StepConditions::end_state(std::span<const double> reactions) const {
  ConditionHistory h = target_;
  const double period = step_.static_procedure ? step_.static_procedure->time_period : 1.0;
  for (auto& [d, v] : h.boundary) v.end_value = v.amplitude.empty() ? v.value : v.value * amplitude(v.amplitude, period);
  for (auto& [d, v] : h.cload) v.end_value = v.amplitude.empty() ? v.value : v.value * amplitude(v.amplitude, period);
  for (auto& [k, v] : h.dload) v.end_value = v.amplitude.empty() ? v.value : v.value * amplitude(v.amplitude, period);
  for (auto& [n, v] : h.temperature) v.end_value = v.amplitude.empty() ? v.value : v.value * amplitude(v.amplitude, period);
  for (auto& [n, v] : h.temperature_gradient)
    v.end_value = v.amplitude.empty() ? v.value : v.value * amplitude(v.amplitude, period);
  h.reactions.assign(reactions.begin(), reactions.end());
  h.released_forces.clear();  // released over this step only
  return h;
}

}  // namespace inpact::solver
