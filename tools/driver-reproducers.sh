#!/usr/bin/env bash
# The reproducers of the driver reports (references/driver-reports/): each
# report's reduced case, NAME.yaml beside NAME.md, exported by `rayspec
# export` (docs/export.md) into NAME.c, a C file a driver developer builds
# with `cc NAME.c -lvulkan -o repro` and runs without rayspec.
#
#   tools/driver-reproducers.sh write            # NAME.c of every NAME.yaml, as rayspec exports it now
#   tools/driver-reproducers.sh check OUT        # ctest driver-reports/reproducers: the two below
#   tools/driver-reproducers.sh stale OUT        # every NAME.c as rayspec exports it now (else: stale),
#                                                # a case the export refuses as NAME.md's row "rayspec export" says
#   tools/driver-reproducers.sh build OUT        # every NAME.c built into OUT/NAME (for a machine without headers)
#   tools/driver-reproducers.sh play OUT LABEL [RUNNER...]
#       every NAME.c built into OUT/NAME (kept where OUT/NAME is there: `build OUT` made it) and run
#       (by RUNNER, e.g. `bash tools/second-driver.sh exec`), its exit status and output held to
#       NAME.md's row LABEL ("lavapipe 25.0.7")
#
# A report's rows (its section "Reproducer"): `| LABEL | EXIT | `TEXT` |`, EXIT
# the status expected (0 PASS, 1 FAIL, 77 NotSupported; words after the number
# are a note) and TEXT a line the output must hold. RAYSPEC: the binary
# (build/rayspec); CC: the C compiler (cc); DEVICE: the reproducers' device
# argument (llvmpipe). Exit 0 when every one agrees, 1 naming each that does not.
set -uo pipefail
cd "$(dirname "$0")/.."
reports=references/driver-reports
rayspec=${RAYSPEC:-build/rayspec}
cc=${CC:-cc}
device=${DEVICE:-llvmpipe}

die() { echo "driver-reproducers: $*" >&2; exit 2; }

# The row LABEL of report $1: "EXIT<tab>TEXT", nothing where it has none.
row() {
  awk -v label="$2" 'index($0, "| " label " | ") == 1 {
      split($0, cell, " \\| "); exit_status = cell[2] + 0
      text = cell[3]; sub(/^`/, "", text); sub(/` \|$/, "", text)
      printf "%s\t%s\n", exit_status, text; exit }' "$1"
}

# Exports case $1 into folder $2; prints the export's exit status.
export_into() {
  "$rayspec" export "$1" --out "$2" >"$2/export.txt" 2>&1
  echo $?
}

write() {
  local yaml name tmp rc
  tmp=$(mktemp -d)
  for yaml in "$reports"/*.yaml; do
    name=$(basename "$yaml" .yaml)
    mkdir -p "$tmp/$name"
    rc=$(export_into "$yaml" "$tmp/$name")
    if [[ $rc == 0 ]]; then
      cp "$tmp/$name/repro.c" "$reports/$name.c" && echo "wrote $reports/$name.c"
    else
      rm -f "$reports/$name.c"
      echo "$name: rayspec export exits $rc: $(tail -n 1 "$tmp/$name/export.txt")"
    fi
  done
  rm -rf "$tmp"
}

# One case: exported again, compared with its committed C file or its
# report's refusal; prints what is wrong, nothing where all agrees.
stale_one() {
  local yaml=$1 out=$2 name rc want
  name=$(basename "$yaml" .yaml)
  mkdir -p "$out/$name"
  rc=$(export_into "$yaml" "$out/$name")
  if [[ -f "$reports/$name.c" ]]; then
    [[ $rc == 0 ]] || { echo "$name: rayspec export exits $rc: $(tail -n 1 "$out/$name/export.txt")"; return; }
    cmp -s "$out/$name/repro.c" "$reports/$name.c" ||
      echo "$name: $reports/$name.c is stale (not what rayspec exports now; tools/driver-reproducers.sh write)"
    return
  fi
  want=$(row "$reports/$name.md" "rayspec export")
  [[ -n $want ]] || { echo "$name: no $name.c and no row \"rayspec export\" in $name.md"; return; }
  [[ $rc == "${want%%$'\t'*}" ]] && grep -qF -- "${want#*$'\t'}" "$out/$name/export.txt" ||
    echo "$name: rayspec export exits $rc ($(tail -n 1 "$out/$name/export.txt")), $name.md says ${want//$'\t'/: }"
}

stale() {
  local out=$1 yaml bad=0 said
  mkdir -p "$out"
  for yaml in "$reports"/*.yaml; do
    said=$(stale_one "$yaml" "$out/export")
    [[ -z $said ]] || { echo "$said"; bad=1; }
  done
  [[ $bad == 0 ]] && echo "driver-reproducers: every C file as rayspec exports it"
  return $bad
}

# C file $1 built into folder $2, named as the file without .c.
build_one() {
  local name
  name=$(basename "$1" .c)
  "$cc" -std=c99 "$1" -lvulkan -o "$2/$name" 2>"$2/$name.build.txt"
}

build() {
  local c bad=0
  mkdir -p "$1"
  for c in "$reports"/*.c; do
    build_one "$c" "$1" && echo "built $1/$(basename "$c" .c)" || { echo "$c does not build"; bad=1; }
  done
  return $bad
}

# One C file built (where not yet) and run, held to its report's row; prints one line.
play_one() {
  local c=$1 out=$2 label=$3 name want rc
  shift 3
  name=$(basename "$c" .c)
  want=$(row "$reports/$name.md" "$label")
  [[ -n $want ]] || { echo "DISAGREES $name: no row \"$label\" in $name.md"; return; }
  [[ -x $out/$name ]] || build_one "$c" "$out" ||
    { echo "DISAGREES $name: does not build ($out/$name.build.txt)"; return; }
  "$@" "$out/$name" "$device" >"$out/$name.txt" 2>&1
  rc=$?
  if [[ $rc == "${want%%$'\t'*}" ]] && grep -qF -- "${want#*$'\t'}" "$out/$name.txt"; then
    echo "agrees $name: exit $rc, $(grep -m1 -F -- "${want#*$'\t'}" "$out/$name.txt")"
  else
    echo "DISAGREES $name: exit $rc ($(head -n 1 "$out/$name.txt")), $name.md's \"$label\" says ${want//$'\t'/: }"
  fi
}

play() {
  [[ $# -ge 2 ]] || die "usage: tools/driver-reproducers.sh play OUT LABEL [RUNNER...]"
  local out=$1 label=$2 c said bad=0
  shift 2
  mkdir -p "$out"
  for c in "$reports"/*.c; do
    said=$(play_one "$c" "$out" "$label" "$@")
    echo "$said"
    [[ $said == agrees* ]] || bad=1
  done
  return $bad
}

case ${1:-} in
  write) write ;;
  stale) shift; [[ $# -eq 1 ]] || die "usage: tools/driver-reproducers.sh stale OUT"; stale "$1" ;;
  play) shift; play "$@" ;;
  build) shift; [[ $# -eq 1 ]] || die "usage: tools/driver-reproducers.sh build OUT"; build "$1" ;;
  check)
    shift; [[ $# -eq 1 ]] || die "usage: tools/driver-reproducers.sh check OUT"
    rm -rf "$1"; rc=0
    stale "$1" || rc=1
    play "$1/play" "lavapipe 25.0.7" || rc=1
    exit $rc ;;
  *) die "usage: tools/driver-reproducers.sh write | check OUT | stale OUT | build OUT | play OUT LABEL [RUNNER...]" ;;
esac
