#!/usr/bin/env bash
# Fails when a C++ file of the project is not as clang-format (.clang-format: Google's style at
# 120 columns) would write it, naming each file; `--fix` formats them instead.
# Files: the tracked *.cpp and *.h under src/, python/src/, tests/, bench/ and fuzz/, except
# tests/data/ (fixtures whose line counts and layout are what a test checks).
# Usage: bash scripts/check-format.sh [--fix] [FILE...]   (FILE: only these, e.g. the staged ones)
# Exits 77 (ctest: skipped) when clang-format is missing (Debian: clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
fix=0
if [ "${1:-}" = --fix ]; then fix=1; shift; fi
if ! command -v clang-format >/dev/null; then
  echo "check-format: skipped: clang-format is not installed (Debian: apt-get install clang-format)" >&2
  exit 77
fi
files=()
if [ $# -gt 0 ]; then
  for f in "$@"; do
    case "$f" in tests/data/*) ;; src/*|python/src/*|tests/*|bench/*|fuzz/*)
      case "$f" in *.cpp|*.h) [ -f "$f" ] && files+=("$f") ;; esac ;; esac
  done
elif git rev-parse --git-dir >/dev/null 2>&1; then
  while IFS= read -r -d '' f; do files+=("$f"); done < <(git ls-files -z -- 'src/*.cpp' 'src/*.h' 'python/src/*.cpp' \
    'python/src/*.h' 'tests/*.cpp' 'tests/*.h' 'bench/*.cpp' 'bench/*.h' 'fuzz/*.cpp' 'fuzz/*.h' ':!tests/data/*')
else
  while IFS= read -r -d '' f; do files+=("$f"); done < <(find src python/src tests bench fuzz -path tests/data -prune -o \
    \( -name '*.cpp' -o -name '*.h' \) -print0)
fi
[ ${#files[@]} -eq 0 ] && exit 0
if [ "$fix" = 1 ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "$f: not formatted (bash scripts/check-format.sh --fix $f)"
    bad=$((bad + 1))
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "check-format: $bad file(s) differ from clang-format's layout (.clang-format)" >&2
  exit 1
fi
