#!/usr/bin/env bash
# Installs what is missing, builds, and runs the unit tests and one test per
# case file (device against model, validation layer on) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default -j"$(nproc)"
ctest --preset default -j"$(nproc)" "$@"
