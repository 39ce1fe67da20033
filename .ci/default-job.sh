#!/usr/bin/env bash
# Builds inpact and runs the default job: the README's first command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target inpact
# The default job: the manual's pin-in-hole (general contact, friction, smoothing), results in
# build/jobs/.
build/apps/inpact run decks/pin_in_hole.inp -o build/jobs
