#!/usr/bin/env bash
# Surface-to-surface contact time per Newton iteration against one element assembly +
# factorisation of the same system (issue 14), per deck; see contact_iteration.py. Writes
# bench/results/contact_iteration.md and prints it.
#
#   bash bench/contact_iteration/run.sh [--base OTHER/apps/inpact] [--runs 5] [--threads N] [--decks ...]
#   env: BUILD (default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build}
source "$root/bench/bench_setup.sh"
bench_build "$root" "$build" apps/inpact
/usr/bin/python3 "$root/bench/contact_iteration/contact_iteration.py" --inpact "$build/apps/inpact" "$@"
cat "$root/bench/results/contact_iteration.md"
