# PETSc is optional: found (pkg-config `PETSc`, Debian's petsc-dev, with Open MPI) → the
# iterative solver path `inpact run --solver petsc` is built as a module, libinpact_petsc.so,
# that the solver loads only when a run chooses it. Linking PETSc into the executable would
# load its 100 shared libraries (MPI, hypre, MUMPS, X11, ...) at every process start: 44 ms
# against the 1 ms a study case starts in. INPACT_PETSC=OFF builds without it even when found.
set(INPACT_PETSC AUTO CACHE STRING "Build the PETSc solver path: AUTO (when found), ON (required), OFF")
set(INPACT_HAVE_PETSC OFF)
if(NOT INPACT_PETSC STREQUAL "OFF")
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  endif()
  if(PETSC_FOUND)
    find_package(MPI COMPONENTS C)
  endif()
  if(PETSC_FOUND AND MPI_C_FOUND)
    set(INPACT_HAVE_PETSC ON)
    message(STATUS "PETSc ${PETSC_VERSION}: inpact run --solver petsc is available")
  elseif(INPACT_PETSC STREQUAL "ON")
    message(FATAL_ERROR "INPACT_PETSC=ON but PETSc (pkg-config PETSc) with MPI was not found")
  else()
    message(STATUS "PETSc not found: inpact is built without --solver petsc")
  endif()
endif()
