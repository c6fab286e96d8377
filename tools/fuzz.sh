#!/usr/bin/env bash
# Fuzzes the case parser, sweep expansion and plan (fuzz/fuzz_case.cpp) for
# SECONDS (default 60) or RUNS executions (FUZZ_RUNS=N), starting from a
# corpus made of cases/. Builds the `fuzz` preset (clang, ASan, UBSan) first.
# Exit 0: no crash, hang, leak or sanitizer report. A finding is left as
# build-fuzz/crash-* (replay: build-fuzz/fuzz/fuzz_case FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
if [ ! -x build-fuzz/fuzz/fuzz_case ] || [ -n "${FUZZ_REBUILD:-}" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake --preset fuzz "${launcher[@]}" >/dev/null
fi
cmake --build --preset fuzz -j"$(nproc)" >/dev/null
seed=build-fuzz/corpus-seed
rm -rf "$seed" && mkdir -p "$seed" build-fuzz/corpus
find cases -name '*.yaml' | while read -r f; do cp "$f" "$seed/$(echo "$f" | tr / _)"; done
limit=(-max_total_time="$seconds")
[ -n "${FUZZ_RUNS:-}" ] && limit=(-runs="$FUZZ_RUNS")
cd build-fuzz
exec ./fuzz/fuzz_case corpus corpus-seed -dict=../fuzz/case.dict "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
  -max_len=16384 -print_final_stats=1 -jobs=1 -workers=1
