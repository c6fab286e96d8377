#!/usr/bin/env bash
# A second, newer driver beside the one tools/setup.sh installs: Debian sid in
# a chroot (current Mesa lavapipe, Vulkan loader, validation layers and
# SPIRV-Tools), the run-only build run inside it, the saved run judged here
# with the model against that driver's baseline.
#
#   tools/second-driver.sh prepare          # make or refresh the environment (root; about a minute)
#   tools/second-driver.sh versions         # what it holds: Mesa, loader, layers, spirv-val, device
#   tools/second-driver.sh run OUT [--baseline FILE] [rayspec run options...]
#       OUT/device   the run inside (lavapipe of the environment, --strict-validation: its layers)
#       OUT/spirv-val.txt  every SPIR-V module that run compiled, checked by the environment's spirv-val
#       OUT/judged   that run judged here against FILE (default references/baselines/lavapipe-26.csv)
#       PACK_CASES=DIR before it: DIR's cases run inside and are judged here (rayspec fuzz
#       --generate-only's OUT/cases), instead of the library's
#   tools/second-driver.sh compare RUN_A RUN_B    # rayspec compare of two judged or saved runs
#   tools/second-driver.sh limits [BASELINE]  # the environment's lavapipe: rayspec devices --check-limits
#       judged against BASELINE (default references/baselines/lavapipe-26-limits.csv)
#   RAYSPEC_VARIANT_CASES=DIR RAYSPEC_VARIANT_NAME=NAME RAYSPEC_VARIANT_OUT=OUT tools/second-driver.sh device
#       the device side of case NAME (DIR/NAME.yaml) by the environment's lavapipe, left in OUT as
#       `rayspec run --out` leaves it: rayspec reduce --device-command 'bash tools/second-driver.sh device'
#   tools/second-driver.sh exec PROGRAM [ARGS...]  # a program built here (a reproducer of
#       tools/driver-reproducers.sh) run inside, on the environment's loader and lavapipe; its exit status
#   tools/second-driver.sh generated OUT    # the generator test's modules (tests/glsl_generator_test.cpp:
#       random programs over the whole vocabulary) through the environment's spirv-val: OUT/spirv-val.txt
#
# The environment lives in $RAYSPEC_SECOND_DRIVER (default /var/cache/rayspec/sid).
# `run` exits 77 when it does not exist (ctest counts that as skipped), 1 when
# spirv-val rejects a module or the judged run has an unexpected result, else 0.
set -euo pipefail
cd "$(dirname "$0")/.."
ENV_DIR=${RAYSPEC_SECOND_DRIVER:-/var/cache/rayspec/sid}
MIRROR=${RAYSPEC_SECOND_MIRROR:-http://deb.debian.org/debian}
SUITE=${RAYSPEC_SECOND_SUITE:-sid}
PACKAGES=(mesa-vulkan-drivers libvulkan1 vulkan-validationlayers spirv-tools vulkan-tools)
APT=(apt-get -o Acquire::Check-Valid-Until=false)  # sid's Release file may be past Valid-Until
ICD=/usr/share/vulkan/icd.d/lvp_icd.json
WORK=/opt/rayspec-second-driver  # inside the environment

die() { echo "second-driver: $*" >&2; exit "${2:-2}"; }
ready() { [[ -x "$ENV_DIR/usr/bin/spirv-val" && -f "$ENV_DIR$ICD" ]]; }

# /proc and /dev inside the environment while a command runs there.
mounted=()
mount_inside() {
  for m in proc dev; do
    mountpoint -q "$ENV_DIR/$m" && continue
    mount --bind "/$m" "$ENV_DIR/$m" && mounted+=("$ENV_DIR/$m")
  done
}
unmount_inside() { for m in "${mounted[@]}"; do umount "$m" || true; done; mounted=(); }
inside() { chroot "$ENV_DIR" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root "$@"; }

prepare() {
  [[ $(id -u) -eq 0 ]] || die "prepare needs root (debootstrap, chroot)"
  command -v debootstrap >/dev/null ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends debootstrap
  if [[ ! -x "$ENV_DIR/usr/bin/apt-get" ]]; then
    mkdir -p "$ENV_DIR"
    debootstrap --variant=minbase "$SUITE" "$ENV_DIR" "$MIRROR"
  fi
  trap unmount_inside EXIT
  mount_inside
  inside "${APT[@]}" update
  inside env DEBIAN_FRONTEND=noninteractive "${APT[@]}" install -y --no-install-recommends "${PACKAGES[@]}"
  unmount_inside
  versions
}

versions() {
  ready || die "no environment in $ENV_DIR: run tools/second-driver.sh prepare" 77
  inside dpkg-query -W -f='${Package} ${Version}\n' "${PACKAGES[@]}"
  inside spirv-val --version | head -n 1
}

# Packs the run-only build straight into the environment (unpacked). The
# pack brings its SPIR-V (pack/cache), which the run inside uses; Mesa's own
# shader cache beside it is kept between runs.
install_pack() {
  rm -rf "$ENV_DIR$WORK/pack" "$ENV_DIR$WORK/cache"
  mkdir -p "$ENV_DIR$WORK/pack"
  PACK_STAGE="$ENV_DIR$WORK/pack" bash tools/pack-device.sh >/dev/null
}

# Every module of a folder inside the environment (default: the pack's SPIR-V
# cache, which the run inside used and added to where it compiled more),
# through the environment's spirv-val, as many at once as there are cores;
# OUT/spirv-val.txt names each module it rejects, with why.
check_spirv() {
  local out=$1 modules=${2:-$WORK/pack/cache/spirv} n bad
  n=$(find "$ENV_DIR$modules" -name '*.spv' | wc -l)
  # shellcheck disable=SC2016  # expanded inside the environment
  local each='m=$(spirv-val --target-env vulkan1.2 "$0" 2>&1) || printf "%s: INVALID\n%s\n" "$0" "$m"'
  inside sh -c 'cd "$0" && find . -name "*.spv" -print0 | xargs -0 -r -P "$(nproc)" -n 1 sh -c "$1"' \
    "$modules" "$each" >"$out/spirv-val.txt"
  bad=$(grep -c ': INVALID$' "$out/spirv-val.txt" || true)
  echo "spirv-val $(inside spirv-val --version | head -n 1 | awk '{print $2}'): $((n - bad)) of $n modules valid" |
    tee -a "$out/spirv-val.txt"
  [[ $n -gt 0 && $bad -eq 0 ]]
}

run() {
  [[ $# -ge 1 ]] || die "usage: tools/second-driver.sh run OUT [--baseline FILE] [rayspec run options...]"
  local out baseline=references/baselines/lavapipe-26.csv args=()
  out=$(realpath -m "$1")
  shift
  while [[ $# -gt 0 ]]; do
    case $1 in
      --baseline) baseline=$2; shift 2 ;;
      --baseline=*) baseline=${1#*=}; shift ;;
      *) args+=("$1"); shift ;;
    esac
  done
  ready || { echo "second-driver: SKIPPED: no environment in $ENV_DIR (tools/second-driver.sh prepare makes it)"; exit 77; }
  [[ -x build/rayspec ]] || die "build/rayspec is missing: build the default preset first"
  [[ -f "$baseline" ]] || die "baseline $baseline is missing"
  [[ $(id -u) -eq 0 ]] || die "run needs root (chroot)"
  rm -rf "$out" && mkdir -p "$out"
  install_pack
  trap unmount_inside EXIT
  mount_inside
  echo "== drivers: here, then inside $ENV_DIR"
  ./build/rayspec devices --icd "$ICD" | grep -E '^ +(\[|driver )' || true
  inside sh -c "cd $WORK/pack && LD_LIBRARY_PATH=lib ./rayspec devices --icd $ICD" | grep -E '^ +(\[|driver )' || true
  # Mesa 26.2.6 reads BVH slots it never wrote for inactive instances and
  # primitives (references/driver-reports/lavapipe-inactive-before-active.md):
  # in a worker that ran cases before they hold stale data, where a fresh
  # process reads zeros and only loses the object. A crash there no longer
  # needs these globs (a case that crashes in a reused worker runs again
  # alone), but the verdict itself moves with what ran before: without them
  # (2026-11-27) 15 cases crashed in reused workers and passed or failed alone
  # as the baseline says, and accel/empty-first/no-boxes-blas and
  # no-triangles-blas passed in a worker where alone they fail. So the cases
  # with inactive objects (inactive/*, culling/mask-combinations/*, accel/*:
  # top levels with inactive instances, empty BLASes) run in processes of
  # their own, for a verdict that does not depend on the order of the run.
  # --timeout 300: builtins/launch-largest/2p30 (2^30 ids) takes this llvmpipe
  # about 110 s on a quiet 2-core machine, past the default 120 s under load
  # (2026-12-07: a Timeout twice while other jobs ran).
  echo "== the run inside (device side only; exit 3 is the run-only build's)"
  local rc=0
  inside sh -c 'icd=$1; shift; cd "$0/pack" && RAYSPEC_CACHE_DIR="$0/pack/cache" RAYSPEC_CONFIG_DIR="$0/pack/config" MESA_SHADER_CACHE_DIR="$0/mesa-cache" LD_LIBRARY_PATH=lib \
    ./rayspec run --cases cases --rules spec-rules.yaml --icd "$icd" --strict-validation --timeout 300 \
      --process-per-case-for "inactive/*" --process-per-case-for "culling/mask-combinations/*" \
      --process-per-case-for "accel/*" --out "$0/out" "$@" >"$0/run.log" 2>&1' \
    "$WORK" "$ICD" "${args[@]}" || rc=$?
  tail -n 5 "$ENV_DIR$WORK/run.log"
  # 1: a case failed or crashed inside (judged below, against the baseline);
  # 3: every case NotSupported inside (nothing compared there); 77: the same
  # for a run of one case. 2 and the rest: the run itself could not go on.
  [[ $rc -eq 0 || $rc -eq 1 || $rc -eq 3 || $rc -eq 77 ]] || die "the run inside exited $rc ($ENV_DIR$WORK/run.log)" 1
  mv "$ENV_DIR$WORK/out" "$out/device"
  local spirv_ok=0
  check_spirv "$out" || spirv_ok=1
  unmount_inside
  echo "== judged here against $baseline"
  local judged=0
  # PACK_CASES=DIR (tools/pack-device.sh) ran DIR's cases inside: judge those.
  local cases=()
  [[ -n ${PACK_CASES:-} ]] && cases=(--cases "$PACK_CASES")
  ./build/rayspec run --device-results "$out/device" --out "$out/judged" --baseline "$baseline" \
    "${cases[@]}" "${args[@]}" || judged=$?
  [[ $spirv_ok -eq 0 ]] || { echo "second-driver: spirv-val rejected modules: $out/spirv-val.txt"; exit 1; }
  exit "$judged"
}

# One case's device side, for `rayspec reduce --device-command`: the pack is
# installed on the first call (again when build-device's rayspec is newer),
# each case in a process of its own, the bundle moved to RAYSPEC_VARIANT_OUT.
device() {
  ready || { echo "second-driver: SKIPPED: no environment in $ENV_DIR"; exit 77; }
  [[ $(id -u) -eq 0 ]] || die "device needs root (chroot)"
  [[ -n ${RAYSPEC_VARIANT_CASES:-} && -n ${RAYSPEC_VARIANT_NAME:-} && -n ${RAYSPEC_VARIANT_OUT:-} ]] ||
    die "device needs RAYSPEC_VARIANT_CASES, RAYSPEC_VARIANT_NAME and RAYSPEC_VARIANT_OUT"
  [[ -x "$ENV_DIR$WORK/pack/rayspec" && ! build-device/rayspec -nt "$ENV_DIR$WORK/pack/rayspec" ]] ||
    install_pack
  rm -rf "$ENV_DIR$WORK/variant" && mkdir -p "$ENV_DIR$WORK/variant"
  cp -r "$RAYSPEC_VARIANT_CASES" "$ENV_DIR$WORK/variant/cases"
  trap unmount_inside EXIT
  mount_inside
  local rc=0
  inside sh -c 'cd "$0/pack" && RAYSPEC_CACHE_DIR="$0/pack/cache" RAYSPEC_CONFIG_DIR="$0/pack/config" MESA_SHADER_CACHE_DIR="$0/mesa-cache" LD_LIBRARY_PATH=lib \
    ./rayspec run --cases "$0/variant/cases" --filter "$2" --rules spec-rules.yaml --icd "$1" --strict-validation \
      --process-per-case --out "$0/variant/out"' "$WORK" "$ICD" "$RAYSPEC_VARIANT_NAME" || rc=$?
  unmount_inside
  [[ $rc -eq 0 || $rc -eq 1 || $rc -eq 3 || $rc -eq 77 ]] || die "the run inside exited $rc" 1
  rm -rf "$RAYSPEC_VARIANT_OUT" && mkdir -p "$(dirname "$RAYSPEC_VARIANT_OUT")"
  mv "$ENV_DIR$WORK/variant/out" "$RAYSPEC_VARIANT_OUT"
}

# A program built here run inside (glibc of sid runs what bookworm builds),
# with the environment's lavapipe as its only driver; exits as it does.
exec_inside() {
  [[ $# -ge 1 && -f $1 ]] || die "usage: tools/second-driver.sh exec PROGRAM [ARGS...]"
  ready || { echo "second-driver: SKIPPED: no environment in $ENV_DIR"; exit 77; }
  [[ $(id -u) -eq 0 ]] || die "exec needs root (chroot)"
  rm -rf "$ENV_DIR$WORK/exec" && mkdir -p "$ENV_DIR$WORK/exec"
  cp "$1" "$ENV_DIR$WORK/exec/program"
  shift
  trap unmount_inside EXIT
  mount_inside
  local rc=0
  inside env VK_DRIVER_FILES="$ICD" VK_ICD_FILENAMES="$ICD" "$WORK/exec/program" "$@" || rc=$?
  unmount_inside
  exit $rc
}

# The generator test (build/tests/test_glsl, GeneratedStages.*) writes every
# module it compiled into the environment, whose spirv-val checks them all.
generated() {
  [[ $# -eq 1 ]] || die "usage: tools/second-driver.sh generated OUT"
  ready || die "no environment in $ENV_DIR: run tools/second-driver.sh prepare" 77
  [[ $(id -u) -eq 0 ]] || die "generated needs root (chroot)"
  local out modules="$WORK/generated"
  out=$(realpath -m "$1")
  mkdir -p "$out"
  rm -rf "${ENV_DIR:?}$modules"
  mkdir -p "$ENV_DIR$modules"
  RAYSPEC_GENERATED_SPIRV="$ENV_DIR$modules" ./build/tests/test_glsl --gtest_filter='GeneratedStages.*' \
    >"$out/generator-test.txt" || die "the generator test failed: $out/generator-test.txt" 1
  check_spirv "$out" "$modules" || die "spirv-val rejected generated modules: $out/spirv-val.txt" 1
}

# The environment's lavapipe's ray tracing limits against the specification's
# required ones (rayspec devices --check-limits), judged against BASELINE.
limits() {
  local baseline=${1:-references/baselines/lavapipe-26-limits.csv}
  ready || die "no environment in $ENV_DIR: run tools/second-driver.sh prepare" 77
  [[ -f "$baseline" ]] || die "baseline $baseline is missing"
  [[ $(id -u) -eq 0 ]] || die "limits needs root (chroot)"
  install_pack
  cp "$baseline" "$ENV_DIR$WORK/pack/limits-baseline.csv"
  trap unmount_inside EXIT
  mount_inside
  inside sh -c "cd $WORK/pack && LD_LIBRARY_PATH=lib VK_LAYER_PATH=layer ./rayspec devices --check-limits --icd $ICD --baseline limits-baseline.csv"
}

# One command at a time uses the environment: its pack, work folders and
# mounts are shared, so a second command (CI's second-driver test while a
# reduction runs variants) waits for the first. No lock where it cannot be
# made (no root: every such command stops at its own check).
lock_environment() {
  mkdir -p "$(dirname "$ENV_DIR")" 2>/dev/null || return 0
  { exec 9>>"$ENV_DIR.lock"; } 2>/dev/null || return 0
  flock 9
}

[[ ${1:-} == compare ]] || lock_environment
case ${1:-} in
  prepare) prepare ;;
  limits) shift; limits "$@" ;;
  versions) versions ;;
  run) shift; run "$@" ;;
  compare) shift; exec ./build/rayspec compare "$@" ;;
  generated) shift; generated "$@" ;;
  device) device ;;
  exec) shift; exec_inside "$@" ;;
  *) die "usage: tools/second-driver.sh prepare | versions | run OUT [--baseline FILE] [options] | limits [BASELINE] | compare A B | generated OUT | device (RAYSPEC_VARIANT_*) | exec PROGRAM [ARGS]" ;;
esac
