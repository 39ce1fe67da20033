// Compiled by tests/layering/CMakeLists.txt with PROBE_HEADER set to one library's header and
// linked against another library: it builds only when the include follows the dependency
// direction apps → io, solver → contact → model ← parser (cmake/Layers.cmake).
#include PROBE_HEADER

int inpact_layering_probe() { return 0; }
