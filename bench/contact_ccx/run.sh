#!/usr/bin/env bash
# inpact against CalculiX on the same contact problems in CalculiX's dialect (issue 4): Hertz line
# contact and the interference fit as one-element-thick C3D8 slabs, linear penalty; error, Newton
# iterations, wall and CPU time side by side, and inpact's time per Newton iteration against one
# assembly + factorisation (bench/solver_floor). Writes bench/results/contact_ccx.md (printed) and
# .json; see ccx_bench.py.
#
#   bash bench/contact_ccx/run.sh [--levels 1 2] [--runs 3] [--discretization "NODE TO SURFACE" "SURFACE TO SURFACE"]
#   env: BUILD (default build)
#
# ccx runs take 4 (level 1) to 15 s (level 2) of CPU each; both discretisations take about ten minutes.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build}
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact bench/solver_floor
command -v ccx >/dev/null || bench_need calculix-ccx  # Debian's CalculiX (2.20 on bookworm)
bench_need_python h5py numpy
bench_install_needed
exec /usr/bin/python3 "$root/bench/contact_ccx/ccx_bench.py" --inpact "$build/apps/inpact" \
  --floor "$build/bench/solver_floor" --work "$build/contact_ccx" "$@"
