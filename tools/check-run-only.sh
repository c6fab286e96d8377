#!/usr/bin/env bash
# The run-only binary (preset `device`, RAYSPEC_WITH_MODEL=OFF and
# RAYSPEC_WITH_OIIO=OFF) must link neither the model's Embree and TBB nor
# OpenImageIO: it goes to machines that only hold a driver. ctest runs this
# as device/run-only-links (tools/test.sh builds the preset first); exit 77
# (skip) when the binary has not been built.
set -euo pipefail
bin=${1:-"$(dirname "$0")/../build-device/rayspec"}
if [ ! -x "$bin" ]; then
  echo "no $bin: build it with: cmake --preset device && cmake --build --preset device"
  exit 77
fi
libs=$(ldd "$bin")
echo "$libs"
if grep -Ei 'embree|tbb|OpenImageIO|OpenEXR' <<<"$libs"; then
  echo "FAIL: $bin links the libraries above"
  exit 1
fi
# Nothing of Embree linked in statically either (its API is rtc*).
if nm -C "$bin" | grep -Eq ' (T|U) rtc[A-Z]'; then
  echo "FAIL: $bin holds Embree symbols"
  exit 1
fi
echo "OK: $bin links neither Embree, TBB nor OpenImageIO"
