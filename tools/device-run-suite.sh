#!/usr/bin/env bash
# On the GPU machine (the `device` tool): the whole suite in 4 shards with the
# run-only pack (.device/pack.tar.xz, tools/pack-device.sh) and the Vulkan
# loader and libglvnd debs in .gl/, validation layer on; then the device
# bundles packed into OUT/bundles.tar.xz.NN pieces of 15 MiB (the tool brings
# back at most 8 files of 16 MiB). Here, after it:
#   cat OUT/bundles.tar.xz.* | tar -C DIR -xJf -
#   ./build/rayspec run --device-results DIR/run --baseline references/baselines/nvidia.csv --out JUDGED
#   ./build/rayspec mutate DIR/run --out MUTATED
# Usage: bash tools/device-run-suite.sh OUT [extra rayspec run options]
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
cd "$work/p"
./rayspec devices --icd "$icd" | tee "$out/devices.txt" || true
start=$(date +%s)
for i in 1 2 3 4; do
  ./rayspec run --cases cases --rules spec-rules.yaml --icd "$icd" --device NVIDIA --strict-validation \
    --shard "$i/4" --out "$work/shard$i" "$@" > "$out/shard$i.log" 2>&1 &
done
wait || true
echo "4 shards: $(( $(date +%s) - start )) s wall" | tee "$out/timing.txt"
./rayspec merge "$work/shard1" "$work/shard2" "$work/shard3" "$work/shard4" --out "$work/run" > "$out/merge.log" 2>&1 || true
cp "$work/run/summary.txt" "$out/" 2>/dev/null || true
cd "$work"
# The shards hold disjoint cases in one layout: their bundles join into run/.
find shard? -path '*/device/*' -type f \( -name results.json -o -name records.bin -o -name '*.raw' \) -print0 |
  tar --null -T - --transform 's,^shard[0-9],run,' -cf - | xz -T0 -6 | split -b 15M -d - "$out/bundles.tar.xz."
ls -la "$out"
