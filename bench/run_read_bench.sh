#!/usr/bin/env bash
# Reading benchmark: generates structured C3D8 cube decks (about 100k, 300k and 1M elements),
# times read_deck on each (median of RUNS runs, one process per deck so that the peak RSS is that
# deck's) and writes bench/results/read_deck.md (git-ignored), which it also prints.
#
#   bench/run_read_bench.sh [RUNS]          # default 3
#   BUILD_DIR=... EDGES="47 67 100" bench/run_read_bench.sh
#
# Goal (issue): 1M C3D8 elements read in under 3 s and under 1 GB.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build-bench}"
runs="${1:-3}"
edges="${EDGES:-47 67 100}"   # 47^3 = 103,823; 67^3 = 300,763; 100^3 = 1,000,000 elements

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF
fi
cmake --build "$build" --target read_deck_bench -j "${JOBS:-2}"

decks="$build/bench-decks"
mkdir -p "$decks" "$root/bench/results"
gen="$root/bench/gen_cube_deck.py"
out="$root/bench/results/read_deck.md"
{
  echo "# read_deck: structured C3D8 cube decks"
  echo
  echo "$(date -u +%Y-%m-%dT%H:%MZ), $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')$(git -C "$root" diff --quiet 2>/dev/null || echo '+local changes'), $(uname -m), $(nproc) cores, median of $runs runs. Goal: 1M elements in < 3 s and < 1 GB."
  echo
  echo "| elements | nodes | deck MB | read median s | min s | max s | peak RSS MB | MB/s |"
  echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$out"
for n in $edges; do
  deck="$decks/cube_$n.inp"
  # Regenerate when the generator is newer than the deck.
  if [[ ! -s "$deck" || "$gen" -nt "$deck" ]]; then
    echo "generating $deck" >&2
    python3 "$gen" "$n" "$deck.tmp" && mv "$deck.tmp" "$deck"
  fi
  read -r ne nn med mn mx rss mb < <("$build/bench/read_deck_bench" "$deck" "$runs")
  rate=$(awk -v mb="$mb" -v s="$med" 'BEGIN { printf "%.0f", (s > 0 ? mb / s : 0) }')
  echo "| $ne | $nn | $mb | $med | $mn | $mx | $rss | $rate |" >> "$out"
done
cat "$out"
