#!/usr/bin/env bash
# Real pFUnit 4.9.0 for the unit tests (tests/**/*.pf), built once per machine and
# compiler into a cache outside the repository and its build folders, then reused.
# Prints the install prefix on stdout (give it to CMake: -DCMAKE_PREFIX_PATH=<prefix>);
# progress goes to stderr.
#
#   cache:  ${RODYN_PFUNIT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rodyn}
#   prefix: <cache>/pfunit-4.9.0-gfortran-<gfortran version>
#   source: ../shared/vendor/pFUnit-4.9.0.tar.gz beside the repository when there,
#           else pFUnit's own v4.9.0 release on GitHub (sha256 checked either way).
#
# Safe to interrupt: everything is built and installed in a temporary folder of the
# cache, and the finished install is renamed into place in one step, so the prefix is
# either complete or absent. Concurrent callers wait for each other (flock). On failure
# the build log is kept beside the prefix and its end is shown.
# Needs gfortran (or $FC), cmake, make, python3 and m4 (tools/setup.sh installs them).
# Usage:
#   bash tools/pfunit.sh     (about 3 minutes of CPU the first time, on
#                             RODYN_PFUNIT_JOBS=2 jobs by default; then instant)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

version=4.9.0
# the vendored tarball (../shared/vendor/README.md)
vendored="$root/../shared/vendor/pFUnit-${version}.tar.gz"
vendored_sha256=14f70ea1d33194b6676590212dc3520f06d693debd146ac0a7e4fb084383c2ab
# pFUnit's release asset (an uncompressed tar holding the git submodules gFTL, gFTL-shared
# and fArgParse, unlike GitHub's automatic archives of the tag); its sha256 as Spack's
# pfunit package lists it
url="https://github.com/Goddard-Fortran-Ecosystem/pFUnit/releases/download/v${version}/pFUnit-v${version}.tar"
url_sha256=caea019f623d4e02dd3e8442cee88e6087b4c431a2628e9ec2de55b527b51ab6

fc="${FC:-gfortran}"
fc_version="$("$fc" -dumpfullversion 2>/dev/null || "$fc" -dumpversion)"
cache="${RODYN_PFUNIT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rodyn}"
mkdir -p "$cache"
cache="$(cd "$cache" && pwd -P)"  # absolute: the install is staged under DESTDIR
name="pfunit-${version}-$(basename "$fc")-${fc_version}"
prefix="$cache/$name"
log="$cache/$name-build.log"

# A complete install: pFUnit's CMake package file is its last piece.
complete() { compgen -G "$prefix/PFUNIT-*/cmake/PFUNITConfig.cmake" >/dev/null; }

if complete; then
  echo "$prefix"
  exit 0
fi

# One builder at a time per prefix; the others wait, then find it complete.
if command -v flock >/dev/null 2>&1; then
  exec 9>"$cache/$name.lock"
  flock 9
  if complete; then
    echo "$prefix"
    exit 0
  fi
  rm -rf "$cache/.$name.tmp."*  # left by a killed build (no one else is building)
fi
if [ -e "$prefix" ]; then  # not complete (made by hand?): never reuse nor overwrite it
  echo "pfunit: $prefix exists but holds no complete pFUnit install; remove it" >&2
  exit 1
fi

# Temporary folder on the cache's file system (the final rename is then atomic),
# removed on any exit.
tmp="$(mktemp -d "$cache/.$name.tmp.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

echo "pfunit: building pFUnit ${version} with $fc ${fc_version} into $prefix" \
     "(once per machine, about 3 minutes of CPU; log: $log)" >&2
command -v m4 >/dev/null 2>&1 || {
  echo "pfunit: m4 is needed to build pFUnit (Debian: apt-get install m4, or bash tools/setup.sh)" >&2
  exit 1
}

# ------------------------------------------------------------------ source
tarball="$tmp/pFUnit-${version}.tar"
if [ -f "$vendored" ]; then
  echo "pfunit: source: $vendored" >&2
  cp "$vendored" "$tarball"
  sha256="$vendored_sha256"
else
  echo "pfunit: source: $url" >&2
  if command -v curl >/dev/null 2>&1; then
    fetch=(curl -fsSL --retry 3 -o "$tarball" "$url")
  else
    fetch=(wget -q -O "$tarball" "$url")
  fi
  "${fetch[@]}" || {
    echo "pfunit: could not download $url (offline? put the tarball at $vendored)" >&2
    exit 1
  }
  sha256="$url_sha256"
fi
if ! echo "$sha256  $tarball" | sha256sum -c --status; then
  echo "pfunit: the pFUnit source's sha256 is not $sha256" >&2
  exit 1
fi
mkdir "$tmp/src"
tar -xf "$tarball" -C "$tmp/src" --strip-components=1  # gzip or not: tar sees which

# ------------------------------------------------------------------ build and install
# Serial pFUnit only (no MPI, OpenMP, hamcrest, ESMF, robust runner). Installed with
# DESTDIR into the temporary folder so that the files name the final prefix.
build() {
  cmake -S "$tmp/src" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_Fortran_COMPILER="$fc" -DCMAKE_INSTALL_PREFIX="$prefix" \
        -DSKIP_MPI=YES -DSKIP_OPENMP=YES -DSKIP_FHAMCREST=YES -DSKIP_ESMF=YES \
        -DSKIP_ROBUST=YES -DBUILD_TESTING=OFF &&
    cmake --build "$tmp/build" -j "${RODYN_PFUNIT_JOBS:-2}" &&
    DESTDIR="$tmp/stage" cmake --install "$tmp/build"
}
start=$SECONDS
if ! build >"$tmp/build.log" 2>&1; then
  cp "$tmp/build.log" "$log"
  tail -n 40 "$log" >&2
  echo "pfunit: the build of pFUnit failed; whole log: $log" >&2
  exit 1
fi
mv -T "$tmp/stage$prefix" "$prefix"
cp "$tmp/build.log" "$log"
echo "pfunit: pFUnit ${version} built in $((SECONDS - start)) s: $prefix" >&2
complete || { echo "pfunit: $prefix: no PFUNITConfig.cmake after install" >&2; exit 1; }
echo "$prefix"
