#!/usr/bin/env bash
# Sets up (scripts/setup.sh), configures and builds everything on all cores.
# TMU_BUILD_DIR chooses the build directory (default: build/); extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}
# ccache caches a compilation that uses a precompiled header (the tests' and the models') only
# when told that the header's macros and __DATE__/__TIME__ may be ignored: without this every
# clean build recompiles them.
export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros}
# Paths inside the checkout hashed relative to it: a clone elsewhere (CI's fresh clone) finds
# what another clone compiled.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}

"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja "$@"
cmake --build "$build" -j "$(nproc)"
