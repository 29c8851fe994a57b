#!/usr/bin/env bash
# Renders a sweep's report.html in headless Chromium (Debian's `chromium`, installed if
# missing) and saves three PNG screenshots under out/: the top of the page; the section of
# participant SECTION (its heading's id, default p1: its animated fastest swing and figures)
# as it opens; and the same after 0.25 s of virtual time, mid-animation. Headless Chromium
# paints nothing when told to scroll to REPORT.html#SECTION, so the section is cut out into a
# page of its own (the report's <head> and the section's HTML unchanged) for its screenshots.
# Fails if Chromium fails or writes no screenshot. Look at the PNGs: the figures and each participant's animated fastest swing
# should be drawn (docs/report-html.md).
# Not run in CI: installing Chromium costs minutes there, and the report's structure is
# checked by tests/report/sweep_html_test.cpp.
# Usage: bash scripts/check-report-html.sh [REPORT.html [SECTION]]
#        (default out/burkett2004/report.html and p1)
set -euo pipefail
cd "$(dirname "$0")/.."
report="${1:-out/burkett2004/report.html}"
section="${2:-p1}"
[ -f "$report" ] || { echo "check-report-html: $report: no such file (run: build/swingsim sweep studies/burkett2004.yaml)" >&2; exit 1; }
command -v chromium >/dev/null || bash scripts/install-packages.sh chromium
mkdir -p out
url="file://$(realpath "$report")"
stem="out/$(basename "$(dirname "$(realpath "$report")")")-report-html"
size="1100,1600"
shoot() {  # shoot PNG URL [extra chromium options]
  local png="$1" page="$2"; shift 2
  rm -f "$png"
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$size" \
    --screenshot="$(realpath -m "$png")" "$@" "$page" >"$png.log" 2>&1 ||
    { echo "check-report-html: chromium failed on $report (log: $png.log)" >&2; exit 1; }
  [ -s "$png" ] || { echo "check-report-html: chromium wrote no screenshot $png (log: $png.log)" >&2; exit 1; }
  echo "screenshot: $png"
}
shoot "$stem.png" "$url"
# The section: from its <h2 id="SECTION"> to the next <h2 (or the end of the body).
page="$stem-$section.html"
awk -v start="<h2 id=\"$section\">" '
  index($0, "<h2 id=") == 1 { inside = index($0, start) == 1 }
  $0 == "<body>" { print; head = 1; next }
  !head || inside { print }
  END { print "</body>\n</html>" }' "$report" >"$page"
grep -q "<h2 id=\"$section\">" "$page" || { echo "check-report-html: $report has no section with id \"$section\"" >&2; exit 1; }
url="file://$(realpath "$page")"
shoot "$stem-$section.png" "$url"
shoot "$stem-$section-animated.png" "$url" --virtual-time-budget=250
