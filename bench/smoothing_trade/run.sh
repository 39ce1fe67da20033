#!/usr/bin/env bash
# Smoothing against mesh density (issue 5): the interference fit (levels 1-4, faceted and smoothed,
# surface to surface, direct and penalty) and the pin-in-hole (levels 1-3, faceted and smoothed,
# general contact). Writes bench/results/smoothing_trade.md (printed) and smoothing_trade.png;
# see trade.py.
#
#   bash bench/smoothing_trade/run.sh    env: BUILD (default build), RUNS (3), RUNS_BIG (1),
#                                             LEVELS_2D ("1 2 3 4"), LEVELS_PIN ("1 2 3")
#
# The pin's levels 2 and 3 take about 11 and 27 s of CPU (faceted and smoothed together; run
# once each), the rest a few seconds. The machine is shared: CPU times are the measure, wall times are
# noisy. `trade.py --report-only --work BUILD/smoothing_trade` rewrites the table and the plot.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build}
if [ ! -x "$build/apps/inpact" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DINPACT_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build "$build" --target inpact -j 2
fi
# Debian's matplotlib, h5py and numpy for /usr/bin/python3, and GNU time, installed when missing.
need=()
/usr/bin/python3 -c 'import matplotlib' 2>/dev/null || need+=(python3-matplotlib)
/usr/bin/python3 -c 'import h5py' 2>/dev/null || need+=(python3-h5py)
/usr/bin/python3 -c 'import numpy' 2>/dev/null || need+=(python3-numpy)
[ -x /usr/bin/time ] || need+=(time)
if [ ${#need[@]} -gt 0 ]; then
  sudo_cmd=""; [ "$(id -u)" = 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get install -y "${need[@]}" >/dev/null
fi
# shellcheck disable=SC2086
exec /usr/bin/python3 "$root/bench/smoothing_trade/trade.py" --inpact "$build/apps/inpact" --runs "${RUNS:-3}" \
  --runs-big "${RUNS_BIG:-1}" --levels-2d ${LEVELS_2D:-1 2 3 4} --levels-pin ${LEVELS_PIN:-1 2 3} \
  --work "$build/smoothing_trade"
