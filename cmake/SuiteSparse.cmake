# Debian's SuiteSparse 5.x ships no CMake package: find the libraries by hand and expose one
# imported target per component. OpenBLAS under CHOLMOD is chosen by Debian's alternatives
# system (libopenblas-dev), which the set-up script installs.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
foreach(component cholmod umfpack suitesparseconfig)
  string(TOUPPER ${component} upper)
  find_library(${upper}_LIBRARY ${component} REQUIRED)
  add_library(SuiteSparse::${component} UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::${component} PROPERTIES
    IMPORTED_LOCATION "${${upper}_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}")
endforeach()
