#pragma once
/// Which BLAS the sparse factorisations run on: it decides their speed (Debian's reference
/// BLAS is about ten times slower than OpenBLAS for CHOLMOD's supernodal factorisation).
#include <string>

namespace inpact::solver {

/// "OpenBLAS 0.3.21 ..." when OpenBLAS is loaded, else "reference or unknown BLAS".
std::string blas_description();

/// Threads the BLAS may use under the factorisation (OpenBLAS; no effect on other BLAS).
void set_blas_threads(int n);

}  // namespace inpact::solver
