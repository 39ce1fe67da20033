#include "blas_info.hpp"

#include <dlfcn.h>

#include <cholmod.h>

namespace inpact::solver {

std::string blas_description() {
  // CHOLMOD links the BLAS through Debian's libblas.so.3 alternative; ask the process which
  // implementation answered. OpenBLAS exports openblas_get_config().
  (void)&cholmod_l_start;  // keep CHOLMOD (and so its BLAS) linked in
  using ConfigFn = const char* (*)();
  if (void* sym = dlsym(RTLD_DEFAULT, "openblas_get_config"))
    return std::string("OpenBLAS ") + reinterpret_cast<ConfigFn>(sym)();
  return "reference or unknown BLAS (install libopenblas-dev for a ten times faster factorisation)";
}

}  // namespace inpact::solver
