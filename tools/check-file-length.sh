#!/usr/bin/env bash
# ctest style/file-length: no C or C++ source or header of harness/, tests/,
# bench/ or fuzz/ longer than 700 lines. A file that outgrows it holds more
# than one thing: cut the other thing into a file named after it
# (docs/layout-and-conventions.md, "File length").
set -euo pipefail
cd "$(dirname "$0")/.."
LIMIT=700
status=0
count=0
while IFS= read -r -d '' file; do
  count=$((count + 1))
  lines=$(wc -l < "$file")
  if (( lines > LIMIT )); then
    echo "check-file-length: $file is $lines lines (at most $LIMIT): cut what it holds besides its one thing into a file of its own" >&2
    status=1
  fi
done < <(find harness tests bench fuzz -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.c' \) -print0)
[[ $status -eq 0 ]] && echo "check-file-length: $count files, none over $LIMIT lines"
exit $status
