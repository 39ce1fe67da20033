#!/usr/bin/env bash
# Builds inpact and runs the default job: the README's first command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target inpact
# The solver is not built yet: the default job is the datacheck of the default deck.
build/apps/inpact check decks/punch_on_block.inp
