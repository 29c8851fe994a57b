#!/usr/bin/env bash
# Renders a sweep's report.html in headless Chromium (Debian's `chromium`, installed if
# missing) and saves two PNG screenshots under out/: the page as it opens, and the page after
# about half a second of its animations (virtual time). Fails if Chromium fails or writes no
# screenshot. Look at the PNGs: the figures and each participant's animated fastest swing
# should be drawn (docs/report-html.md).
# Not run in CI: installing Chromium costs minutes there, and the report's structure is
# checked by tests/report/sweep_html_test.cpp.
# Usage: bash scripts/check-report-html.sh [REPORT.html]   (default out/burkett2004/report.html)
set -euo pipefail
cd "$(dirname "$0")/.."
report="${1:-out/burkett2004/report.html}"
[ -f "$report" ] || { echo "check-report-html: $report: no such file (run: build/swingsim sweep studies/burkett2004.yaml)" >&2; exit 1; }
command -v chromium >/dev/null || bash scripts/install-packages.sh chromium
mkdir -p out
url="file://$(realpath "$report")"
stem="out/$(basename "$(dirname "$(realpath "$report")")")-report-html"
size="1100,2400"
shoot() {  # shoot PNG [extra chromium options]
  local png="$1"; shift
  rm -f "$png"
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$size" \
    --screenshot="$(realpath -m "$png")" "$@" "$url" >"$png.log" 2>&1 ||
    { echo "check-report-html: chromium failed on $report (log: $png.log)" >&2; exit 1; }
  [ -s "$png" ] || { echo "check-report-html: chromium wrote no screenshot $png (log: $png.log)" >&2; exit 1; }
  echo "screenshot: $png"
}
shoot "$stem.png"
shoot "$stem-animated.png" --virtual-time-budget=500
