# The dependency direction apps → io, solver → contact → model ← parser, enforced by the build:
# each library exports only its own folder as an include root (build/include/<folder>/<folder>,
# a link to the source folder), so `#include "solver/x.hpp"` compiles only in a target that
# links solver. tests/layering holds an include against the direction that must fail to build.
function(inpact_export_folder target folder)
  set(root ${PROJECT_BINARY_DIR}/include/${folder})
  file(MAKE_DIRECTORY ${root})
  if(NOT EXISTS ${root}/${folder})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${root}/${folder} SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC ${root})
endfunction()
