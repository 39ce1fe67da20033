#pragma once
/// Automatic stabilization of static steps (*STATIC, STABILIZE), as the Abaqus Analysis Guide
/// describes it ("Automatic stabilization of static problems with a constant damping factor"):
/// viscous forces
///     F_v = c M* v,   v = Δu/Δt (the increment's displacement over its time increment),
/// are added to the equilibrium, M* an artificial mass matrix computed with unit density and c
/// the damping factor; the tangent gets c M*/Δt. inpact's M* is lumped: each element's volume
/// (the sum of its integration points' volumes, 2πr·dA for CAX) shared equally by its nodes, on
/// every DOF of the node. The viscous forces act on the free DOFs (not on prescribed ones, nor on
/// those an *EQUATION makes dependent: their masters carry the damping), so reactions stay the
/// elements' and contact's.
///
/// Energies: ALLSE = Σ_points ½ σ·ε dV (the strain energy of linear elasticity, engineering
/// shears with their Voigt stresses; for NLGEOM or inelastic materials an approximation) and
/// ALLSD = Σ_increments F_v·Δu = Σ c Δuᵀ M* Δu / Δt, accumulated from the analysis's start, plus
/// the energy contact stabilization dissipates (Σ f_stab·Δu of its damped slave nodes,
/// solver/contact_problem.hpp, contact/contact_stabilization.hpp) in steps that have it.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "assembler.hpp"
#include "dof_map.hpp"
#include "model/step.hpp"

namespace inpact::solver {

/// M* with unit density, lumped: one value per global DOF (zero on nodes without elements).
std::vector<double> unit_density_lumped_mass(const AnalysisModel& am, const ElementPoints& points);

/// Σ_points ½ σ·ε · volume.
double strain_energy(const ElementPoints& points);

/// The viscous forces of one increment attempt: c, M*, Δt. Newton's hook.
class ViscousForces {
 public:
  ViscousForces(const DofMap& dofs, std::span<const double> mass) : dofs_(&dofs), mass_(mass) {}
  void set(double factor, double dt) { factor_ = factor, dt_ = dt; }
  /// The displacements at the increment's start (Δu = u − u_start), copied: augmentations
  /// restart Newton from intermediate states, the increment's start stays.
  void set_start(std::span<const double> u_start) { u_start_.assign(u_start.begin(), u_start.end()); }
  double factor() const { return factor_; }
  /// f_int += c M* (u − u_start)/Δt on the free DOFs.
  void add_force(std::span<const double> u, std::span<double> f_int) const;
  /// The reduced tangent += c M*/Δt (through the DOF map's masters, as the elements').
  void add_tangent(Assembler& assembler) const;
  /// F_v·Δu = c Δuᵀ M* Δu / Δt over the same DOFs.
  double dissipated(std::span<const double> du) const;

 private:
  const DofMap* dofs_;
  std::span<const double> mass_;
  std::vector<double> u_start_;
  double factor_ = 0.0, dt_ = 1.0;
};

/// The damping factor that makes an increment like the first dissipate the energy fraction f of
/// the strain energy extrapolated to the step's end (see stabilization.cpp for the derivation).
double factor_from_first_increment(double fraction, double strain_energy, double du_m_du, double time_period);
/// The same when the first increment gives no Δu (it failed: a rigid-body mode held only by
/// contact): the Rayleigh quotient ΔuᵀKΔu/ΔuᵀM*Δu replaced by mean(diag K)/mean(diag M*).
double factor_from_diagonals(double fraction, const SparseMatrix& tangent, const DofMap& dofs,
                             std::span<const double> mass, double time_period);

/// What a stabilized step keeps: M*, c (once known), ALLSE and ALLSD. Not movable (its forces
/// point into its mass). A step with contact stabilization only has no viscous forces of its own
/// (no M*, no c) and keeps the energies.
class StepStabilization {
 public:
  StepStabilization(const StepStabilization&) = delete;
  /// `previous_factor`: the damping factor the previous step ended with (CONTINUE=YES), or 0;
  /// `allsd_before`: ALLSD of the earlier steps (it accumulates over the analysis, as Abaqus's).
  /// `spec` null: no *STATIC, STABILIZE; `contact_damping`: the step has contact stabilization.
  StepStabilization(const AnalysisModel& am, const model::Stabilization* spec, double time_period,
                    const DofMap& dofs, Assembler& assembler, std::span<const double> u, double previous_factor,
                    double allsd_before, bool contact_damping = false);

  /// The forces for an attempt of size dt from u_start, or null while c is unknown (the first increment
  /// is tried without damping, as Abaqus does).
  const ViscousForces* for_attempt(double dt, std::span<const double> u_start);
  /// An attempt failed. While c is unknown it is set from the tangent's diagonal: true (retry
  /// the increment with damping, a rigid-body mode is no reason to stop now).
  bool attempt_failed(Assembler& assembler);
  /// A converged increment from u_start to u: ALLSE, ALLSD (with `contact_dissipated`, the
  /// contact damping's f·Δu of the increment), c after the first. Returns the .sta note line.
  std::string increment_converged(std::span<const double> u_start, std::span<const double> u, double dt,
                                  Assembler& assembler, std::span<const double> delta_t, bool nlgeom,
                                  double contact_dissipated = 0.0);
  /// The step's end: a warning when ALLSD exceeds 5 % of ALLSE, else nothing.
  std::optional<std::string> end_of_step_warning() const;

  double factor() const { return factor_; }
  double allse() const { return allse_; }
  double allsd() const { return allsd_; }

 private:
  const DofMap& dofs_;
  model::Stabilization spec_;
  bool viscous_ = true;   ///< *STATIC, STABILIZE (else contact stabilization only)
  bool contact_ = false;  ///< contact stabilization in this step
  double contact_allsd_ = 0.0;  ///< its share of ALLSD in this step
  double time_period_;
  std::vector<double> mass_;
  ViscousForces forces_;
  double factor_ = 0.0;  ///< 0 while unknown
  double allse_ = 0.0, allsd_ = 0.0;
  std::vector<double> f_scratch_;
};

/// ALLSD / ALLSE above which the end of a step warns (Abaqus's own guidance: a few percent).
inline constexpr double kAllsdWarningRatio = 0.05;

}  // namespace inpact::solver
