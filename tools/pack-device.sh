#!/usr/bin/env bash
# Builds the run-only binary (preset `device`: no model, so no Embree or TBB;
# no OpenImageIO; no tests) and packs it with the cases, the rule catalog,
# the shared libraries a bare GPU machine may lack (yaml-cpp, libcrypto; ldd
# decides) and the validation layer, and the SPIR-V of every stage
# (cache/spirv: KEY.spv beside KEY.sum, spirv/spirv_cache.h) with the key of
# its sums (config/spirv-cache.key, spirv/cache_secret.h), into
# .device/pack.tar.xz (ignored by git). There:
#   mkdir -p /tmp/p && tar -C /tmp/p -xJf pack.tar.xz && cd /tmp/p
#   RAYSPEC_CONFIG_DIR=config LD_LIBRARY_PATH=lib VK_LAYER_PATH=layer ./rayspec run --cases cases \
#     --rules spec-rules.yaml --cache-dir cache --out DIR
# It runs the device side only; bring DIR back and judge it where the full
# build is: rayspec run --device-results DIR --out JUDGED (README.md,
# docs/driver-only-machine.md).
# PACK_CASES=DIR packs DIR's cases instead of cases/ (see below).
# PACK_STAGE=DIR (an empty or missing folder) leaves the pack unpacked there
# instead (tools/second-driver.sh: no compression for a copy on this machine).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/compiler-cache.sh
cmake --preset device "${launcher[@]}" >/dev/null
cmake --build --preset device -j"$(nproc)"
bash tools/check-run-only.sh build-device/rayspec >/dev/null
stage=${PACK_STAGE:-$(mktemp -d)}
mkdir -p "$stage/lib" "$stage/layer" .device
cp build-device/rayspec "$stage/" && strip "$stage/rayspec"
# The cases as they are here: a saved bundle is judged only against the same case text.
# PACK_CASES=DIR packs that folder as the cases instead of the library (the
# cases `rayspec fuzz --generate-only` wrote: OUT/cases).
cp -r "${PACK_CASES:-cases}" "$stage/cases"
cp references/spec-rules.yaml "$stage/"
# The SPIR-V of every generated stage, compiled here by this very binary (the
# cache key is the GLSL text and the compile options, not the machine), so
# that the GPU machine compiles no GLSL. `rayspec compile` runs nothing: no
# device, no trace (a run of the suite on lavapipe did this before, compiling
# every pipeline with LLVM on the way: 11 minutes on a bare 2-core machine).
# The sums are keyed with a key made for the pack alone (config/, beside the
# cache, not in it), so the user's own key (~/.config/rayspec) never leaves
# this machine; RAYSPEC_CONFIG_DIR=config names it there. A run there without
# it finds every module a miss and compiles it again (the binary has glslang).
RAYSPEC_CONFIG_DIR="$stage/config" build-device/rayspec compile --cases "$stage/cases" --cache-dir "$stage/cache"
# The driver pipeline caches a GPU run brought back (tools/device-run-suite.sh:
# OUT/pipelines, kept in .device/pipelines): a driver finds its own file
# (named by device and driver version, its header checked) and creates its
# pipelines from it instead of compiling them (on an H200, 80 of the 108 s
# of a cold run's cases); any other driver ignores them.
if compgen -G ".device/pipelines/*.bin" >/dev/null; then
  mkdir -p "$stage/cache/pipelines" && cp .device/pipelines/*.bin "$stage/cache/pipelines/"
fi
for lib in $(ldd build-device/rayspec | awk '/=>/ {print $3}' | grep -E 'yaml-cpp|libcrypto'); do cp -L "$lib" "$stage/lib/"; done
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
cp /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$stage/layer/"
sed 's#"library_path": "libVkLayer_khronos_validation.so"#"library_path": "./libVkLayer_khronos_validation.so"#' \
  "$layer_json" > "$stage/layer/VkLayer_khronos_validation.json"
if [ -n "${PACK_STAGE:-}" ]; then
  echo "the pack, unpacked: $stage"
  exit 0
fi
tar -C "$stage" -cf - . | xz -T0 -4 > .device/pack.tar.xz
(cd "$stage" && for f in . * lib/* layer/*; do du -sh "$f"; done)
rm -rf "$stage"
ls -la .device/pack.tar.xz
