#!/usr/bin/env bash
# ctest style/naming: the one naming rule for variables (.clang-tidy says it
# in full): locals, parameters and members are snake_case, so a variable
# declared with a camelCase name fails. This check reads declarations
# textually (a type, a camelCase name, then = { ; , ) or :), comments and
# string literals taken out; it runs in a second. Constants may be
# kPascalCase, and pointers to Vulkan functions (PFN_*) are named like them. clang-tidy applies the same
# rule exactly, and fixes what it finds, in about a minute on two cores:
#   tools/check-naming.sh --clang-tidy [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."

if [[ ${1:-} == --clang-tidy ]]; then
  fix=()
  [[ ${2:-} == --fix ]] && fix=(-fix)
  exec run-clang-tidy -quiet -p build -j "$(nproc)" "${fix[@]}" \
    -header-filter='.*/(harness|tests|bench|fuzz)/'
fi

mapfile -t files < <(find harness tests bench fuzz -name '*.cpp' -o -name '*.h' | sort)
[[ ${#files[@]} -gt 100 ]] || { echo "check-naming: only ${#files[@]} files found" >&2; exit 2; }
perl -ne '
  BEGIN { $bad = 0 }
  s{"(?:[^"\\]|\\.)*"}{""}g;        # string literals
  s{//.*}{};                        # line comments
  my $type = qr{(?:auto|bool|char|int|unsigned|float|double|size_t|u?int(?:8|16|32|64)_t
               |std::[\w:]+(?:<[^;(){}]*>)?|[A-Z]\w*(?:::\w+)*(?:<[^;(){}]*>)?)}x;
  while (/(?:^|[\s(,{;])(?:const\s+|static\s+|constexpr\s+)*$type\s*[&*]*\s+([a-z][a-z0-9]*[A-Z]\w*)\s*(?:=(?!=)|\{|;|,|\)|:(?!:)|\[)/g) {
    next if $1 =~ /^k[A-Z]/ || $& =~ /\bPFN_/;  # kConstants; Vulkan function pointers
    print "$ARGV:$.: variable \x27$1\x27 is not snake_case\n";
    $bad++;
  }
  while (/\bauto\s*[&*]*\s*\[([^\]]*)\]/g) {    # structured bindings
    for my $n (split /\s*,\s*/, $1) {
      next unless $n =~ /^[a-z][a-z0-9]*[A-Z]\w*$/;
      print "$ARGV:$.: variable \x27$n\x27 is not snake_case\n";
      $bad++;
    }
  }
  close ARGV if eof;                # $. counts lines per file
  END { exit($bad ? 1 : 0) }
' "${files[@]}" || {
  echo "check-naming: name variables in snake_case (.clang-tidy; tools/check-naming.sh --clang-tidy --fix renames them)" >&2
  exit 1
}
echo "check-naming: ${#files[@]} files, every declared variable snake_case"
