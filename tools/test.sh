#!/usr/bin/env bash
# Installs what is missing, builds, and runs the unit tests and one test per
# case family (device against model, validation layer on) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/phases.sh
phase setup
bash tools/setup.sh
source tools/compiler-cache.sh
phase build-default
cmake --preset default "${launcher[@]}" >/dev/null
cmake --build --preset default -j"$(nproc)"
phase build-fuzz
# The fuzz targets (clang, ASan, UBSan), which ctest's fuzz/inputs runs.
cmake --preset fuzz "${launcher[@]}" >/dev/null
cmake --build --preset fuzz -j"$(nproc)"
phase build-device
# The run-only binary (no model, no Embree, no OpenImageIO), which ctest's
# device/run-only-links checks with ldd and cli/device-results runs.
cmake --preset device "${launcher[@]}" >/dev/null
cmake --build --preset device -j"$(nproc)"
phase ctest
status=0
ctest --preset default -j"$(nproc)" "$@" || status=$?
phases_done
exit $status
