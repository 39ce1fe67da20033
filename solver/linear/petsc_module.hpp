#pragma once
/// The C entry points of the PETSc module (libinpact_petsc.so, petsc_solver.cpp) that
/// petsc_module.cpp looks up after loading it; and the process-wide PETSc session.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "linear_solver.hpp"

extern "C" {
/// PetscInitialize (MPI_Init with it), on one rank or on those of mpirun; 0 on success.
int inpact_petsc_start();
/// PetscFinalize (MPI_Finalize with it).
void inpact_petsc_finish();
/// This process's rank and the ranks of PETSC_COMM_WORLD.
void inpact_mpi_world(int* rank, int* size);
/// values[0..n) combined over every rank, in place: op 0 sum, 1 min, 2 max.
void inpact_mpi_allreduce(double* values, long n, int op);
/// Every rank's `count` records of `record_bytes` bytes at `send`, concatenated in rank order
/// into `recv` on every rank; `count_of_rank[r]`: how many rank r sends (the same list on every
/// rank). Counted in records, so that a gather of more than 2 GiB stays within MPI's int counts.
void inpact_mpi_allgather_records(const void* send, long count, long record_bytes, void* recv, const long* count_of_rank);
/// Ends every rank of the run (MPI_Abort) with exit code `code`.
void inpact_mpi_abort(int code);
/// PETSc's graph partitioner (petsc_partition.cpp) on the graph of n vertices whose neighbours
/// are adjacency[xadj[v] .. xadj[v+1]) (no self-loops, sorted), the same on every rank: the
/// rank of each vertex into rank_of_element. Nonzero (the reason in `error`) on failure.
int inpact_partition_elements(long n, const long* xadj, const long* adjacency, int* rank_of_element,
                              std::string* error);
/// A new solver; the caller owns it. Null (with the reason in `error`) on failure.
inpact::solver::LinearSolver* inpact_petsc_create(const inpact::solver::EquationPoints* points, std::string* error);
}

namespace inpact::solver {

/// Whether this build has the PETSc path (PETSc was found when it was configured).
bool petsc_built();
/// "PETSc 3.18.5" (the version built against), or "" without PETSc.
std::string petsc_build_version();
/// Loads the module and starts PETSc (MPI_Init, PetscInitialize), once per process; later
/// calls do nothing. PetscFinalize runs at exit. Throws std::runtime_error when it cannot.
void start_petsc();

/// The ranks of this run as the analysis sees them: PETSC_COMM_WORLD once PETSc is started
/// (mpirun), one rank otherwise (no call loads the module).
struct RankWorld {
  int rank = 0;
  int size = 1;
  bool distributed() const { return size > 1; }
  /// values summed over the ranks, in place (nothing on one rank).
  void sum(std::span<double> values) const;
  /// The smallest value over the ranks.
  double min(double value) const;
  /// Every rank's `mine` (records of `record_bytes` bytes), concatenated in rank order into `all`
  /// (on every rank); rank r gives count_of_rank[r] records, which every rank knows. On one
  /// rank `all` is `mine`.
  void gather(std::span<const std::byte> mine, std::span<std::byte> all, std::size_t record_bytes,
              std::span<const long> count_of_rank) const;
  /// A rank that cannot go on ends them all (on one rank: nothing; the caller exits).
  void abort(int code) const;
};
RankWorld rank_world();

/// The rank of each vertex of a graph (CSR: xadj, adjacency, as inpact_partition_elements
/// takes it) by PETSc's partitioner over the ranks of the run. Throws std::runtime_error.
std::vector<int> partition_graph(std::span<const long> xadj, std::span<const long> adjacency);

}  // namespace inpact::solver
