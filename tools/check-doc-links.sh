#!/usr/bin/env bash
# ctest style/doc-links: README.md and docs/*.md name only what exists.
#   - every relative markdown link, [text](target), resolves (from the page's
#     folder) to a file or folder of the checkout, and its #anchor, where it
#     has one and the target is a markdown page, is a heading of that page
#     (GitHub's slug: lower case, punctuation dropped, spaces to '-');
#   - every path the pages write that starts at a top-level folder of the
#     checkout (cases/, harness/, tools/, references/, tests/, bench/, fuzz/,
#     docs/, shaders/, .ci/) exists, and so does every header or source file
#     named from its harness module (run/fault_seam.h is harness/run/...).
#     Paths with a placeholder or a glob (<case>, *, {, $) are not checked;
#     a ctest test's name (fuzz/inputs) is no path.
#   - no page of those or of cases/*.md names a path up out of the checkout
#     (../shared/...): a user's clone has only the repository.
# Prints each one that does not; exits 1 if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."

pages=(README.md docs/*.md)
bad=0

complain() {
  echo "check-doc-links: $1" >&2
  bad=1
}

# The slugs of a page's headings, one a line (fenced code blocks skipped).
slugs() {
  awk '/^```/ { fence = !fence; next } !fence && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
    tr '[:upper:]' '[:lower:]' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g'
}

for page in "${pages[@]}"; do
  dir=$(dirname "$page")
  # Links: ](target), outside inline code spans.
  while IFS= read -r target; do
    case "$target" in http://* | https://* | mailto:*) continue ;; esac
    file=${target%%#*}
    anchor=""
    [[ $target == *"#"* ]] && anchor=${target#*#}
    resolved=$page
    if [[ -n $file ]]; then
      resolved=$dir/$file
      [[ -e $resolved ]] || { complain "$page: link to $target: no such file"; continue; }
    fi
    if [[ -n $anchor && $resolved == *.md ]] && ! slugs "$resolved" | grep -qxF -- "$anchor"; then
      complain "$page: link to $target: no heading '$anchor' in $resolved"
    fi
  done < <(sed -e 's/`[^`]*`//g' "$page" | grep -oE '\]\([^) ]+\)' | sed -e 's/^](//' -e 's/)$//')

  # Paths from a top-level folder, and harness files named from their module.
  while IFS= read -r path; do
    path=${path%%[.,:;]}
    path=${path%%[.,:;]}
    [[ $path == *[\<\>\*\{\}\$]* ]] && continue
    [[ -e $path || -e harness/$path ]] && continue
    grep -qF "add_test(NAME $path " tests/CMakeLists.txt && continue  # a ctest test: fuzz/inputs
    complain "$page: $path: no such file or folder"
  done < <(grep -oP '(?<![A-Za-z0-9_./-])(?:(?:cases|harness|tools|references|tests|bench|fuzz|docs|shaders|\.ci)/[A-Za-z0-9_./<>*{}$-]*|[a-z_]+/[A-Za-z0-9_]+\.(?:h|cpp)(?![A-Za-z0-9_]))' "$page" || true)
done

# Nothing outside the checkout: a path up out of it (../shared/..., from
# README.md, docs/ or cases/*.md) names what a user's clone does not have;
# what a page cites must be readable from the repository (the rules' text:
# references/spec-rules.yaml). A link's target is read from the page's
# folder, a path in the text from the checkout's root (where ../ leaves it).
root=$(pwd -P)
for page in README.md docs/*.md cases/*.md; do
  dir=$(dirname "$page")
  while IFS= read -r target; do
    [[ $(realpath -m "$dir/$target") == "$root"/* ]] ||
      complain "$page: link to $target: outside the checkout"
  done < <(grep -oE '\]\(\.\./[^) ]*\)' "$page" | sed -e 's/^](//' -e 's/)$//' || true)
  while IFS= read -r path; do
    complain "$page: $path: outside the checkout"
  done < <(sed -E 's/\]\([^) ]*\)//g' "$page" |
    grep -oE '(^|[^A-Za-z0-9_./-])(\.\./)+[A-Za-z0-9_./-]*' | sed -E 's/^[^.]*//' || true)
done
exit $bad
