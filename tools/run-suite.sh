#!/usr/bin/env bash
# Installs what is missing, builds, and runs every case on lavapipe and on the
# model, printing a summary. Extra arguments go to `rayspec run`.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/phases.sh
phase setup
bash tools/setup.sh
source tools/compiler-cache.sh
phase build-rayspec
cmake --preset default "${launcher[@]}" >/dev/null
# Only the command line: the tests and benchmarks are tools/test.sh's.
cmake --build --preset default -j"$(nproc)" --target rayspec
# Mesa's shader cache beside rayspec's own (tests/CMakeLists.txt: the same place).
export MESA_SHADER_CACHE_DIR="${RAYSPEC_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/rayspec}/mesa-shader-cache"
# The known lavapipe deviations are listed (and shown) as expected results.
phase run
status=0
./build/rayspec run --out build/results --baseline references/baselines/lavapipe.csv "$@" || status=$?
phases_done
exit $status
