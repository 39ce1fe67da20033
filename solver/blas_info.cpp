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
  // OpenBLAS starts a thread per core when it loads, and those threads spin (sched_yield) for
  // about 0.1 s before they sleep: a process that uses one thread burnt 0.1 s of another core
  // at every start (measured: 1.35 CPUs busy for a 0.3 s run), which GNU parallel, a Slurm array
  // or `study --inpact` pays once per case. One thread: stop them. OpenBLAS starts them again
  // itself (blas_thread_init) should a later call run threaded; OpenBLAS's fork handler does
  // the same before every fork.
  using ShutdownFn = int (*)();
  if (n == 1)
    if (void* sym = dlsym(RTLD_DEFAULT, "blas_thread_shutdown_")) reinterpret_cast<ShutdownFn>(sym)();
  // CHOLMOD's OpenMP loops (clearing maps and supernodes) ask for 4 threads in their clause,
  // which neither omp_set_num_threads nor OMP_NUM_THREADS overrides; allowing no active
  // parallel level runs them on the calling thread. Only clearing: the results are the same.
  // A study case (one per core) spent about 50 ms of a 0.3 s solve waking those threads.
  if (void* sym = dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"))
    reinterpret_cast<SetFn>(sym)(n == 1 ? 0 : 1);
}

}  // namespace inpact::solver
