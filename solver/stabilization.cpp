#include "stabilization.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace inpact::solver {

std::vector<double> unit_density_lumped_mass(const AnalysisModel& am, const ElementPoints& points) {
  std::vector<double> mass(am.n_dof(), 0.0);
  const auto& elements = am.model->mesh.elements;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    double volume = 0.0;
    for (const auto& p : points.of(e)) volume += p.volume;
    const auto nodes = elements.nodes_of(e);
    if (nodes.empty()) continue;
    const double share = volume / static_cast<double>(nodes.size());
    for (std::int32_t node : nodes)
      for (int c = 0; c < am.dim; ++c) mass[static_cast<std::size_t>(node) * am.dim + c] += share;
  }
  return mass;
}

double strain_energy(const ElementPoints& points) {
  double energy = 0.0;
  for (const auto& p : points.points) {
    double density = 0.0;
    for (std::size_t i = 0; i < 6; ++i) density += p.stress[i] * p.strain[i];
    energy += 0.5 * density * p.volume;
  }
  return energy;
}

void ViscousForces::add_force(std::span<const double> u, std::span<double> f_int) const {
  const double scale = factor_ / dt_;
  for (std::int64_t d = 0; d < dofs_->n_dof(); ++d)
    if (dofs_->kind(d) == DofMap::Kind::Free) f_int[d] += scale * mass_[d] * (u[d] - u_start_[d]);
}

void ViscousForces::add_tangent(Assembler& assembler) const {
  const double scale = factor_ / dt_;
  for (std::int64_t d = 0; d < dofs_->n_dof(); ++d) {
    if (dofs_->kind(d) != DofMap::Kind::Free || mass_[d] == 0.0) continue;
    assembler.add_diagonal(d, scale * mass_[d]);
  }
}

double ViscousForces::dissipated(std::span<const double> du) const {
  double sum = 0.0;
  for (std::int64_t d = 0; d < dofs_->n_dof(); ++d)
    if (dofs_->kind(d) == DofMap::Kind::Free) sum += mass_[d] * du[d] * du[d];
  return factor_ / dt_ * sum;
}

// Abaqus: "the damping factor is determined in such a way that the dissipated energy for a
// given increment with characteristics similar to the first increment is a small fraction of
// the extrapolated strain energy" (the dissipated energy fraction, default 2e-4). inpact reads
// it as: an increment like the first (Δu₁ over Δt₁) dissipates E_d = c Δu₁ᵀM*Δu₁/Δt₁; the strain
// energy E₁ after it, extrapolated linearly in time to the step's end, is E₁·T/Δt₁; E_d = f·E₁·T/Δt₁
// gives c = f E₁ T / (Δu₁ᵀ M* Δu₁). For a step that goes on like its first increment, ALLSD/ALLSE
// at its end is then f itself, whatever Δt₁. (The extrapolation Abaqus uses is not published.)
double factor_from_first_increment(double fraction, double strain_energy, double du_m_du, double time_period) {
  if (!(du_m_du > 0.0) || !(strain_energy > 0.0)) return 0.0;
  return fraction * strain_energy * time_period / du_m_du;
}

// With E₁ = ½ Δu₁ᵀKΔu₁ the formula above is c = f ½ T (Δu₁ᵀKΔu₁)/(Δu₁ᵀM*Δu₁); without a Δu₁ the
// quotient is estimated by mean(diag K)/mean(diag M*) over the equations (inpact's choice).
double factor_from_diagonals(double fraction, const SparseMatrix& tangent, const DofMap& dofs,
                             std::span<const double> mass, double time_period) {
  // A distributed run's ranks hold parts of the tangent (Assembler): their diagonals add up.
  std::vector<double> diagonal(static_cast<std::size_t>(dofs.n_equations()), 0.0);
  for (std::int64_t eq = 0; eq < dofs.n_equations(); ++eq)
    if (const std::int64_t pos = tangent.find(eq, eq); pos >= 0) diagonal[eq] = tangent.values[pos];
  if (const RankWorld world = rank_world(); world.distributed()) world.sum(diagonal);
  double k_sum = 0.0, m_sum = 0.0;
  std::int64_t n = 0;
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d) {
    const std::int64_t eq = dofs.equation(d);
    if (eq < 0 || dofs.kind(d) != DofMap::Kind::Free) continue;
    k_sum += std::abs(diagonal[eq]);
    m_sum += mass[d];
    ++n;
  }
  if (n == 0 || m_sum <= 0.0) return 0.0;
  return fraction * 0.5 * time_period * k_sum / m_sum;
}

StepStabilization::StepStabilization(const AnalysisModel& am, const model::Stabilization* spec, double time_period,
                                     const DofMap& dofs, Assembler& assembler, std::span<const double> u,
                                     double previous_factor, double allsd_before, bool contact_damping)
    : dofs_(dofs), spec_(spec ? *spec : model::Stabilization{}), viscous_(spec != nullptr), contact_(contact_damping),
      time_period_(time_period), forces_(dofs, {}), allsd_(allsd_before), f_scratch_(am.n_dof()) {
  if (!viscous_) return;
  // The element volumes: the points' reference volumes, whatever u is.
  AssemblyRequest volumes{.tangent = false, .nlgeom = false, .delta_t = {}, .points = true};
  assembler.assemble(u, volumes, f_scratch_);
  const ElementPoints* points = assembler.points_at(u, {}, false);
  mass_ = points ? unit_density_lumped_mass(am, *points) : std::vector<double>(am.n_dof(), 0.0);
  forces_ = ViscousForces(dofs, mass_);
  if (spec->damping_factor) factor_ = *spec->damping_factor;
  else if (spec->continue_previous && previous_factor > 0.0) factor_ = previous_factor;
}

const ViscousForces* StepStabilization::for_attempt(double dt, std::span<const double> u_start) {
  if (factor_ <= 0.0) return nullptr;
  forces_.set(factor_, dt);
  forces_.set_start(u_start);
  return &forces_;
}

bool StepStabilization::attempt_failed(Assembler& assembler) {
  if (!viscous_ || factor_ > 0.0) return false;
  factor_ = factor_from_diagonals(spec_.energy_fraction, assembler.tangent(), dofs_, mass_,
                                  time_period_);
  return factor_ > 0.0;
}

std::string StepStabilization::increment_converged(std::span<const double> u_start, std::span<const double> u,
                                                   double dt, Assembler& assembler, std::span<const double> delta_t,
                                                   bool nlgeom, double contact_dissipated) {
  const ElementPoints* points = assembler.points_at(u, delta_t, nlgeom);
  if (!points) {
    AssemblyRequest request{.tangent = false, .nlgeom = nlgeom, .delta_t = delta_t, .points = true};
    assembler.assemble(u, request, f_scratch_);
    points = assembler.points_at(u, delta_t, nlgeom);
  }
  allse_ = points ? strain_energy(*points) : 0.0;
  std::vector<double> du(u.size());
  for (std::size_t d = 0; d < u.size(); ++d) du[d] = u[d] - u_start[d];
  std::string note;
  if (!viscous_) {
    // Contact stabilization only.
  } else if (factor_ > 0.0) {
    forces_.set(factor_, dt);
    allsd_ += forces_.dissipated(du);
  } else {
    // The first increment converged without damping: c from its characteristics.
    ViscousForces unit(dofs_, mass_);
    unit.set(1.0, 1.0);
    factor_ = factor_from_first_increment(spec_.energy_fraction, allse_, unit.dissipated(du), time_period_);
    if (factor_ <= 0.0) factor_ = factor_from_diagonals(spec_.energy_fraction, assembler.tangent(), dofs_, mass_, time_period_);
    note = fmt::format(" (damping factor {:.4g} from this increment)", factor_);
  }
  // ALLSDTOL (inpact's adaptive scheme, global): lower c when ALLSD passes tol·ALLSE.
  if (spec_.allsdtol && allse_ > 0.0 && allsd_ > *spec_.allsdtol * allse_)
    factor_ *= std::max(0.1, *spec_.allsdtol * allse_ / allsd_);
  allsd_ += contact_dissipated;
  contact_allsd_ += contact_dissipated;
  std::string line = fmt::format("     STABILIZATION ALLSE={:.6e} ALLSD={:.6e} ALLSD/ALLSE={:.4g}", allse_, allsd_,
                                 allse_ > 0.0 ? allsd_ / allse_ : 0.0);
  if (viscous_) line += fmt::format(" FACTOR={:.4g}", factor_);
  if (contact_) line += fmt::format(" CONTACT ALLSD={:.6e}", contact_allsd_);
  return line + note;
}

std::optional<std::string> StepStabilization::end_of_step_warning() const {
  if (!(allsd_ > kAllsdWarningRatio * allse_)) return std::nullopt;
  return fmt::format(
      "warning: the energy dissipated by {} stabilization ALLSD = {:.4g} is {:.3g} % of the strain energy "
      "ALLSE = {:.4g} (more than {:.0f} %): the stabilised answer may be wrong",
      viscous_ ? (contact_ ? "automatic and contact" : "automatic") : "contact", allsd_, allse_ > 0.0 ? 100.0 * allsd_ / allse_ : 0.0, allse_, 100.0 * kAllsdWarningRatio);
}

}  // namespace inpact::solver
