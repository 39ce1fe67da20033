#pragma once
/// The boundary conditions, loads and temperatures in force during one step, and their values
/// at any time of it, following Abaqus's rules for static steps:
///  - a value defined in this step without an amplitude ramps linearly from its value at the
///    end of the previous step (0 for a new load; the current displacement for a boundary
///    condition) to the new one over the step (*STEP, AMPLITUDE=RAMP, the static default), or
///    applies at once (AMPLITUDE=STEP);
///  - with AMPLITUDE=name the value is magnitude × a(t);
///  - *BOUNDARY, FIXED holds a DOF where it is at the start of the step;
///  - OP=MOD (default) changes the definitions it names and keeps the others; OP=NEW (on any
///    of a step's blocks of a kind) removes the earlier steps' definitions of that kind: removed
///    loads ramp down to zero, and a removed boundary condition leaves its reaction as a load
///    that ramps down to zero;
///  - a load given twice in one step (a DOF, an element face, a body load) carries the sum.
/// Loads act on the reference geometry, except pressure (*DLOAD Pn, *DSLOAD P) and shell edge
/// tractions in an NLGEOM step: they follow the surface (Abaqus's default), evaluated on X + u
/// each iteration. A *CLOAD moment keeps its global direction; under NLGEOM in 3D it reaches a
/// turning node's rotation vector as Tᵀ(ψ) m (rotation_moments.hpp). Neither's load stiffness is
/// in the tangent (Newton then converges linearly on that part).
#include <array>
#include <cstdint>
#include <string>
#include <map>
#include <span>
#include <vector>

#include "analysis_model.hpp"
#include "elements/face_loads.hpp"

namespace inpact::solver {

/// What carries over from one step to the next: every definition in force with the value it
/// reached, and the reactions at the constrained DOFs.
struct ConditionHistory {
  struct Value {
    double value = 0.0;      ///< the magnitude as defined
    std::string amplitude;   ///< upper-case amplitude name; empty = the step's ramp/step
    double end_value = 0.0;  ///< what it reached at the end of its step (= value × a(t_end))
    /// *BOUNDARY, FIXED: held at the value the DOF has at the start of the step (value and
    /// amplitude unused); carried into later steps it keeps holding that value.
    bool fixed = false;
  };
  std::map<std::int64_t, Value> boundary;  ///< key: global DOF
  std::map<std::int64_t, Value> cload;     ///< key: global DOF
  /// Distributed loads by (element row, load key): key = face (0..5) for pressure, 100 + axis
  /// for body forces, 200 for gravity, 300 for CENTRIF, 400 for ROTA; the value holds the
  /// magnitude (with the density for GRAV, CENTRIF and ROTA).
  struct DloadKey {
    std::int32_t element;
    int key;
    bool surface_load;
    auto operator<=>(const DloadKey&) const = default;
  };
  struct DloadValue {
    double value = 0.0;
    std::array<double, 3> direction{0, 0, 0};  ///< GRAV's direction, CENTRIF's and ROTA's axis
    std::array<double, 3> point{0, 0, 0};      ///< CENTRIF, ROTA: a point on the axis
    std::string amplitude;
    double end_value = 0.0;
  };
  std::map<DloadKey, DloadValue> dload;
  std::map<std::int32_t, Value> temperature;  ///< key: node row
  /// The gradient through the thickness of the shells at a node (*TEMPERATURE's third field),
  /// for the nodes whose temperature was given with one, or later without (then 0).
  std::map<std::int32_t, Value> temperature_gradient;
  std::vector<double> reactions;              ///< per global DOF, at the end of the step
  /// The forces (f_int's part, per global DOF; empty: none) of the contact pairs and elements
  /// the next step removes (*MODEL CHANGE, REMOVE), at the end of this step: the next step
  /// applies them as loads that ramp linearly down to zero [IG ctc_contactpair_std].
  std::vector<double> released_forces;
};

/// The state before the first step: the model-level boundary conditions (in force from the
/// start, at their values) and the initial temperatures.
ConditionHistory initial_history(const AnalysisModel& am);

class StepConditions {
 public:
  /// `step_start_time`: total time at the start of the step (for TIME=TOTAL amplitudes).
  StepConditions(const AnalysisModel& am, const model::Step& step, const ConditionHistory& previous,
                 double step_start_time);

  /// Per global DOF: 1 when a boundary condition prescribes it in this step.
  const std::vector<std::uint8_t>& prescribed() const { return prescribed_; }
  /// The DOFs a *CLOAD in force this step loads (non-zero magnitude), ascending.
  std::vector<std::int64_t> loaded_dofs() const;
  /// Writes the prescribed DOFs' values at step time t into u. `u_start` is u at the start of
  /// the increment; the first call of the step (increment 1: every attempt of it starts from
  /// the step start) records where each ramped DOF starts, so that later increments ramp from
  /// the step-start value and not from the increment's.
  void apply_prescribed(double t, std::span<const double> u_start, std::span<double> u) const;
  /// External force vector at step time t (size n_dof), overwritten.
  void external_force(double t, std::span<double> f) const;
  /// The same with the pressure loads on the current coordinates X + u (follower pressure).
  void external_force(double t, std::span<const double> u, std::span<double> f) const;
  /// NLGEOM and a pressure load in force: the external force depends on u.
  bool has_follower_pressure() const;
  /// NLGEOM in 3D and a *CLOAD moment (or a released reaction moment) in force at a node that
  /// turns finitely: its force conjugate to the node's rotation vector depends on u
  /// (rotation_moments.hpp).
  bool has_turning_moments() const { return turning_moments_; }
  /// The external force depends on u: external_force(t, u, f) each iteration.
  bool depends_on_displacement() const { return has_follower_pressure() || has_turning_moments(); }
  /// Nodal temperature change T(t) − T_initial, or empty when the model has no temperatures;
  /// when some node has a shell temperature gradient, the gradient's change g(t) − g_initial of
  /// every node follows (2 × nodes values; AnalysisModel::element_temperature_changes).
  std::vector<double> temperature_change(double t) const;
  /// The definitions in force at the end of the step, for the next one.
  ConditionHistory end_state(std::span<const double> reactions) const;
  /// a(t) of an amplitude `name` at step time t; empty name: the step's own (RAMP t/T, or 1 for
  /// AMPLITUDE=STEP).
  double amplitude_value(const std::string& name, double t) const { return name.empty() ? ramp(t) : amplitude(name, t); }

 private:
  double ramp(double t) const;
  double amplitude(const std::string& name, double t) const;
  /// OP=NEW: the temperatures it removed return to their initial values over the step.
  void return_removed_temperatures();
  void apply_cloads(const std::vector<model::CloadBlock>& blocks);
  void apply_dloads(const std::vector<model::DloadBlock>& blocks);
  /// The change at step time t of a nodal field (temperature_change).
  void nodal_change(const std::map<std::int32_t, ConditionHistory::Value>& previous,
                    const std::map<std::int32_t, ConditionHistory::Value>& target, std::span<const double> initial,
                    double t, std::span<double> out) const;
  /// Value at step time t of a definition that was `prev` at the step start and is `target` in
  /// this step (either may be absent).
  template <class V>
  double value_at(const V* prev, const V* target, double t) const;
  /// The gravity vector at step time t: from the step start's vector to the target's (a turned
  /// GRAV turns as it ramps), or the target's times its amplitude.
  std::array<double, 3> gravity_at(const ConditionHistory::DloadValue* prev, const ConditionHistory::DloadValue* target,
                                   double t) const;
  void add_dload_shape(const ConditionHistory::DloadKey& key);
  /// The pressure load of `key` at unit magnitude on X + u (global DOF, force).
  std::vector<std::pair<std::int64_t, double>> follower_shape(const ConditionHistory::DloadKey& key,
                                                              std::span<const double> u) const;

  const AnalysisModel& am_;
  const model::Step& step_;
  double start_time_;
  ConditionHistory previous_;  ///< values at the step start
  ConditionHistory target_;    ///< definitions in force in this step (values = targets)
  std::vector<std::uint8_t> prescribed_;
  std::map<std::int64_t, double> released_reaction_;  ///< BCs removed by OP=NEW: ramp to 0
  /// NLGEOM in 3D: concentrated loads or released reactions at turning nodes, which reach their
  /// rotation vectors as Tᵀ(ψ) m (has_turning_moments).
  bool turning_moments_ = false;
  /// NLGEOM in 3D: the rotation nodes (rows), whose DOFs are total rotation vectors.
  std::vector<std::int32_t> turning_nodes_;
  bool moments_at_turning_nodes() const;
  /// u at the step start of the prescribed DOFs without amplitude (recorded on first use).
  mutable std::map<std::int64_t, double> step_start_value_;
  /// Global nodal forces of each distributed load at unit magnitude (reference geometry).
  std::map<ConditionHistory::DloadKey, std::vector<std::pair<std::int64_t, double>>> dload_shape_;
  /// CENTRIF's and ROTA's loads per element: each node's volume moments (reference geometry),
  /// folded with the axis when evaluated (add_rotation_force).
  std::map<ConditionHistory::DloadKey, std::vector<std::pair<std::int32_t, elements::VolumeMoments>>> rotation_moments_;
  /// Adds v × the centrifugal (CENTRIF) or rotary acceleration (ROTA) load of the element of
  /// `key` about `axis` through `point` to f.
  void add_rotation_force(const ConditionHistory::DloadKey& key, double v, const std::array<double, 3>& axis,
                             const std::array<double, 3>& point, std::span<double> f) const;
};

}  // namespace inpact::solver
