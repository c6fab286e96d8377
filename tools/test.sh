#!/usr/bin/env bash
# Installs what is missing, builds, and runs ctest: the unit tests, one test
# per case family (device against model, validation layer on), the command
# line, the reports and the style checks. --full adds the full tier (ctest
# label `full`: the suite again through feature paths, motions and
# permutations, one case at a time, every generic wrong device, the second
# driver and the fuzzers); CI runs that. Other arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
if [[ "${1:-}" == --full ]]; then
  full=1
  shift
fi
source tools/phases.sh
phase setup
bash tools/setup.sh
source tools/compiler-cache.sh
phase build-default
cmake --preset default "${launcher[@]}" >/dev/null
cmake --build --preset default -j"$(nproc)"
if [[ $full -eq 1 ]]; then
  phase build-fuzz
  # The fuzz targets (clang, ASan, UBSan), which ctest's fuzz/inputs runs.
  cmake --preset fuzz "${launcher[@]}" >/dev/null
  cmake --build --preset fuzz -j"$(nproc)"
fi
phase build-device
# The run-only binary (no model, no Embree, no OpenImageIO), which ctest's
# device/run-only-links checks with ldd and cli/device-results runs.
cmake --preset device "${launcher[@]}" >/dev/null
cmake --build --preset device -j"$(nproc)"
phase ctest
tier=(-LE full)
[[ $full -eq 1 ]] && tier=()
status=0
ctest --preset default -j"$(nproc)" "${tier[@]}" "$@" || status=$?
phases_done
exit $status
