#pragma once
/// Sparse solvers behind one interface. The symbolic analysis (ordering, elimination tree, a
/// preconditioner's pattern) is kept while the pattern stays the same.
///  - CHOLMOD (supernodal Cholesky): symmetric positive definite systems.
///  - UMFPACK (unsymmetric multifrontal LU): Lagrange multipliers (indefinite) and friction
///    (unsymmetric). 2-10× slower and 2.5× the memory of CHOLMOD on SPD systems: use only there.
///  - PETSc (petsc_solver.cpp, a module loaded on use): Krylov methods with algebraic multigrid,
///    and MUMPS for saddle-point systems. "Factorise" sets the preconditioner up; "solve" iterates.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

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
  /// An iterative solver stops when ||b − A x|| <= rtol ||b||; a direct one ignores it.
  virtual void set_relative_tolerance(double rtol) {}
  /// Krylov iterations of every solve so far (0 for a direct solver).
  virtual long krylov_iterations() const { return 0; }
};

/// Where the displacement equations of a step sit: what an algebraic multigrid needs to build
/// the rigid-body modes of the mesh (its near null space) and to keep a node's DOFs together.
/// Equations beyond these (contact multipliers) have no point.
struct EquationPoints {
  int dim = 3;                       ///< displacement components per node
  std::vector<std::int64_t> node;    ///< per equation: its node (a row of the mesh's nodes)
  std::vector<int> component;        ///< per equation: 0 .. dim-1
  std::vector<double> coordinates;   ///< per node row: x, y, z (3 per node, every node)
  /// Per node row: 1 for a rotation node (a beam's, shell's, rigid body's or coupling's: its
  /// components are the rotation θ; θ3 in component 0 in 2D), which a rigid-body motion turns
  /// rather than moves. Empty: the model has none.
  std::vector<char> rotation;
  /// A distributed run: per node row, the rank whose elements it belongs to (the lowest of
  /// them), which owns its rows of the system. Empty: the rows are shared evenly in order.
  std::vector<int> node_rank;
};

std::unique_ptr<LinearSolver> make_cholmod_solver();
std::unique_ptr<LinearSolver> make_umfpack_solver();
/// The PETSc solver (petsc_module.cpp loads the module and starts PETSc on first use). Throws
/// std::runtime_error when this build has no PETSc or the module cannot be loaded.
std::unique_ptr<LinearSolver> make_petsc_solver(const EquationPoints& points);

}  // namespace inpact::solver
