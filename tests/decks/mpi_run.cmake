# End-to-end test of a distributed run: `mpirun -np 2 inpact run DECK` against the serial direct
# run of the same case, measured by bench/petsc_solver/compare_solvers.py (the issue's
# acceptance, and the measure `--solver petsc` is held to on one rank): every field of every
# frame within 1e-6 of the field's largest value over the step. The differences are the Krylov
# tolerance's (solver/linear_solve.cpp), not the distribution's.
#
#   cmake -DINPACT=inpact -DSOURCE=repo -DCASE=name -DWORK=dir [-DDECK=path] [-DCONTACT=ON] -P mpi_run.cmake
# CASE names a case of compare_solvers.py, or with DECK that deck (named by its file).
cmake_minimum_required(VERSION 3.22)
foreach(var INPACT SOURCE CASE WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "mpi_run.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
set(extra "")
if(DEFINED DECK)
  set(extra --extra "${DECK}")
endif()
execute_process(COMMAND /usr/bin/python3 "${SOURCE}/bench/petsc_solver/compare_solvers.py" --inpact "${INPACT}"
                        --out "${WORK}" --only "${CASE}" --ranks 2 ${extra}
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 280)
message(STATUS "${o}${e}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compare_solvers.py --ranks 2 --only ${CASE}: exit ${rc}")
endif()
# One set of files from the two ranks (rank 1 writes into a scratch folder it removes).
file(GLOB written RELATIVE "${WORK}/petsc" "${WORK}/petsc/*")
list(SORT written)
set(expected "${CASE}.dat;${CASE}.h5;${CASE}.sta;${CASE}.timings;${CASE}.xdmf")
if(NOT written STREQUAL expected)
  message(FATAL_ERROR "the run on 2 ranks wrote [${written}], expected [${expected}]")
endif()
file(READ "${WORK}/petsc/${CASE}.dat" dat)
string(FIND "${dat}" "LINEAR SOLVER: petsc" solver_at)
string(FIND "${dat}" "; 2 MPI ranks" ranks_at)
if(solver_at EQUAL -1 OR ranks_at EQUAL -1)
  message(FATAL_ERROR "${CASE}.dat does not say it was solved by PETSc on 2 MPI ranks")
endif()
# A contact case says in its .sta how its slave nodes were shared over the ranks.
if(CONTACT)
  file(READ "${WORK}/petsc/${CASE}.sta" sta)
  string(FIND "${sta}" "contact's slave nodes shared over the 2 ranks" share_at)
  if(share_at EQUAL -1)
    message(FATAL_ERROR "${CASE}.sta does not say how contact's slave nodes were shared over the ranks")
  endif()
endif()
