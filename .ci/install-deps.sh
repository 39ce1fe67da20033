#!/usr/bin/env bash
# Installs the Debian packages inpact builds, tests and benchmarks with. Runs apt-get (update
# once, then install) only when something is missing, so it is cheap on a prepared machine.
set -euo pipefail

packages=(
  cmake ninja-build ccache g++ pkg-config   # build
  libeigen3-dev                              # dense element algebra
  libsuitesparse-dev libopenblas-dev         # CHOLMOD / UMFPACK on an optimised BLAS
  libhdf5-dev                                # results file
  libssl-dev                                 # SHA-256 of the deck (libcrypto, static)
  libfmt-dev libcli11-dev                    # formatting, command line
  libgtest-dev                               # tests
  python3-h5py python3-meshio python3-paraview xvfb xauth  # results-file reader tests (tests/io)
  parallel                                   # GNU parallel running study shards (tests/decks)
  petsc-dev                                  # iterative solver (--solver petsc; optional at configure)
  openmpi-bin                                # mpirun for distributed runs and their tests (tests/decks mpi.*)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

# CHOLMOD calls the BLAS through Debian's libblas.so.3 alternative: make sure it is OpenBLAS
# (the reference BLAS factorises about ten times slower).
arch_dir=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
if [ -e "/usr/lib/$arch_dir/openblas-pthread/libblas.so.3" ]; then
  current=$(update-alternatives --query "libblas.so.3-$arch_dir" 2>/dev/null | awk '/^Value:/ {print $2}')
  case "$current" in
    *openblas*) ;;
    *) ${sudo:-} update-alternatives --set "libblas.so.3-$arch_dir" "/usr/lib/$arch_dir/openblas-pthread/libblas.so.3" ;;
  esac
fi
