/// The element partition of a distributed run, by PETSc's graph partitioner (MatPartitioning,
/// PT-Scotch in Debian's PETSc) on the elements' dual graph. Part of the PETSc module.
#include <petscmat.h>

#include <algorithm>
#include <string>

#include "petsc_error.hpp"
#include "petsc_module.hpp"

extern "C" int inpact_partition_elements(long n, const long* xadj, const long* adjacency, int* rank_of_element,
                                         std::string* error) {
  const MPI_Comm comm = PETSC_COMM_WORLD;
  PetscMPIInt rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  // Each rank gives PETSc an even block of the graph's rows; every rank holds the whole graph.
  const long begin = n * rank / ranks, end = n * (rank + 1) / ranks;
  PetscInt *ia = nullptr, *ja = nullptr;  // owned by the MPIAdj matrix once created
  PetscMalloc1(end - begin + 1, &ia);
  PetscMalloc1(xadj[end] - xadj[begin], &ja);
  for (long e = begin; e <= end; ++e) ia[e - begin] = static_cast<PetscInt>(xadj[e] - xadj[begin]);
  for (long k = xadj[begin]; k < xadj[end]; ++k) ja[k - xadj[begin]] = static_cast<PetscInt>(adjacency[k]);
  Mat graph = nullptr;
  MatPartitioning partitioning = nullptr;
  IS local = nullptr, all = nullptr;
  PetscErrorCode code = MatCreateMPIAdj(comm, static_cast<PetscInt>(end - begin), static_cast<PetscInt>(n), ia, ja,
                                        nullptr, &graph);
  const char* step = "MatCreateMPIAdj";
  if (!code) code = MatPartitioningCreate(comm, &partitioning), step = "MatPartitioningCreate";
  if (!code) code = MatPartitioningSetAdjacency(partitioning, graph), step = "MatPartitioningSetAdjacency";
  if (!code) code = MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH), step = "MatPartitioningSetType";
  if (!code) code = MatPartitioningSetFromOptions(partitioning), step = "MatPartitioningSetFromOptions";
  if (!code) code = MatPartitioningApply(partitioning, &local), step = "MatPartitioningApply";
  if (!code) code = ISAllGather(local, &all), step = "ISAllGather";
  if (!code) {
    const PetscInt* parts = nullptr;
    ISGetIndices(all, &parts);
    std::copy(parts, parts + n, rank_of_element);
    ISRestoreIndices(all, &parts);
  } else {
    *error = inpact::solver::petsc_error(code, step);
  }
  if (all) ISDestroy(&all);
  if (local) ISDestroy(&local);
  if (partitioning) MatPartitioningDestroy(&partitioning);
  if (graph) MatDestroy(&graph);
  return code ? 1 : 0;
}
