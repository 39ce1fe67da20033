#!/bin/sh
# Runs the verification suite (tests/verification) and collects its measured figures
# (errors, observed convergence rates, Newton iterations, balance of reactions) and the wall
# time into bench/results/verification.txt.
#   bench/verification/run_verification.sh [BUILD_DIR]   (default: build-verif)
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build-verif}
out=$here/bench/results/verification.txt
mkdir -p "$(dirname "$out")"
cd "$build/tests"
start=$(date +%s.%N)
./test_verification > verification.log 2>&1 || status=$?
end=$(date +%s.%N)
{
  echo "# inpact verification suite, $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores"
  grep '^\[verification\]' verification.log
  grep -E '^\[  (PASSED|FAILED) ' verification.log
  echo "wall time: $(echo "$end - $start" | bc) s"
} > "$out"
cat "$out"
exit ${status:-0}
