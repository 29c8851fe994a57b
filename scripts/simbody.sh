#!/usr/bin/env bash
# Simbody for swingsim: Debian's own source package, built in Release (NDEBUG), installed once
# into a cache outside the clone and reused. Prints the install prefix on stdout (and nothing
# else); progress goes to stderr.
#
#   bash scripts/simbody.sh            -> e.g. /root/.cache/swingsim/simbody-3.7+dfsg-3-1a2b3c4d5e
#
# Why not Debian's binary package libsimbody-dev: debhelper builds it with
# CMAKE_BUILD_TYPE=None, so it is compiled without NDEBUG and keeps Simbody's debug checks
# (a dynamic_cast in every cache access, index and stage checks): a swing costs 2.4x more
# (docs/speed.md). The source is the same package (3.7+dfsg-3 with Debian's patches).
#
# The cache: ${SWINGSIM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/swingsim}. The folder's name
# holds the source version and a hash of the build flags and the compiler, so another clone or
# a CI run on the same machine finds it; a changed version or flag builds a new one. A build
# is installed into a temporary folder and renamed into place only when complete, so an
# interrupted build is never mistaken for a finished one; a lock file in the cache lets one
# build run at a time.
set -euo pipefail
unset CC CXX CFLAGS CXXFLAGS LDFLAGS  # always the system g++, whatever the caller builds with
cd "$(dirname "$0")/.."

version="3.7+dfsg-3"   # Debian bookworm's simbody source package
flags=(-DCMAKE_BUILD_TYPE=Release -DBUILD_EXAMPLES=OFF -DBUILD_TESTING=OFF -DBUILD_VISUALIZER=OFF
       -DBUILD_STATIC_LIBRARIES=OFF)
# What the build needs (installed only when missing, so a cache hit costs a dpkg query); first,
# because the cache key names the compiler.
bash scripts/install-packages.sh build-essential cmake dpkg-dev liblapack-dev libblas-dev >&2
cache="${SWINGSIM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/swingsim}"
compiler="$(c++ --version 2>/dev/null | head -1)"
hash="$(printf '%s\n' "$version" "${flags[@]}" "$compiler" | sha256sum | cut -c1-10)"
prefix="$cache/simbody-$version-$hash"

# Prints the prefix and ends the script when a finished build is there.
take_if_built() { if [ -f "$prefix/.complete" ]; then echo "$prefix"; exit 0; fi; }
take_if_built

# One build at a time per cache (two clones set up at once): the second waits for the first
# and then finds its result.
mkdir -p "$cache"
exec 9>"$cache/.simbody.lock"
if ! flock -n 9; then
  echo "== waiting for another build of Simbody into $cache to finish" >&2
  flock 9
fi
take_if_built

echo "== Simbody $version (Release) is not in the cache: fetching Debian's source package and building it into $prefix (about 6 min on 2 cores, once)" >&2

# A deb-src entry for the Debian mirror the machine already uses, in a file of our own.
src_list=/etc/apt/sources.list.d/swingsim-deb-src.sources
if ! apt-get source --print-uris "simbody=$version" >/dev/null 2>&1; then
  uri="$(sed -n 's/^URIs:[[:space:]]*//p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | grep -v security | head -1)"
  uri="${uri:-http://deb.debian.org/debian}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  printf 'Types: deb-src\nURIs: %s\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$uri" | $SUDO tee "$src_list" >/dev/null
  $SUDO apt-get update -qq
fi

work="$(mktemp -d "$cache/.simbody-build-XXXXXX")"
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get source -qq "simbody=$version" >/dev/null 2>&1) || {
  echo "error: apt-get source simbody=$version failed (is a deb-src entry for bookworm reachable? see $src_list)" >&2
  exit 1
}
srcdir="$(find "$work" -maxdepth 1 -mindepth 1 -type d -name 'simbody-*' | head -1)"
[ -n "$srcdir" ] || { echo "error: no simbody source folder after apt-get source in $work" >&2; exit 1; }

staging="$work/install"
cmake -S "$srcdir" -B "$work/build" "${flags[@]}" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_INSTALL_LIBDIR=lib -DSIMBODY_VISUALIZER_INSTALL_DIR="$prefix/libexec" >"$work/configure.log" 2>&1 || {
  tail -30 "$work/configure.log" >&2; exit 1; }
cmake --build "$work/build" -j"$(nproc)" >"$work/build.log" 2>&1 || { tail -40 "$work/build.log" >&2; exit 1; }
DESTDIR="$staging" cmake --install "$work/build" >"$work/install.log" 2>&1 || { tail -20 "$work/install.log" >&2; exit 1; }
rm -rf "$prefix"
mv "$staging$prefix" "$prefix"
printf 'simbody %s\nflags %s\ncompiler %s\n' "$version" "${flags[*]}" "$compiler" >"$prefix/.complete"
echo "== Simbody installed into $prefix" >&2
echo "$prefix"
