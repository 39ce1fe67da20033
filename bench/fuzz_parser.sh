#!/usr/bin/env bash
# Fuzzes the deck reader (tests/fuzz/fuzz_read_deck.cpp) with libFuzzer for a bounded time.
#
#   bench/fuzz_parser.sh [SECONDS]        # default 60
#   MAX_LEN=16384 TIMEOUT=10 RSS_MB=2048 BUILD_DIR=build-fuzz bench/fuzz_parser.sh 600
#
# Configures a clang build folder with INPACT_FUZZ=ON (ASan + UBSan + coverage), builds only the
# fuzz target, seeds it with the project's decks and runs it. The working corpus is kept in the
# build folder, so a second run continues where the first stopped. Exit status: 0 when nothing
# was found; 1 when libFuzzer left a crash/timeout/oom/leak artifact, which is listed with the
# command that replays it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
build="${BUILD_DIR:-$root/build-fuzz}"
max_len="${MAX_LEN:-16384}"
timeout="${TIMEOUT:-10}"
rss_mb="${RSS_MB:-2048}"

# clang and its libFuzzer runtime (Debian: clang + libclang-rt-14-dev).
need=()
command -v clang >/dev/null && command -v clang++ >/dev/null || need+=(clang)
if command -v clang++ >/dev/null; then
  rt="$(clang++ -print-file-name=libclang_rt.fuzzer-x86_64.a 2>/dev/null || true)"
  [[ -f "$rt" ]] || rt="$(find /usr/lib/llvm-*/lib/clang -name 'libclang_rt.fuzzer*.a' 2>/dev/null | head -n1)"
  [[ -n "$rt" && -f "$rt" ]] || need+=(libclang-rt-14-dev)
fi
if ((${#need[@]})); then
  echo "installing ${need[*]}" >&2
  sudo=""; [[ $(id -u) -eq 0 ]] || sudo="sudo"
  $sudo apt-get update -qq && $sudo apt-get install -y -qq "${need[@]}"
fi

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  # -O1 -g without NDEBUG: fast enough to fuzz, asserts on, readable stack traces.
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DINPACT_FUZZ=ON -DBUILD_TESTING=OFF \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g"
fi
cmake --build "$build" --target fuzz_read_deck -j "${JOBS:-2}"

# Seeds: every deck in the project, the fuzz seeds and a small generated cube.
seeds="$build/fuzz-seeds"
corpus="$build/fuzz-corpus"
artifacts="$build/fuzz-artifacts"
mkdir -p "$seeds" "$corpus" "$artifacts"
while IFS= read -r -d '' f; do
  rel="${f#"$root"/}"
  cp "$f" "$seeds/${rel//\//_}"
done < <(find "$root/decks" "$root/tests/fuzz/seeds" -name '*.inp' -size -256k -print0 2>/dev/null)
python3 "$root/bench/gen_cube_deck.py" 2 "$seeds/generated_cube_2.inp"
echo "seeds: $(ls "$seeds" | wc -l) files; corpus: $(ls "$corpus" | wc -l) files" >&2

before="$(ls "$artifacts" | wc -l)"
status=0
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
"$build/tests/fuzz/fuzz_read_deck" \
  -max_total_time="$seconds" -max_len="$max_len" -timeout="$timeout" -rss_limit_mb="$rss_mb" \
  -dict="$root/tests/fuzz/inp.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
  "$corpus" "$seeds" || status=$?
after="$(ls "$artifacts" | wc -l)"

if ((status == 72 && after == before)); then  # libFuzzer's code for an interrupt (Ctrl-C)
  echo "fuzz_parser: interrupted; nothing found so far" >&2
  exit 130
fi
if ((status != 0 || after > before)); then
  echo >&2
  echo "fuzz_parser: libFuzzer stopped with status $status; artifacts in $artifacts:" >&2
  ls -t "$artifacts" | head -n 10 >&2
  newest="$(ls -t "$artifacts" | head -n1)"
  [[ -n "$newest" ]] && echo "replay: $build/tests/fuzz/fuzz_read_deck $artifacts/$newest" >&2
  exit 1
fi
echo "fuzz_parser: no crash, hang or leak in ${seconds}s" >&2
