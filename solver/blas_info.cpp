#include "blas_info.hpp"

#include <dlfcn.h>

#include <cholmod.h>

namespace inpact::solver {

std::string blas_description() {
  // CHOLMOD links the BLAS through Debian's libblas.so.3 alternative; ask the process which
  // implementation answered. OpenBLAS exports openblas_get_config().
  // Starting CHOLMOD loads the BLAS it was linked against (and keeps the link from being
  // dropped as unneeded), so the answer is about the library the factorisation will use.
  cholmod_common common;
  cholmod_l_start(&common);
  cholmod_l_finish(&common);
  using ConfigFn = const char* (*)();
  if (void* sym = dlsym(RTLD_DEFAULT, "openblas_get_config"))
    return reinterpret_cast<ConfigFn>(sym)();  // "OpenBLAS 0.3.21 ... MAX_THREADS=64"
  return "reference or unknown BLAS (install libopenblas-dev for a ten times faster factorisation)";
}

void set_blas_threads(int n) {
  using SetFn = void (*)(int);
  if (void* sym = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetFn>(sym)(n);
}

}  // namespace inpact::solver
