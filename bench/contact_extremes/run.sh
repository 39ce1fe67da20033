#!/usr/bin/env bash
# Contact at the extremes (issue 4): penalty scale factors 1e-6 … 1e8, modulus contrast 1e-6 … 1e6,
# element-size contrast 1e3, ν = 0.4999, initial gaps 0 / ±1e-12 of the model size, mm against m,
# bodies held only by contact (driven by a force; stabilised).
# Every case is checked against its analytic answer and classified right / stopped / WRONG.
# Writes bench/results/contact_extremes.md (printed) and .json; see extremes.py.
#
#   bash bench/contact_extremes/run.sh [--groups penalty modulus size nu gap units start]
#        [--discretization "SURFACE TO SURFACE" | GENERAL] [--compare bench/results/OLD.json]
#   env: BUILD (default build)
#
# GENERAL: general contact (*CONTACT INCLUSIONS, ALL EXTERIOR) instead of the pair (Hertz cases
# not run). --compare: a section of what changed against an earlier run's .json.
# Each run is a small deck (well under a second); each set takes about a minute.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build}
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact
bench_need_python h5py numpy
bench_install_needed
exec /usr/bin/python3 "$root/bench/contact_extremes/extremes.py" --inpact "$build/apps/inpact" \
  --work "$build/contact_extremes" "$@"
