#!/usr/bin/env bash
# ctest style/fault-seam: test-only hooks stay behind the fault seam
# (docs/layout-and-conventions.md, "The fault seam"). Planted faults live in
# harness/fault/ (and rayspec mutate's generic wrong devices, harness/mutate/,
# build on them); the rest of the product reaches them only through
#   run/fault_seam.h       the run's one entry: refuse, place, arm a fault
#   model/model_faults.h   the model's hook (ModelOptions::faults), read in
#                          the model by model/model_fault_seam.* alone
#   vulkan/vk_fault_hook.h the Vulkan side's hooks (a failing call, obeyed by
#                          vkCall only; a build layout fault, read by
#                          vulkan/scene_builder.cpp only, and the
#                          deferred pipeline fault, read by
#                          vulkan/deferred_operation.cpp only)
# Prints each use outside them; exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."

bad=0
# check WHAT PATTERN ALLOWED...: product files (harness/) naming PATTERN
# outside the ALLOWED path prefixes.
check() {
  local what=$1 pattern=$2
  shift 2
  local allowed=("$@") file line
  while IFS=: read -r file line _; do
    local ok=0 prefix
    for prefix in "${allowed[@]}"; do [[ $file == "$prefix"* ]] && ok=1; done
    if [[ $ok == 0 ]]; then
      echo "check-fault-seam: $file:$line: $what outside the fault seam" >&2
      bad=1
    fi
  done < <(grep -rnE "$pattern" harness --include='*.cpp' --include='*.h' || true)
}

check "a fault/ header" '#include "fault/' harness/fault/ harness/mutate/ harness/run/fault_seam.cpp
check "the Vulkan fault hook" 'injectVkError|injectedVkError|InjectedVkError' \
  harness/vulkan/vk_fault_hook. harness/vulkan/vk_check.h harness/vulkan/device_errors. \
  harness/run/fault_seam.cpp
check "the build layout fault hook" 'injectLayoutFault|injectedLayoutFault' \
  harness/vulkan/vk_fault_hook. harness/vulkan/scene_builder.cpp \
  harness/vulkan/deferred_operation.cpp harness/run/fault_seam.cpp
# Inside the model only its seam reads a knob; model_faults.h defines them
# and model_engine.h carries them in (ModelOptions::faults).
check "the model's fault hook" 'ModelFaults|ModelDeviation|CandidateOrder|[.>]faults\b' \
  harness/model/model_fault_seam. harness/model/model_faults.h harness/model/model_engine.h \
  harness/fault/
check "the planted fault library" 'plantFault|raiseProcessFault|isProcessFault|faultTable\(' \
  harness/fault/ harness/mutate/ harness/run/fault_seam.cpp

[[ $bad == 0 ]] || exit 1
echo "check-fault-seam: test-only hooks used only behind the fault seam"
