#pragma once
/// Where an MPI launcher (`mpirun -np N`, `mpiexec`) put this process, read from the launcher's
/// environment before MPI is started: the executable does not link MPI (petsc_module.cpp), yet
/// the choice of solver and who writes the results must be known before the deck is analysed.
namespace inpact::solver {

struct LaunchRanks {
  int rank = 0;  ///< this process, 0 .. size-1
  int size = 1;  ///< ranks of the run; 1 without a launcher
};

/// Open MPI's OMPI_COMM_WORLD_{RANK,SIZE}, else MPICH's PMI_{RANK,SIZE}, else one rank.
LaunchRanks launch_ranks();

}  // namespace inpact::solver
