#!/usr/bin/env bash
# On the GPU machine (the `device` tool): the whole suite in one run with the
# run-only pack (.device/pack.tar.xz, tools/pack-device.sh) and the Vulkan
# loader and libglvnd debs in .gl/, validation layer on; then the device
# bundles packed into OUT/bundles.tar.xz.NN pieces of 15 MiB (the tool brings
# back at most 8 files of 16 MiB). Here, after it:
#   cat OUT/bundles.tar.xz.* | tar -C DIR -xJf -
#   ./build/rayspec run --device-results DIR/run --baseline references/baselines/nvidia.csv --out JUDGED
#   ./build/rayspec mutate DIR/run --out MUTATED
#   mkdir -p .device/pipelines && cp OUT/pipelines/*.bin .device/pipelines/   # the next pack carries them
# RAYSPEC_DEVICE_NO_LAYER=FILTER also runs the cases FILTER names without the
# validation layer (for extensions newer than the carried layer, such as
# position fetch: see references/baselines/nvidia.csv), bundled apart in
# OUT/no-layer.tar.xz (judge DIR/no-layer the same way).
# Usage: [RAYSPEC_DEVICE_RUNS=2] [RAYSPEC_DEVICE_REFERENCE=1] [RAYSPEC_DEVICE_NO_LAYER=FILTER]
#        bash tools/device-run-suite.sh OUT [run options]
set -euo pipefail
out=$1
shift
root=$(cd "$(dirname "$0")/.." && pwd)
work=/tmp/rayspec-device
rm -rf "$work" && mkdir -p "$work/p" "$work/gl"
tar -C "$work/p" -xJf "$root/.device/pack.tar.xz"
for deb in "$root"/.gl/*.deb; do dpkg-deb -x "$deb" "$work/gl"; done
icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
export LD_LIBRARY_PATH="$work/p/lib:$work/gl/usr/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}"
export VK_LAYER_PATH="$work/p/layer"
export RAYSPEC_CONFIG_DIR="$work/p/config"  # the key of the pack's SPIR-V cache (tools/pack-device.sh)
cd "$work/p"
# The device and its limits against the specification's required ones (exit 1 on a violation: kept going).
./rayspec devices --check-limits --icd "$icd" | tee "$out/devices.txt" || true
# One run, a worker pair per core (-j: one per core, at most 16), the SPIR-V
# the pack brought (cache/spirv) and the pipeline caches the run makes;
# RAYSPEC_DEVICE_RUNS=2 runs it again, warm (the bundles are the last run's).
for n in $(seq 1 "${RAYSPEC_DEVICE_RUNS:-1}"); do
  rm -rf "$work/run"
  start=$(date +%s%N)
  ./rayspec run --cases cases --rules spec-rules.yaml --icd "$icd" --device NVIDIA --strict-validation \
    --cache-dir "$work/p/cache" --out "$work/run" "$@" > "$out/run$n.log" 2>&1 || true
  echo "run $n, whole suite: $(( ($(date +%s%N) - start) / 1000000 )) ms wall" | tee -a "$out/timing.txt"
  cp "$work/run/summary.txt" "$out/summary$n.txt" 2>/dev/null || true
done
# RAYSPEC_DEVICE_REFERENCE=1: the same run with a process per case side
# (--process-per-case, the way runs went before workers), timed beside it.
if [[ -n "${RAYSPEC_DEVICE_REFERENCE:-}" ]]; then
  start=$(date +%s%N)
  ./rayspec run --cases cases --rules spec-rules.yaml --icd "$icd" --device NVIDIA --strict-validation \
    --cache-dir "$work/p/cache" --process-per-case --out "$work/reference" "$@" > "$out/reference.log" 2>&1 || true
  echo "process per case, whole suite: $(( ($(date +%s%N) - start) / 1000000 )) ms wall" | tee -a "$out/timing.txt"
fi
if [[ -n "${RAYSPEC_DEVICE_NO_LAYER:-}" ]]; then
  ./rayspec run --cases cases --rules spec-rules.yaml --icd "$icd" --device NVIDIA --no-validation \
    --cache-dir "$work/p/cache" --filter "$RAYSPEC_DEVICE_NO_LAYER" --out "$work/no-layer" \
    > "$out/no-layer.log" 2>&1 || true
  (cd "$work" && find no-layer -path '*/device/*' -type f -print0 |
    tar --null -T - -cf - | xz -T0 -6 > "$out/no-layer.tar.xz")
fi
cp "$work/run/summary.txt" "$out/" 2>/dev/null || true
# The driver's pipeline cache the runs made (cache/pipelines: one file per
# device and driver version), for the next pack to carry: put OUT/pipelines/
# into .device/pipelines/ here, and tools/pack-device.sh packs it.
mkdir -p "$out/pipelines"
cp "$work/p/cache/pipelines/"*.bin "$out/pipelines/" 2>/dev/null || true
cd "$work"
# The device bundles of the run.
find run -path '*/device/*' -type f \( -name results.json -o -name records.bin -o -name '*.raw' \) -print0 |
  tar --null -T - -cf - | xz -T0 -6 | split -b 15M -d - "$out/bundles.tar.xz."
ls -la "$out"
