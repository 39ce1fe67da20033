#pragma once
/// Which BLAS the sparse factorisations run on: it decides their speed (Debian's reference
/// BLAS is about ten times slower than OpenBLAS for CHOLMOD's supernodal factorisation).
#include <string>

namespace inpact::solver {

/// "OpenBLAS 0.3.21 ..." when OpenBLAS is loaded, else "reference or unknown BLAS".
std::string blas_description();

/// Threads the factorisation may use: the BLAS's (OpenBLAS; no effect on other BLAS) and,
/// for n = 1, CHOLMOD's own OpenMP loops, which otherwise start 4 threads whatever
/// OMP_NUM_THREADS says (a num_threads(4) clause) and wake them for every supernode. For n = 1
/// also stops OpenBLAS's idle threads, which spin for a while after the library loads.
void set_blas_threads(int n);

}  // namespace inpact::solver
