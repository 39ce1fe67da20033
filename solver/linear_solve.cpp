#include "linear_solve.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "element_partition.hpp"
#include "model/reference_nodes.hpp"

namespace inpact::solver {

EquationPoints equation_points(const AnalysisModel& am, const DofMap& dofs) {
  EquationPoints p;
  p.dim = am.dim;
  p.node.resize(static_cast<std::size_t>(dofs.n_equations()));
  p.component.resize(p.node.size());
  for (std::int64_t d = 0; d < dofs.n_dof(); ++d)
    if (const std::int64_t eq = dofs.equation(d); eq >= 0) {
      p.node[eq] = d / am.dim;
      p.component[eq] = static_cast<int>(d % am.dim);
    }
  for (const auto& x : am.model->mesh.nodes.coords) p.coordinates.insert(p.coordinates.end(), x.begin(), x.end());
  for (const model::RotatingNode& r : model::rotating_nodes(*am.model, am.dim)) {
    if (p.rotation.empty()) p.rotation.assign(am.model->mesh.nodes.size(), 0);
    p.rotation[static_cast<std::size_t>(r.rot_node)] = 1;
  }
  if (const RankWorld world = rank_world(); world.distributed()) p.node_rank = element_partition(am, world).rank_of_node;
  return p;
}

double krylov_tolerance(double residual_ratio, double residual_tolerance) {
  if (!(residual_ratio > 0.0)) return 1e-10;
  return std::clamp(kKrylovTarget * residual_tolerance / residual_ratio, 1e-10, 1e-2);
}

CorrectionOutcome CorrectionSolver::solve(const SparseMatrix& tangent, bool saddle_point, std::span<const double> r,
                                          std::span<double> du, std::size_t n_displacement, double model_size,
                                          double residual_ratio) {
  CorrectionOutcome out;
  if (solvers_.petsc) solvers_.petsc->set_relative_tolerance(krylov_tolerance(residual_ratio, residual_tolerance_));
  else if (saddle_point || !tangent.upper_only) current_ = solvers_.umfpack.get();
  FactorStatus status;
  {
    const ScopedSeconds clock(solvers_.seconds.factorization, &solvers_.seconds.factorizations);
    status = current_->factorize(tangent);
    if (status == FactorStatus::NotPositiveDefinite && !solvers_.petsc) {
      current_ = solvers_.umfpack.get();
      status = current_->factorize(tangent);
    }
  }
  if (status == FactorStatus::Singular || status == FactorStatus::NotPositiveDefinite) {
    out.failure = "the stiffness matrix is singular: a part of the model is free to move as a rigid body "
                  "(check its boundary conditions)";
    out.singular = true;
    return out;
  }
  if (status == FactorStatus::OutOfMemory) {
    out.failure = "out of memory in the factorisation";
    return out;
  }
  {
    const ScopedSeconds clock(solvers_.seconds.back_solve);
    const long krylov_before = current_->krylov_iterations();
    current_->solve(r, du);
    solvers_.seconds.krylov_iterations += current_->krylov_iterations() - krylov_before;
  }
  double largest_du = 0.0;  // over the displacement equations (not the contact multipliers)
  bool finite = true;
  for (std::size_t i = 0; i < n_displacement; ++i) {
    finite = finite && std::isfinite(du[i]);
    largest_du = std::max(largest_du, std::abs(du[i]));
  }
  if (!finite || largest_du > 1e8 * model_size) {
    out.failure = fmt::format("the stiffness matrix is singular: a part of the model is free to move as a rigid "
                              "body (check its boundary conditions); the correction was {:.3g}, {:.3g} times the "
                              "model size", largest_du, largest_du / model_size);
    out.singular = true;
    return out;
  }
  out.solved = true;
  return out;
}

}  // namespace inpact::solver
