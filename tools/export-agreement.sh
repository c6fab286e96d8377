#!/usr/bin/env bash
# The C exports of the library (docs/export.md) against rayspec's verdicts on
# one driver: every case file (a sweep's first variant) exported with
# build/rayspec export; each refusal counted by its reason; each export built
# with cc and run on DEVICE, its outcome held to the verdict the driver's
# baseline expects (exit 0 where the case passes, 0 with a "QualityWarning:"
# line for a QualityWarning, 1 Fail, 77 NotSupported; a QualityWarning the
# baseline does not list held to rayspec run's verdict on the case).
#   bash tools/export-agreement.sh OUT [DEVICE] [BASELINE]
# (DEVICE default llvmpipe, BASELINE default references/baselines/lavapipe.csv;
# OUT/summary.txt: the counts per family, the refusals by reason, every
# disagreement.) JOBS (default 2) cases at a time; RAYSPEC: the binary (build/rayspec).
# FORMAT=amber: the Amber exports (repro.amber) instead, each run with $AMBER
# (amber -v 1.2 -d: no validation layer) where AMBER names the binary, and
# only counted where it does not. PREBUILT=1: OUT holds an earlier run's
# exports and builds (made here, carried to a GPU machine without a compiler):
# each built reproducer is only run on DEVICE, against BASELINE.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: export-agreement.sh OUT [DEVICE] [BASELINE]}
device=${2:-llvmpipe}
baseline=${3:-references/baselines/lavapipe.csv}
rayspec=${RAYSPEC:-build/rayspec}
jobs=${JOBS:-2}
mkdir -p "$out"
format=${FORMAT:-c}
amber=${AMBER:-}
export out device baseline rayspec format amber
# One case file: exported, built and run; one line "family, verdict, case, detail" printed.
one_case() {
  local file=$1 rel dir family rc reason name want got status verdict how=""
  rel=${file#cases/}
  dir="$out/${rel%.yaml}"
  family=${rel%%/*}
  mkdir -p "$dir"
  if [[ -n ${PREBUILT:-} ]]; then
    # The exports and their builds of an earlier run (OUT carried to a machine
    # without rayspec's build or a compiler): a refusal stays one, a built
    # reproducer is only run.
    rc=0
    [[ -s "$dir/refused.txt" && ! -e "$dir/repro.c" ]] && rc=1
  else
    "$rayspec" export "$file" --format "$format" --out "$dir" >"$dir/export.txt" 2>"$dir/refused.txt"
    rc=$?
  fi
  if [[ $rc -ne 0 ]]; then
    reason=$(sed -n 's/.*export: case uses \(.*\), \(not yet exported\|which an Amber script cannot express\).*/\1/p' "$dir/refused.txt" | head -1)
    printf '%s\trefused\t%s\t%s\n' "$family" "$rel" "${reason:-exit $rc: $(head -1 "$dir/refused.txt")}"
    return
  fi
  if [[ $format == amber ]]; then
    name=$(sed -n '2s/^# rayspec export of case \([^ ]*\) .*/\1/p' "$dir/repro.amber")
  else
    name=$(sed -n '1s/^\/\* rayspec export of case \([^ ]*\) .*/\1/p' "$dir/repro.c")
  fi
  # The status the baseline expects of the case: Pass where it lists none.
  want=$(grep -v '^#' "$baseline" | awk -F, -v c="$name" '$1 == c {print $2}' | head -1)
  want=${want:-Pass}
  if [[ $format == amber ]]; then
    if [[ -z $amber ]]; then
      printf '%s\texported\t%s\t(not run: no AMBER)\n' "$family" "$name"
      return
    fi
    "$amber" -v 1.2 -d "$dir/repro.amber" >"$dir/run.txt" 2>&1
    got=$?
  else
    if [[ -z ${PREBUILT:-} ]] && ! cc -std=c99 "$dir/repro.c" -lvulkan -o "$dir/repro" 2>"$dir/build.txt"; then
      printf '%s\tbuild-error\t%s\t%s\n' "$family" "$name" "$(head -1 "$dir/build.txt")"
      return
    fi
    "$dir/repro" "$device" >"$dir/run.txt" 2>&1
    got=$?
  fi
  # The outcome as a status name: a QualityWarning exits 0 and says so.
  case $got in
    0) status=Pass; grep -q '^QualityWarning: ' "$dir/run.txt" && status=QualityWarning ;;
    1) status=Fail ;;
    77) status=NotSupported ;;
    *) status="exit $got" ;;
  esac
  # A baseline need not list a QualityWarning (it fails no run): where the
  # export warns and the baseline lists nothing, rayspec's own verdict on
  # the case (rayspec run on DEVICE) is the one expected.
  if [[ $status == QualityWarning && $want == Pass ]]; then
    "$rayspec" run --filter "$name" --device "$device" --out "$dir/rayspec" >/dev/null 2>&1
    grep -q "^$name: QualityWarning" "$dir/rayspec/summary.txt" && want="QualityWarning" &&
      how=" (rayspec run: the baseline lists no QualityWarning)"
  fi
  verdict=$([[ "$status" == "$want" ]] && echo agrees || echo DISAGREES)
  printf '%s\t%s\t%s\t%s (exit %s), expected %s%s\n' "$family" "$verdict" "$name" "$status" "$got" "$want" "$how"
}
export -f one_case
find cases -name '*.yaml' | sort | xargs -P "$jobs" -I{} bash -c 'one_case "$1"' _ {} | sort >"$out/cases.txt"
{
  echo "exports per family (exported / case files; agreeing with $baseline on $device):"
  awk -F'\t' '{n[$1]++; if ($2 != "refused") e[$1]++; if ($2 == "agrees") a[$1]++}
    END {for (f in n) printf "  %-14s %3d / %3d, %3d agree\n", f, e[f], n[f], a[f]}' "$out/cases.txt" | sort
  awk -F'\t' '{n++; if ($2 != "refused") e++; if ($2 == "agrees") a++}
    END {printf "  %-14s %3d / %3d, %3d agree\n", "all", e, n, a}' "$out/cases.txt"
  echo "refused, by reason:"
  awk -F'\t' '$2 == "refused" {print $4}' "$out/cases.txt" | sort | uniq -c | sort -rn
  echo "disagreements and build errors:"
  awk -F'\t' '$2 == "DISAGREES" || $2 == "build-error"' "$out/cases.txt"
} >"$out/summary.txt"
cat "$out/summary.txt"
