#!/usr/bin/env bash
# Fails when a function in src/ or python/src/ runs over 80 lines, counted from its signature
# line to its closing brace (Universal Ctags' line: and end: fields), listing each one as
# `file:line: NAME: N lines (limit 80)`. A long function becomes small named functions, each
# with one job; only a data table, a list whose rows are the content, may stay long, and is
# named in the allowlist below with the reason.
# Usage: bash scripts/check-function-length.sh [ROOT]   (ROOT: the tree to check, default this
#        checkout; tests/data/function_length is a fixture that must fail)
# Exits 77 (ctest: skipped) when Universal Ctags is missing (Debian: universal-ctags).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "${1:-$root}"
readonly limit=80

# Functions allowed past the limit: file, name, and why (one line each).
allowed=(
  "src/identify/effect_table.cpp effectTable the one table of candidate effects, one descriptor a row"
  "src/identify/swing_effects.cpp swingEffectRecords the swing plant's table of effect records, one record a row"
  "src/identify/cylinder_effects.cpp cylinderEffectRecords the cylinder plant's table of effect records, one record a row"
  "src/identify/sweep_effects.cpp sweepEffectLaws the sweep plant's table of effect laws, one law a row"
)

if ! command -v ctags >/dev/null || ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "check-function-length: skipped: Universal Ctags is not installed (Debian: apt-get install universal-ctags)" >&2
  exit 77
fi

allowlist=$(printf '%s\n' "${allowed[@]}" | awk '{print $1 "\t" $2}')
dirs=()
for d in src python/src; do [ -d "$d" ] && dirs+=("$d"); done
tags=$(ctags --languages=C++ --kinds-C++=f --fields=+ne -o - -R "${dirs[@]}")
# Each tag line: name, file, pattern, then fields such as line:N and end:N.
over=$(awk -F'\t' -v limit="$limit" -v allowlist="$allowlist" '
  BEGIN { n = split(allowlist, rows, "\n"); for (i = 1; i <= n; i++) allowed[rows[i]] = 1 }
  {
    start = ""; end = ""
    for (i = 4; i <= NF; i++) {
      if ($i ~ /^line:/) start = substr($i, 6)
      if ($i ~ /^end:/) end = substr($i, 5)
    }
    if (end == "" || ($2 "\t" $1) in allowed) next
    length_ = end - start + 1
    if (length_ > limit) printf "%s:%d: %s: %d lines (limit %d)\n", $2, start, $1, length_, limit
  }' <<<"$tags" | sort -t: -k1,1 -k2,2n)

if [ -n "$over" ]; then
  echo "$over"
  echo "check-function-length: $(wc -l <<<"$over") function(s) over $limit lines; split each into small named functions" \
       "with one job (a data table may go in this script's allowlist, with the reason)" >&2
  exit 1
fi
echo "check-function-length: every function in src/ and python/src/ is at most $limit lines"
