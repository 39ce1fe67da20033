#!/usr/bin/env bash
# Contact speed/accuracy trade: the Hertz and interference-fit decks of decks/contact_verification/
# at three mesh levels, for direct, penalty (stiffness scale factors 0.01 … 100), nonlinear
# penalty and augmented Lagrange (relative penetration tolerances 1e-2 … 1e-5), node to surface
# and surface to surface. Writes
# bench/results/contact_trade.md (printed) and contact_trade.png; see trade.py.
#
#   bash bench/contact_trade/run.sh [--discretizations NTS STS] [--decks hertz_2d interference_2d]
#   env: BUILD (default build-cver), RUNS (3), LEVELS ("1 2 3")
#
# The machine is shared: other work adds noise to the wall times (medians of RUNS runs).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build-cver}
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact
bench_need_python matplotlib h5py numpy
bench_install_needed
# shellcheck disable=SC2086
exec /usr/bin/python3 "$root/bench/contact_trade/trade.py" --inpact "$build/apps/inpact" --runs "${RUNS:-3}" \
  --levels ${LEVELS:-1 2 3} --work "$build/contact_trade" "$@"
