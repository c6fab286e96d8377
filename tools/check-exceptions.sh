#!/usr/bin/env bash
# ctest style/exceptions: the one error convention (harness/base/error.h,
# docs/layout-and-conventions.md, "Errors"). A fallible function of rayspec
# returns Result<T>; nothing in harness/ throws, and no exception type of rayspec's own is declared.
# Exceptions come only from the libraries and the standard library, and are
# caught where they are thrown (yaml-cpp, nlohmann-json, CLI11, OpenImageIO,
# std::filesystem ...), so a `catch` is fine and a `throw` is not.
# Prints each throw (comments and string literals left out) and each class
# derived from a standard exception; exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."

# Files that still throw, each with why; the list may only shrink (none now).
allowed=()

mapfile -t files < <(find harness -name '*.cpp' -o -name '*.h' | sort)
[[ ${#files[@]} -gt 100 ]] || { echo "check-exceptions: only ${#files[@]} files found" >&2; exit 2; }
found=$(perl -ne '
  s{"(?:[^"\\]|\\.)*"}{""}g;  # string literals
  s{//.*}{};                  # line comments
  print "$ARGV:$.: throws\n" if /\bthrow\b/;
  print "$ARGV:$.: declares an exception type\n"
    if /(?:struct|class)\s+\w+\s*(?:final\s*)?:\s*(?:public\s+)?std::(?:exception|runtime_error|logic_error|invalid_argument|out_of_range)\b/;
  close ARGV if eof;          # $. counts lines per file
' "${files[@]}")

bad=0
while IFS= read -r line; do
  [[ -z $line ]] && continue
  file=${line%%:*}
  ok=0
  for a in "${allowed[@]}"; do [[ $file == "$a" ]] && ok=1; done
  if [[ $ok == 0 ]]; then
    echo "check-exceptions: $line: return an Error (base/result.h) instead" >&2
    bad=1
  fi
done <<<"$found"
for a in "${allowed[@]}"; do
  if ! grep -q "^$a:" <<<"$found"; then
    echo "check-exceptions: $a no longer throws: take it off the list in $0" >&2
    bad=1
  fi
done

[[ $bad == 0 ]] || exit 1
echo "check-exceptions: no throw in harness/ but the ${#allowed[@]} files listed"
