#pragma once
/// How every DOF of the model relates to the unknowns of the reduced system.
///
/// Global DOF d = node_row · dim + component. Each DOF is one of
///  - free: an unknown of the linear system (equation number eq(d) >= 0);
///  - prescribed: its value comes from a boundary condition (no equation);
///  - dependent: eliminated by a *TRANSFORM (into its local node), *EQUATION, *TIE,
///    *PRE-TENSION SECTION or distributing
///    *COUPLING, u_d = Σ w_i u_i over independent DOFs, or by a *RIGID BODY or kinematic
///    *COUPLING, u = u_R + (R(θ) − I) r (model/rigid_motion.hpp): linear for small rotations; with
///    finite rotations (NLGEOM) the weights are ∂u/∂(u_R, θ) at the current θ, renewed by
///    relinearize() each iteration; a beam or shell node of such a body (not pinned) or coupling
///    (its rotations listed) turns with it, θ = θ_R (exact, finite rotations too);
///  - unused: a node no element connects (no stiffness; held at zero, not reported).
/// Assembly expands each element DOF into its independent DOFs ("masters") with weights, so
/// K_reduced = Tᵀ K T without ever forming T.
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "analysis_model.hpp"
#include "fields.hpp"

namespace inpact::solver {

struct MasterTerm {
  std::int64_t dof;  ///< an independent (free or prescribed) DOF
  double weight;
};

class DofMap {
 public:
  enum class Kind : std::uint8_t { Free, Prescribed, Dependent, Unused };

  /// `prescribed[d]`: DOF d has a boundary condition in this step.
  /// Throws AnalysisError when an equation's dependent DOF is also prescribed, or appears as
  /// the dependent DOF of two equations, or the equations form a cycle.
  /// `finite_rotations`: rigid bodies turn by R(θ) (NLGEOM) instead of θ × r.
  /// `active` (per element row; empty: all): only active elements make their nodes' DOFs used
  /// (*MODEL CHANGE, element_activity.hpp).
  static DofMap build(const AnalysisModel& am, const std::vector<std::uint8_t>& prescribed,
                      bool finite_rotations = false, std::span<const std::uint8_t> active = {});

  std::int64_t n_dof() const { return static_cast<std::int64_t>(kind_.size()); }
  std::int64_t n_equations() const { return n_eq_; }
  Kind kind(std::int64_t d) const { return kind_[d]; }
  std::int64_t equation(std::int64_t d) const { return eq_[d]; }
  /// The independent DOFs DOF d is made of: itself (weight 1) unless it is dependent.
  std::span<const MasterTerm> masters(std::int64_t d) const;
  /// Sets every dependent DOF of u from its masters (after the independent ones changed).
  void update_dependent(std::vector<double>& u) const;
  /// Finite rotations: the rigid bodies' weights linearised at the θ of `u` (same masters, new
  /// weights); nothing to do otherwise.
  void relinearize(const AnalysisModel& am, const std::vector<double>& u);
  bool has_finite_rotations() const { return finite_rotations_ && !rigid_.empty(); }
  /// The convergence field of DOF d (fields.hpp): in a model with beams or shells their nodes'
  /// rotations (and those of rigid bodies and couplings) are the rotation field; every other
  /// DOF is the displacement field, the rotations of a model without beams and shells too (they
  /// carry no moment of their own to be measured against).
  Field field(std::int64_t d) const { return rotation_.empty() || !rotation_[d] ? kDisplacementField : kRotationField; }

  /// One node of a rigid body or kinematic coupling: its offset r from the reference node and
  /// which of its translations follow the body (a coupling's DOF subset; a body: all).
  struct RigidNode {
    std::int32_t node, ref, rot;
    std::array<double, 3> r;
    std::array<bool, 3> follows{true, true, true};
  };

 private:
  using Dependents = std::map<std::int64_t, std::vector<MasterTerm>>;
  /// The rules of every dependent DOF, each over independent DOFs only; the rigid bodies'
  /// linearised at `u` (null: θ = 0).
  Dependents dependents(const AnalysisModel& am, const std::vector<double>* u);
  void lay_out(const Dependents& dependent);

  std::vector<RigidNode> rigid_;
  std::vector<std::uint8_t> rotation_;  ///< per DOF: in the rotation field (empty: none is)
  bool finite_rotations_ = false;
  int dim_ = 3;
  std::vector<Kind> kind_;
  std::vector<std::int64_t> eq_;
  std::vector<std::int64_t> master_ptr_;  ///< masters of d: master_[master_ptr_[d] .. master_ptr_[d+1])
  std::vector<MasterTerm> master_;
  std::int64_t n_eq_ = 0;
};

}  // namespace inpact::solver
