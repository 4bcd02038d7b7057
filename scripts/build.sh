#!/usr/bin/env bash
# Sets up (scripts/setup.sh), configures and builds everything on all cores.
# TMU_BUILD_DIR chooses the build directory (default: build/); extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}

"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja "$@"
cmake --build "$build" -j "$(nproc)"
