#include "linear_solve.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace inpact::solver {

CorrectionOutcome CorrectionSolver::solve(const SparseMatrix& tangent, bool saddle_point, std::span<const double> r,
                                          std::span<double> du, std::size_t n_displacement, double model_size) {
  CorrectionOutcome out;
  if (saddle_point || !tangent.upper_only) current_ = solvers_.umfpack.get();
  FactorStatus status;
  {
    const ScopedSeconds clock(solvers_.seconds.factorization, &solvers_.seconds.factorizations);
    status = current_->factorize(tangent);
    if (status == FactorStatus::NotPositiveDefinite) {
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
    current_->solve(r, du);
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
