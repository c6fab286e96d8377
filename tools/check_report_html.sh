#!/usr/bin/env bash
# Opens a rayspec report.html in headless Chromium and prints the page's own
# self-check (images loaded, broken images, script errors). Exit 1 when an
# image is broken or a script failed. Usage: tools/check_report_html.sh RUN/report.html
set -euo pipefail
report=$(realpath "${1:?usage: $0 RUN/report.html}")
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
body=$(chromium --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update \
  --disable-sync --no-first-run --allow-file-access-from-files --virtual-time-budget=5000 \
  --user-data-dir="$profile" --dump-dom "file://$report" 2>/dev/null | grep -o '<body[^>]*>' || true)
echo "$body"
[[ "$body" == *'data-checked="1"'* && "$body" == *'data-broken-images="0"'* && "$body" == *'data-script-errors="0"'* ]]
