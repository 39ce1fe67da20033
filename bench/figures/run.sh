#!/usr/bin/env bash
# The pictures the README shows, made anew from this checkout (one command):
#   bash bench/figures/run.sh          env: BUILD (default build), RUNS (3)
# - contact_trade.png: error against time per enforcement method (bench/contact_trade),
# - smoothing_trade.png: faceted against smoothed contact per mesh level (bench/smoothing_trade),
# - pin_in_hole_cpress.png: the default job's contact pressure, rendered by ParaView
#   (render_cpress.py under pvpython and xvfb) from the results file.
# The PNGs are committed in bench/figures/; the tables stay in bench/results/ (not kept).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build}
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact
bench_need_python matplotlib h5py numpy paraview
command -v xvfb-run >/dev/null || bench_need xvfb
bench_install_needed

BUILD=$build RUNS=${RUNS:-3} bash "$root/bench/contact_trade/run.sh"
BUILD=$build RUNS=${RUNS:-3} bash "$root/bench/smoothing_trade/run.sh"
cp "$root/bench/results/contact_trade.png" "$root/bench/results/smoothing_trade.png" "$root/bench/figures/"

jobs="$build/figures"
mkdir -p "$jobs"
(cd "$root" && "$build/apps/inpact" run decks/pin_in_hole.inp -o "$jobs" --quiet)
xvfb-run -a pvpython "$root/bench/figures/render_cpress.py" "$jobs/pin_in_hole.xdmf" \
  "$root/bench/figures/pin_in_hole_cpress.png" 2> "$jobs/render.log"
echo "wrote bench/figures/contact_trade.png, smoothing_trade.png, pin_in_hole_cpress.png"
