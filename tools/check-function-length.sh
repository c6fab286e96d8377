#!/usr/bin/env bash
# ctest style/function-length: no function of harness/, tests/, bench/ or
# fuzz/ longer than 80 lines
# (universal-ctags finds where each starts and ends), except the data tables
# and the functions not yet split that tools/long-functions.txt lists, each
# with the length it may not grow past. A listed function now within 80 lines
# must leave the list, so it only shrinks.
set -euo pipefail
cd "$(dirname "$0")/.."
LIMIT=80
list=tools/long-functions.txt
found=$(ctags -R --languages=C++ --kinds-C++=f --fields=+ne -x --_xformat="%{end} %{line} %F %N" harness tests bench fuzz |
  awk -v limit=$LIMIT '{n = $1 - $2 + 1; if (n > limit) print $3, $4, n}' | sort)
[[ -n $(ctags --version 2>/dev/null | grep -i universal) ]] || { echo "check-function-length: universal-ctags is missing (tools/setup.sh)" >&2; exit 2; }
status=0
while read -r file name lines; do
  [[ -z $file ]] && continue
  allowed=$(awk -v f="$file" -v n="$name" '$1 == f && $2 == n {print $3}' "$list")
  if [[ -z $allowed ]]; then
    echo "check-function-length: $file: $name is $lines lines (at most $LIMIT): split it into named steps" >&2
    status=1
  elif (( lines > allowed )); then
    echo "check-function-length: $file: $name grew to $lines lines ($list allows $allowed): split it" >&2
    status=1
  fi
done <<< "$found"
while read -r file name allowed _; do
  [[ -z $file || $file == \#* ]] && continue
  grep -q "^$file $name " <<< "$found" ||
    { echo "check-function-length: $file: $name is within $LIMIT lines now: remove it from $list" >&2; status=1; }
done < "$list"
[[ $status -eq 0 ]] && echo "check-function-length: no function over $LIMIT lines but the $(grep -vc '^#' "$list") listed in $list"
exit $status
