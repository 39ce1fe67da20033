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
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact
bench_need_python matplotlib h5py numpy
[ -x /usr/bin/time ] || bench_need time
bench_install_needed
# shellcheck disable=SC2086
exec /usr/bin/python3 "$root/bench/smoothing_trade/trade.py" --inpact "$build/apps/inpact" --runs "${RUNS:-3}" \
  --runs-big "${RUNS_BIG:-1}" --levels-2d ${LEVELS_2D:-1 2 3 4} --levels-pin ${LEVELS_PIN:-1 2 3} \
  --work "$build/smoothing_trade"
