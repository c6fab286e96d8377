#!/usr/bin/env bash
# ctest style/format: every C++ file of harness/, tests/, bench/ and fuzz/ is
# formatted as .clang-format says (clang-format 14). Prints the files that
# are not and the command that formats them; exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(find harness tests bench fuzz -name '*.cpp' -o -name '*.h' | sort)
[[ ${#files[@]} -gt 100 ]] || { echo "check-format: only ${#files[@]} files found" >&2; exit 2; }
# One clang-format for all files; only when it finds something, one a file
# to name them.
bad=()
if ! clang-format --dry-run --Werror "${files[@]}" >/dev/null 2>&1; then
  for f in "${files[@]}"; do
    clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
  done
fi
if [[ ${#bad[@]} -gt 0 ]]; then
  printf 'check-format: not formatted: %s\n' "${bad[@]}" >&2
  echo "check-format: run  clang-format -i ${bad[*]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted as .clang-format says"
