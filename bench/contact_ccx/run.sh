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
if [ ! -x "$build/apps/inpact" ] || [ ! -x "$build/bench/solver_floor" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DINPACT_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build "$build" --target inpact solver_floor -j 2
fi
command -v ccx >/dev/null || { echo "ccx (CalculiX) is not installed: apt-get install calculix-ccx" >&2; exit 2; }
need=()
/usr/bin/python3 -c 'import h5py' 2>/dev/null || need+=(python3-h5py)
/usr/bin/python3 -c 'import numpy' 2>/dev/null || need+=(python3-numpy)
if [ ${#need[@]} -gt 0 ]; then
  sudo_cmd=""; [ "$(id -u)" = 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get install -y "${need[@]}" >/dev/null
fi
exec /usr/bin/python3 "$root/bench/contact_ccx/ccx_bench.py" --inpact "$build/apps/inpact" \
  --floor "$build/bench/solver_floor" --work "$build/contact_ccx" "$@"
