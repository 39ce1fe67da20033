#pragma once
/// Direct sparse solvers behind one interface. The symbolic analysis (ordering, elimination
/// tree) is kept while the pattern stays the same; each Newton iteration only refactors.
///  - CHOLMOD (supernodal Cholesky): symmetric positive definite systems.
///  - UMFPACK (unsymmetric multifrontal LU): Lagrange multipliers (indefinite) and friction
///    (unsymmetric). 2-10× slower and 2.5× the memory of CHOLMOD on SPD systems: use only there.
#include <memory>
#include <span>
#include <string>

#include "sparse_matrix.hpp"

namespace inpact::solver {

enum class FactorStatus {
  Ok,
  NotPositiveDefinite,  ///< CHOLMOD met a non-positive pivot: the system is not SPD
  Singular,             ///< a zero pivot: an unconstrained rigid mode, or a singular matrix
  OutOfMemory
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Factorises A. The symbolic analysis is redone only when the pattern (n, nnz, column
  /// pointers) differs from the last call.
  virtual FactorStatus factorize(const SparseMatrix& a) = 0;
  /// Solves A x = b with the last factorisation.
  virtual void solve(std::span<const double> b, std::span<double> x) = 0;
  virtual std::string name() const = 0;
  /// How many symbolic analyses were done (for tests and the benchmark log).
  virtual int analyses() const = 0;
  /// For a Singular or NotPositiveDefinite status: the equation where it showed, or -1.
  virtual std::int64_t failed_equation() const = 0;
};

std::unique_ptr<LinearSolver> make_cholmod_solver();
std::unique_ptr<LinearSolver> make_umfpack_solver();

}  // namespace inpact::solver
