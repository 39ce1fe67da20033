/// The PETSc solver path (the module libinpact_petsc.so, loaded on use), on one process or on
/// the ranks of `mpirun -np N` (PETSC_COMM_WORLD). Every rank holds its part of the inpact
/// system (the ranks share the elements, solver/assembler.hpp), whose entries may lie in any
/// row; each owns the rows of its elements' nodes (RowOwnership), PETSc adds the parts up
/// (preallocate_from_every_rank, fill_values), and the solution comes back to every rank.
///  - a symmetric system (upper_only): CG preconditioned by smoothed-aggregation algebraic
///    multigrid (GAMG) whose near null space is the mesh's rigid-body modes
///    (MatNullSpaceCreateRigidBody from the node coordinates);
///  - an unsymmetric one (friction): GMRES, right-preconditioned by the same GAMG;
///  - a saddle-point system (contact multipliers): LU by MUMPS, through PCLU;
///  - a Krylov solve that does not converge (an indefinite tangent for CG, a stagnating
///    GMRES) is redone by MUMPS on the same matrix, so that no iteration is lost to it.
/// GAMG aggregates whole nodes (block size = dim): the prescribed DOFs of a node that has free
/// ones stay in the PETSc matrix as rows of the identity (scaled like the diagonal), with zero
/// on the right-hand side, so every node keeps its dim rows. Both residual norms are the true
/// (unpreconditioned) ones: rtol means ||b − A x|| <= rtol ||b||.
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "linear_solver.hpp"
#include "petsc_error.hpp"
#include "petsc_module.hpp"
#include "rigid_body_modes.hpp"

namespace inpact::solver {

namespace {

/// A Krylov solve that needs more has met a system it cannot do: MUMPS does it instead.
constexpr PetscInt kMaxKrylovIterations = 2000;

void check(PetscErrorCode code, const char* what) {
  if (code != 0) throw std::runtime_error(petsc_error(code, what));
}

/// The inpact equations placed in the PETSc system: displacement equations node by node
/// (dim slots each, the missing ones identity rows), then the multipliers.
struct SlotLayout {
  std::vector<PetscInt> slot_of_eq;    ///< per inpact equation
  std::vector<PetscInt> fixed_slots;   ///< identity rows
  std::vector<double> block_coords;    ///< per node block: dim coordinates
  std::vector<char> block_rotation;    ///< per node block: 1 for a rotation node (empty: none)
  PetscInt n_displacement_slots = 0;

  std::vector<PetscInt> blocks_of_rank;  ///< node blocks per rank, in slot order (node_rank given)

  SlotLayout(const EquationPoints& p, std::int64_t n_equations, PetscMPIInt ranks) {
    const auto n_disp = static_cast<std::int64_t>(p.node.size());
    std::vector<std::int64_t> node_of_block;  // the nodes with equations, in order of appearance
    std::vector<char> listed;
    for (std::int64_t e = 0; e < n_disp; ++e) {
      const auto node = static_cast<std::size_t>(p.node[e]);
      if (listed.size() <= node) listed.resize(node + 1, 0);
      if (!listed[node]) node_of_block.push_back(p.node[e]);
      listed[node] = 1;
    }
    // A distributed run: each rank's nodes together, so that it owns the rows of its elements.
    if (!p.node_rank.empty()) {
      const auto rank_of = [&](std::int64_t node) { return p.node_rank[static_cast<std::size_t>(node)]; };
      std::stable_sort(node_of_block.begin(), node_of_block.end(),
                       [&](std::int64_t a, std::int64_t b) { return rank_of(a) < rank_of(b); });
      blocks_of_rank.assign(static_cast<std::size_t>(ranks), 0);
      for (std::int64_t node : node_of_block) ++blocks_of_rank[static_cast<std::size_t>(rank_of(node))];
    }
    std::vector<PetscInt> block_of_node(listed.size(), -1);
    for (std::size_t b = 0; b < node_of_block.size(); ++b)
      block_of_node[static_cast<std::size_t>(node_of_block[b])] = static_cast<PetscInt>(b);
    slot_of_eq.resize(static_cast<std::size_t>(n_equations));
    for (std::int64_t e = 0; e < n_disp; ++e)
      slot_of_eq[e] = block_of_node[static_cast<std::size_t>(p.node[e])] * p.dim + p.component[e];
    n_displacement_slots = static_cast<PetscInt>(node_of_block.size()) * p.dim;
    for (std::int64_t e = n_disp; e < n_equations; ++e)
      slot_of_eq[e] = n_displacement_slots + static_cast<PetscInt>(e - n_disp);
    std::vector<char> used(static_cast<std::size_t>(n_displacement_slots), 0);
    for (std::int64_t e = 0; e < n_disp; ++e) used[slot_of_eq[e]] = 1;
    for (PetscInt s = 0; s < n_displacement_slots; ++s)
      if (!used[s]) fixed_slots.push_back(s);
    for (std::int64_t node : node_of_block)
      for (int c = 0; c < p.dim; ++c) block_coords.push_back(p.coordinates[3 * node + c]);
    if (!p.rotation.empty())
      for (std::int64_t node : node_of_block) block_rotation.push_back(p.rotation[static_cast<std::size_t>(node)]);
  }
  PetscInt size(std::int64_t n_equations, std::int64_t n_disp) const {
    return n_displacement_slots + static_cast<PetscInt>(n_equations - n_disp);
  }
};

/// The rows [begin, end) of the PETSc system this rank owns: the node blocks of its elements
/// (SlotLayout::blocks_of_rank; the last rank takes the multipliers too), or else an even share
/// of the node blocks (whole blocks, so that GAMG keeps a node's DOFs together) or of the rows
/// of a saddle-point system (MUMPS needs no blocks).
struct RowOwnership {
  PetscInt begin = 0, end = 0;

  RowOwnership(const SlotLayout& layout, PetscInt n, PetscInt dim, bool saddle_point, PetscMPIInt rank,
               PetscMPIInt ranks) {
    if (!layout.blocks_of_rank.empty()) {
      for (PetscMPIInt r = 0; r < rank; ++r) begin += layout.blocks_of_rank[static_cast<std::size_t>(r)] * dim;
      end = begin + layout.blocks_of_rank[static_cast<std::size_t>(rank)] * dim;
      if (rank == ranks - 1) end = n;
      return;
    }
    const PetscInt block = saddle_point ? 1 : dim;
    const PetscInt units = n / block, share = units / ranks, extra = units % ranks;
    const auto first_unit = [&](PetscMPIInt r) { return r * share + std::min<PetscInt>(r, extra); };
    begin = first_unit(rank) * block;
    end = first_unit(rank + 1) * block;
  }
  PetscInt size() const { return end - begin; }
};

/// The CSR pattern of the PETSc matrix and where each entry of the inpact matrix goes.
struct CsrMap {
  std::vector<PetscInt> row_ptr, col;
  std::vector<PetscInt> target, mirror_target;  ///< per inpact entry (mirror: its transpose, upper_only)

  /// Rows are filled by counting (the inpact matrix holds columns), then each row is sorted:
  /// a sort of all 2·nnz entries at once took 3 s of a 6 s set-up at 100k DOF.
  CsrMap(const SparseMatrix& a, const SlotLayout& layout, PetscInt n) {
    const auto nnz = static_cast<std::int64_t>(a.nnz());
    // Each PETSc entry comes from a source: inpact entry k (k), its mirror (nnz + k), or the
    // identity of fixed slot f (2 nnz + f, set_fixed_diagonals).
    const auto for_each_entry = [&](auto&& visit) {
      for (std::int64_t c = 0; c < a.n; ++c)
        for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
          const PetscInt r = layout.slot_of_eq[a.row_idx[k]], s = layout.slot_of_eq[c];
          visit(r, s, k);
          if (a.upper_only && r != s) visit(s, r, nnz + k);
        }
      for (std::size_t f = 0; f < layout.fixed_slots.size(); ++f)
        visit(layout.fixed_slots[f], layout.fixed_slots[f], 2 * nnz + static_cast<std::int64_t>(f));
    };
    row_ptr.assign(static_cast<std::size_t>(n) + 1, 0);
    for_each_entry([&](PetscInt r, PetscInt, std::int64_t) { ++row_ptr[r + 1]; });
    std::partial_sum(row_ptr.begin(), row_ptr.end(), row_ptr.begin());
    col.resize(static_cast<std::size_t>(row_ptr[n]));
    std::vector<std::int64_t> source(col.size());
    std::vector<PetscInt> next(row_ptr.begin(), row_ptr.end() - 1);
    for_each_entry([&](PetscInt r, PetscInt s, std::int64_t src) {
      col[next[r]] = s;
      source[next[r]++] = src;
    });
    std::vector<std::pair<PetscInt, std::int64_t>> row;
    for (PetscInt r = 0; r < n; ++r) {
      row.clear();
      for (PetscInt i = row_ptr[r]; i < row_ptr[r + 1]; ++i) row.emplace_back(col[i], source[i]);
      std::sort(row.begin(), row.end());
      for (std::size_t j = 0; j < row.size(); ++j) {
        col[row_ptr[r] + j] = row[j].first;
        source[row_ptr[r] + j] = row[j].second;
      }
    }
    target.assign(a.nnz(), -1);
    mirror_target.assign(a.upper_only ? a.nnz() : 0, -1);
    for (std::size_t i = 0; i < source.size(); ++i) {
      const std::int64_t src = source[i];
      if (src < nnz) target[static_cast<std::size_t>(src)] = static_cast<PetscInt>(i);
      else if (src < 2 * nnz) mirror_target[static_cast<std::size_t>(src - nnz)] = static_cast<PetscInt>(i);
    }
  }
};

class PetscSolver final : public LinearSolver {
 public:
  explicit PetscSolver(const EquationPoints& points) : points_(points) { MPI_Comm_size(comm_, &ranks_); }
  ~PetscSolver() override { release(); }
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  FactorStatus factorize(const SparseMatrix& a) override;
  void solve(std::span<const double> b, std::span<double> x) override;
  std::string name() const override { return name_; }
  int analyses() const override { return analyses_; }
  std::int64_t failed_equation() const override { return -1; }
  void set_relative_tolerance(double rtol) override { rtol_ = rtol; }
  long krylov_iterations() const override { return krylov_iterations_; }

 private:
  void build(const SparseMatrix& a);
  void preallocate_from_every_rank(PetscInt m, PetscInt n);
  /// GAMG's near null space for this rank's m of the n rows: the mesh's rigid-body modes.
  PetscOwned<MatNullSpace, MatNullSpaceDestroy> rigid_body_modes(PetscInt m, PetscInt n) const;
  void set_fixed_diagonals();
  void fill_values(const SparseMatrix& a);
  void configure_krylov(KSPType type);
  bool set_up_krylov(bool symmetric);
  FactorStatus set_up_lu();
  bool krylov_solve(KSPType type);
  void release();

  EquationPoints points_;
  std::vector<std::int64_t> col_ptr_, row_idx_;  ///< pattern of the current matrix
  std::unique_ptr<SlotLayout> layout_;
  std::unique_ptr<CsrMap> csr_;
  std::unique_ptr<RowOwnership> rows_;
  std::vector<PetscScalar> values_;  ///< the PETSc matrix's values in csr_'s order (every row)
  MPI_Comm comm_ = PETSC_COMM_WORLD;
  PetscMPIInt ranks_ = 1;
  std::int64_t n_ = 0;
  bool saddle_point_ = false, symmetric_ = true, lu_ready_ = false, krylov_ready_ = false;
  Mat a_ = nullptr;
  Vec b_ = nullptr, x_ = nullptr;
  Vec x_everywhere_ = nullptr;          ///< the whole solution on every rank
  VecScatter to_everywhere_ = nullptr;
  KSP krylov_ = nullptr, lu_ = nullptr;
  double rtol_ = 1e-8;
  long krylov_iterations_ = 0;
  int analyses_ = 0;
  std::string name_ = "PETSc";
};

void PetscSolver::release() {
  if (krylov_) KSPDestroy(&krylov_);
  if (lu_) KSPDestroy(&lu_);
  if (a_) MatDestroy(&a_);
  if (b_) VecDestroy(&b_);
  if (x_) VecDestroy(&x_);
  if (x_everywhere_) VecDestroy(&x_everywhere_);
  if (to_everywhere_) VecScatterDestroy(&to_everywhere_);
}

/// A new pattern: the slot layout, the CSR map, this rank's rows of the matrix (with its block
/// size and near null space when it is solved iteratively), the vectors and both solvers.
void PetscSolver::build(const SparseMatrix& a) {
  release();
  n_ = a.n;
  const auto n_disp = static_cast<std::int64_t>(points_.node.size());
  saddle_point_ = n_ > n_disp;
  PetscMPIInt rank = 0;
  MPI_Comm_rank(comm_, &rank);
  layout_ = std::make_unique<SlotLayout>(points_, n_, ranks_);
  const PetscInt n = layout_->size(n_, n_disp);
  csr_ = std::make_unique<CsrMap>(a, *layout_, n);
  values_.assign(csr_->col.size(), 0.0);
  rows_ = std::make_unique<RowOwnership>(*layout_, n, points_.dim, saddle_point_, rank, ranks_);
  const PetscInt m = rows_->size();
  check(MatCreate(comm_, &a_), "MatCreate");
  check(MatSetSizes(a_, m, m, n, n), "MatSetSizes");
  if (!saddle_point_) check(MatSetBlockSize(a_, points_.dim), "MatSetBlockSize");
  check(MatSetType(a_, MATAIJ), "MatSetType");
  if (ranks_ == 1) check(MatSeqAIJSetPreallocationCSR(a_, csr_->row_ptr.data(), csr_->col.data(), values_.data()),
                         "preallocation");
  else preallocate_from_every_rank(m, n);
  check(MatSetOption(a_, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "MatSetOption");
  if (!saddle_point_) check(MatSetNearNullSpace(a_, rigid_body_modes(m, n).get()), "MatSetNearNullSpace");
  check(MatCreateVecs(a_, &x_, &b_), "MatCreateVecs");
  check(VecScatterCreateToAll(x_, &to_everywhere_, &x_everywhere_), "VecScatterCreateToAll");
  check(KSPCreate(comm_, &lu_), "KSPCreate");
  check(KSPSetType(lu_, KSPPREONLY), "KSPSetType");
  PC pc;
  check(KSPGetPC(lu_, &pc), "KSPGetPC");
  check(PCSetType(pc, PCLU), "PCSetType");
  check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  check(KSPSetOptionsPrefix(lu_, "lu_"), "prefix");
  check(KSPSetFromOptions(lu_), "KSPSetFromOptions");
  if (!saddle_point_) {
    check(KSPCreate(comm_, &krylov_), "KSPCreate");
    check(KSPGetPC(krylov_, &pc), "KSPGetPC");
    check(PCSetType(pc, PCGAMG), "PCSetType");
    // The prolongator of the first Newton iteration serves the later ones of the pattern.
    check(PCGAMGSetReuseInterpolation(pc, PETSC_TRUE), "PCGAMGSetReuseInterpolation");
  }
  ++analyses_;
}

/// Without rotation nodes, PETSc's own modes from the coordinates; with them, those of
/// rigid_body_modes.hpp, orthonormalised (Gram–Schmidt).
PetscOwned<MatNullSpace, MatNullSpaceDestroy> PetscSolver::rigid_body_modes(PetscInt m, PetscInt n) const {
  const PetscInt dim = points_.dim;
  const double* coords = layout_->block_coords.data() + rows_->begin;
  PetscOwned<MatNullSpace, MatNullSpaceDestroy> rigid;
  if (layout_->block_rotation.empty()) {
    PetscOwned<Vec, VecDestroy> c;
    check(VecCreateMPIWithArray(comm_, dim, m, n, coords, c.out()), "coords");
    check(MatNullSpaceCreateRigidBody(c.get(), rigid.out()), "MatNullSpaceCreateRigidBody");
    return rigid;
  }
  const auto values = solver::rigid_body_modes(
      static_cast<int>(dim), std::span<const double>(coords, static_cast<std::size_t>(m)),
      std::span<const char>(layout_->block_rotation.data() + rows_->begin / dim, static_cast<std::size_t>(m / dim)));
  std::vector<PetscOwned<Vec, VecDestroy>> owned(values.size());
  std::vector<Vec> modes(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    check(VecCreateMPI(comm_, m, n, owned[k].out()), "VecCreateMPI");
    Vec v = modes[k] = owned[k].get();
    PetscScalar* a;
    check(VecGetArray(v, &a), "VecGetArray");
    std::copy(values[k].begin(), values[k].end(), a);
    check(VecRestoreArray(v, &a), "VecRestoreArray");
    for (std::size_t i = 0; i < k; ++i) {  // Gram–Schmidt against the modes before it
      PetscScalar d;
      check(VecDot(v, modes[i], &d), "VecDot");
      check(VecAXPY(v, -d, modes[i]), "VecAXPY");
    }
    check(VecNormalize(v, nullptr), "VecNormalize");
  }
  check(MatNullSpaceCreate(comm_, PETSC_FALSE, static_cast<PetscInt>(modes.size()), modes.data(), rigid.out()),
        "MatNullSpaceCreate");
  return rigid;
}

/// Several ranks: each holds the entries of its own elements, in rows other ranks may own
/// (Assembler). PETSc's preallocator gathers each row's columns from every rank at its owner.
void PetscSolver::preallocate_from_every_rank(PetscInt m, PetscInt n) {
  PetscOwned<Mat, MatDestroy> owned;
  check(MatCreate(comm_, owned.out()), "MatCreate");
  Mat counter = owned.get();
  check(MatSetType(counter, MATPREALLOCATOR), "MatSetType");
  check(MatSetSizes(counter, m, m, n, n), "MatSetSizes");
  if (!saddle_point_) check(MatSetBlockSize(counter, points_.dim), "MatSetBlockSize");
  check(MatSetUp(counter), "MatSetUp");
  for (PetscInt r = 0; r < n; ++r)
    if (const PetscInt at = csr_->row_ptr[r], count = csr_->row_ptr[r + 1] - at; count > 0)
      check(MatSetValues(counter, 1, &r, count, csr_->col.data() + at, values_.data() + at, INSERT_VALUES),
            "MatSetValues");
  check(MatAssemblyBegin(counter, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(counter, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(MatPreallocatorPreallocate(counter, PETSC_TRUE, a_), "MatPreallocatorPreallocate");
}

/// The inpact values into the PETSc matrix. On several ranks each holds a partial sum (its share
/// of the elements and of the contact's slave nodes, solver/assembler.hpp): every rank adds what
/// it has, the rows of others included, and PETSc's
/// assembly sends those to their owners. Then the identity rows (set_fixed_diagonals).
void PetscSolver::fill_values(const SparseMatrix& a) {
  std::fill(values_.begin(), values_.end(), 0.0);
  for (std::int64_t c = 0; c < a.n; ++c)
    for (std::int64_t k = a.col_ptr[c]; k < a.col_ptr[c + 1]; ++k) {
      values_[csr_->target[k]] += a.values[k];
      if (a.upper_only && a.row_idx[k] != c) values_[csr_->mirror_target[k]] += a.values[k];
    }
  if (ranks_ == 1) {  // the SEQAIJ arrays are csr_'s order: one copy
    PetscScalar* v = nullptr;
    check(MatSeqAIJGetArray(a_, &v), "MatSeqAIJGetArray");
    std::copy(values_.begin(), values_.end(), v);
    check(MatSeqAIJRestoreArray(a_, &v), "MatSeqAIJRestoreArray");
  } else {
    check(MatZeroEntries(a_), "MatZeroEntries");
    const PetscInt n = static_cast<PetscInt>(csr_->row_ptr.size()) - 1;
    for (PetscInt r = 0; r < n; ++r) {
      const PetscInt at = csr_->row_ptr[r], count = csr_->row_ptr[r + 1] - at;
      const PetscScalar* row = values_.data() + at;
      const bool owned = r >= rows_->begin && r < rows_->end;
      if (!owned && std::all_of(row, row + count, [](PetscScalar v) { return v == 0.0; })) continue;
      check(MatSetValues(a_, 1, &r, count, csr_->col.data() + at, row, ADD_VALUES), "MatSetValues");
    }
    check(MatAssemblyBegin(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  }
  set_fixed_diagonals();
}

/// The identity rows take the mean |diagonal| of the displacement rows (so that they weigh
/// like the others in GAMG's aggregation), from the assembled matrix: on several ranks no
/// rank holds a whole diagonal before the assembly.
void PetscSolver::set_fixed_diagonals() {
  if (layout_->fixed_slots.empty()) return;
  PetscOwned<Vec, VecDestroy> owned;
  check(MatCreateVecs(a_, nullptr, owned.out()), "MatCreateVecs");
  Vec diagonal = owned.get();
  check(MatGetDiagonal(a_, diagonal), "MatGetDiagonal");
  const PetscScalar* d = nullptr;
  check(VecGetArrayRead(diagonal, &d), "VecGetArrayRead");
  const auto& fixed = layout_->fixed_slots;  // ascending
  auto next_fixed = std::lower_bound(fixed.begin(), fixed.end(), rows_->begin);
  double sums[2] = {0.0, 0.0};  // Σ |diagonal|, rows
  for (PetscInt s = rows_->begin; s < std::min(rows_->end, layout_->n_displacement_slots); ++s) {
    if (next_fixed != fixed.end() && *next_fixed == s) {
      ++next_fixed;
      continue;
    }
    sums[0] += std::abs(d[s - rows_->begin]);
    sums[1] += 1.0;
  }
  check(VecRestoreArrayRead(diagonal, &d), "VecRestoreArrayRead");
  if (ranks_ > 1) MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_);
  const PetscScalar scale = sums[1] > 0 && sums[0] > 0 ? sums[0] / sums[1] : 1.0;
  for (auto f = std::lower_bound(fixed.begin(), fixed.end(), rows_->begin); f != fixed.end() && *f < rows_->end; ++f)
    check(MatSetValues(a_, 1, &*f, 1, &*f, &scale, INSERT_VALUES), "MatSetValues");
  check(MatAssemblyBegin(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

/// CG (left preconditioning) or GMRES (right); both stop on the true residual norm.
void PetscSolver::configure_krylov(KSPType type) {
  const bool cg = std::string(type) == KSPCG;
  check(KSPSetType(krylov_, type), "KSPSetType");
  check(KSPSetPCSide(krylov_, cg ? PC_LEFT : PC_RIGHT), "KSPSetPCSide");
  if (!cg) check(KSPGMRESSetRestart(krylov_, 100), "KSPGMRESSetRestart");
  check(KSPSetNormType(krylov_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(krylov_, rtol_, 1e-300, PETSC_DEFAULT, kMaxKrylovIterations), "KSPSetTolerances");
  check(KSPSetFromOptions(krylov_), "KSPSetFromOptions");  // PETSC_OPTIONS may override any of these
}

/// Whether GAMG could be set up: on a tangent far from a converged state (a diverging
/// increment about to be cut back) its eigenvalue estimate may find nothing to smooth.
bool PetscSolver::set_up_krylov(bool symmetric) {
  check(KSPSetOperators(krylov_, a_, a_), "KSPSetOperators");
  configure_krylov(symmetric ? KSPCG : KSPGMRES);
  int failed = KSPSetUp(krylov_) != 0 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm_);  // every rank takes the same branch
  return failed == 0;
}

FactorStatus PetscSolver::set_up_lu() {
  check(KSPSetOperators(lu_, a_, a_), "KSPSetOperators");
  const PetscErrorCode code = KSPSetUp(lu_);
  PC pc;
  KSPGetPC(lu_, &pc);
  PCFailedReason reason = PC_NOERROR;
  PCGetFailedReason(pc, &reason);
  // A factor fails on one rank's rows: every rank must take the same branch after it.
  int failure[2] = {static_cast<int>(reason), code != 0 ? 1 : 0};
  MPI_Allreduce(MPI_IN_PLACE, failure, 2, MPI_INT, MPI_MAX, comm_);
  reason = static_cast<PCFailedReason>(failure[0]);
  if (reason == PC_FACTOR_OUTMEMORY) return FactorStatus::OutOfMemory;
  if (failure[1] != 0 || reason != PC_NOERROR) return FactorStatus::Singular;
  lu_ready_ = true;
  return FactorStatus::Ok;
}

FactorStatus PetscSolver::factorize(const SparseMatrix& a) {
  // Each rank holds its own part of the pattern: a change in one (its contact nodes') is a new
  // matrix on every rank.
  int changed = !a_ || a.n != n_ || a.col_ptr != col_ptr_ || a.row_idx != row_idx_ ? 1 : 0;
  if (ranks_ > 1) MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, comm_);
  if (changed) {
    build(a);
    col_ptr_ = a.col_ptr;
    row_idx_ = a.row_idx;
  }
  fill_values(a);
  symmetric_ = a.upper_only;
  lu_ready_ = false;
  krylov_ready_ = false;
  if (saddle_point_) {
    name_ = "PETSc MUMPS";
    return set_up_lu();
  }
  name_ = symmetric_ ? "PETSc CG+GAMG" : "PETSc GMRES+GAMG";
  krylov_ready_ = set_up_krylov(symmetric_);
  if (krylov_ready_) return FactorStatus::Ok;
  name_ = "PETSc MUMPS (GAMG could not be set up)";
  return set_up_lu();
}

/// One Krylov solve of b_ into x_ from zero; whether it converged.
bool PetscSolver::krylov_solve(KSPType type) {
  configure_krylov(type);
  check(KSPSolve(krylov_, b_, x_), "KSPSolve");
  PetscInt its = 0;
  KSPGetIterationNumber(krylov_, &its);
  krylov_iterations_ += its;
  KSPConvergedReason reason;
  KSPGetConvergedReason(krylov_, &reason);
  return reason > 0;
}

void PetscSolver::solve(std::span<const double> b, std::span<double> x) {
  PetscScalar* bv = nullptr;
  check(VecSet(b_, 0.0), "VecSet");
  check(VecGetArray(b_, &bv), "VecGetArray");
  for (std::size_t e = 0; e < b.size(); ++e) {
    const PetscInt slot = layout_->slot_of_eq[e];
    if (slot >= rows_->begin && slot < rows_->end) bv[slot - rows_->begin] = b[e];
  }
  check(VecRestoreArray(b_, &bv), "VecRestoreArray");
  bool solved = false;
  if (krylov_ready_) {
    solved = krylov_solve(symmetric_ ? KSPCG : KSPGMRES);
    if (!solved && symmetric_) solved = krylov_solve(KSPGMRES);  // CG met an indefinite tangent
    if (!solved) name_ = "PETSc MUMPS (the Krylov solve did not converge)";
  }
  if (!solved) {
    if (!lu_ready_ && set_up_lu() != FactorStatus::Ok) {
      std::fill(x.begin(), x.end(), std::nan(""));  // the rigid-body guard reports it as singular
      return;
    }
    check(KSPSolve(lu_, b_, x_), "MUMPS solve");
  }
  check(VecScatterBegin(to_everywhere_, x_, x_everywhere_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(to_everywhere_, x_, x_everywhere_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* xv = nullptr;
  check(VecGetArrayRead(x_everywhere_, &xv), "VecGetArrayRead");
  for (std::size_t e = 0; e < x.size(); ++e) x[e] = xv[layout_->slot_of_eq[e]];
  check(VecRestoreArrayRead(x_everywhere_, &xv), "VecRestoreArrayRead");
}

}  // namespace

}  // namespace inpact::solver

extern "C" {

int inpact_petsc_start() {
  // One process started without mpirun: Open MPI's singleton start probes every network
  // transport and prepares to spawn processes, 1.0 s of idle waiting (0.4 s with these; measured
  // under load). One rank needs none of it. Settings the user made stay (overwrite = 0).
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK")) {
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("OMPI_MCA_mtl", "^ofi", 0);
  }
  int argc = 0;
  char** argv = nullptr;
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) return 1;
  // Errors come back as codes (check() turns them into exceptions), not as printed tracebacks.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  return 0;
}

void inpact_petsc_finish() { PetscFinalize(); }

void inpact_mpi_world(int* rank, int* size) {
  MPI_Comm_rank(PETSC_COMM_WORLD, rank);
  MPI_Comm_size(PETSC_COMM_WORLD, size);
}

void inpact_mpi_allgather_records(const void* send, long count, long record_bytes, void* recv, const long* count_of_rank) {
  int size = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<int> counts(static_cast<std::size_t>(size)), displacements(static_cast<std::size_t>(size));
  long at = 0;
  for (int r = 0; r < size; ++r) {
    counts[static_cast<std::size_t>(r)] = static_cast<int>(count_of_rank[r]);
    displacements[static_cast<std::size_t>(r)] = static_cast<int>(at);
    at += count_of_rank[r];
  }
  MPI_Datatype record;
  MPI_Type_contiguous(static_cast<int>(record_bytes), MPI_BYTE, &record);
  MPI_Type_commit(&record);
  MPI_Allgatherv(send, static_cast<int>(count), record, recv, counts.data(), displacements.data(), record,
                 PETSC_COMM_WORLD);
  MPI_Type_free(&record);
}

void inpact_mpi_abort(int code) {
  std::fflush(nullptr);
  MPI_Abort(PETSC_COMM_WORLD, code);
}

/// Reduced on rank 0 and sent to every rank, not MPI_Allreduce: with more than two ranks an
/// all-reduce may add in different orders on different ranks, and every rank must take the
/// same decisions (contact status, convergence) from bit-identical numbers.
void inpact_mpi_allreduce(double* values, long n, int op) {
  const MPI_Op mpi_op = op == 1 ? MPI_MIN : op == 2 ? MPI_MAX : MPI_SUM;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const int count = static_cast<int>(n);
  MPI_Reduce(rank == 0 ? MPI_IN_PLACE : values, rank == 0 ? values : nullptr, count, MPI_DOUBLE, mpi_op, 0,
             PETSC_COMM_WORLD);
  MPI_Bcast(values, count, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
}

inpact::solver::LinearSolver* inpact_petsc_create(const inpact::solver::EquationPoints* points, std::string* error) {
  try {
    return new inpact::solver::PetscSolver(*points);
  } catch (const std::exception& e) {
    *error = e.what();
    return nullptr;
  }
}
}
