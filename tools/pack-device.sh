#!/usr/bin/env bash
# Builds the run-only binary (no OpenImageIO, no tests) and packs it with the
# shared libraries and the validation layer a bare GPU machine lacks, into
# .device/pack.tar.xz (ignored by git). On that machine:
#   tar -C /tmp/p -xJf .device/pack.tar.xz
#   LD_LIBRARY_PATH=/tmp/p/lib VK_LAYER_PATH=/tmp/p/layer /tmp/p/rayspec run --cases cases
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset device >/dev/null
cmake --build --preset device -j"$(nproc)"
stage=$(mktemp -d)
mkdir -p "$stage/lib" "$stage/layer" .device
cp build-device/rayspec "$stage/" && strip "$stage/rayspec"
for lib in $(ldd build-device/rayspec | awk '/=>/ {print $3}' | grep -E 'embree|tbb|yaml-cpp'); do cp -L "$lib" "$stage/lib/"; done
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
cp /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$stage/layer/"
sed 's#"library_path": "libVkLayer_khronos_validation.so"#"library_path": "./libVkLayer_khronos_validation.so"#' \
  "$layer_json" > "$stage/layer/VkLayer_khronos_validation.json"
tar -C "$stage" -cf - . | xz -T0 -4 > .device/pack.tar.xz
rm -rf "$stage"
ls -la .device/pack.tar.xz
