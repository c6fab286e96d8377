#!/usr/bin/env bash
# Fuzzes, each for SECONDS (default 60) or RUNS executions (FUZZ_RUNS=N):
#   fuzz_case   the case parser, sweep expansion and plan (fuzz/fuzz_case.cpp),
#               from a corpus made of cases/ and fuzz/case.dict;
#   fuzz_saved  baselines, flakes and skips files, results bundles,
#               summary.json, SPIR-V cache entries, shards to merge and
#               case journals
#               (fuzz/fuzz_saved.cpp), from references/baselines/ and
#               fuzz/seeds/, with the path-escape property.
# TARGETS (default both) picks one: tools/fuzz.sh 600 fuzz_saved.
# Builds the `fuzz` preset (clang, ASan, UBSan) first. Exit 0: no crash,
# hang, leak, sanitizer report or broken property. A finding is left as
# build-fuzz/crash-* (replay: build-fuzz/fuzz/<target> FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("${@:-fuzz_case fuzz_saved}")
read -r -a targets <<<"${targets[*]}"
source tools/compiler-cache.sh
if [ ! -x build-fuzz/fuzz/fuzz_saved ] || [ -n "${FUZZ_REBUILD:-}" ]; then
  cmake --preset fuzz "${launcher[@]}" >/dev/null
fi
cmake --build --preset fuzz -j"$(nproc)" >/dev/null

# Seeds: the case files; for fuzz_saved, each seed file behind its format byte.
seeds() {
  local target=$1 dir=build-fuzz/seed-$1
  rm -rf "$dir" && mkdir -p "$dir"
  if [ "$target" = fuzz_case ]; then
    find cases -name '*.yaml' | while read -r f; do cp "$f" "$dir/$(echo "$f" | tr / _)"; done
  else
    for f in references/baselines/*.csv; do { printf '\000'; cat "$f"; } >"$dir/baseline-$(basename "$f")"; done
    { printf '\001'; printf '^anyhit/\n(a|b)*c$  # comment\nsbt/.*-aabbs\n'; } >"$dir/patterns"
    { printf '\002'; cat fuzz/seeds/results-bundle.bin; } >"$dir/results-bundle"
    { printf '\002'; cat fuzz/seeds/results-numbers.bin; } >"$dir/results-numbers"
    { printf '\003'; cat fuzz/seeds/summary.json; } >"$dir/summary"
    { printf '\004'; printf 'not-a-sum'; printf '\000'; printf '\003\002\043\007'; } >"$dir/spirv-entry"
    { printf '\004'; cat fuzz/seeds/spirv-entry.bin; } >"$dir/spirv-keyed-entry"
    { printf '\005'; cat fuzz/seeds/summary.json; } >"$dir/shard"
    { printf '\006'; cat fuzz/seeds/outcomes.jsonl; } >"$dir/journal"
    { printf '\006'; head -c -40 fuzz/seeds/outcomes.jsonl; } >"$dir/journal-cut"
    printf '\007rayspec run, process 1234, since 2026-12-06 05:00:00 UTC\n' >"$dir/lock"
  fi
  echo "$dir"
}

# Per input: a case may legally expand to 2^24 rays (a 4096 x 4096 grid or
# camera): about 1 GB and 8 s under the sanitizers here, and a sweep input
# parses up to 4 such variants, on a CI machine that runs other tests beside
# it. -timeout and -rss_limit_mb leave room for that; a hang or a runaway
# allocation still fails.
limit=(-max_total_time="$seconds")
[ -n "${FUZZ_RUNS:-}" ] && limit=(-runs="$FUZZ_RUNS")
for target in "${targets[@]}"; do
  seed=$(seeds "$target")
  dict=()
  [ "$target" = fuzz_case ] && dict=(-dict=../fuzz/case.dict)
  mkdir -p "build-fuzz/corpus-$target"
  echo "== $target"
  (cd build-fuzz && ./fuzz/"$target" "corpus-$target" "${seed#build-fuzz/}" "${dict[@]}" "${limit[@]}" -timeout=120 \
    -rss_limit_mb=6144 -max_len=16384 -print_final_stats=1 -jobs=1 -workers=1)
done
