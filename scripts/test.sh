#!/usr/bin/env bash
# Set up, build, and run every test: GoogleTest suites (golden, hls, rtl, equiv), the RTL
# lint and the Yosys synthesis check. Extra arguments go to ctest (e.g. -L equiv).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}

"$root/scripts/build.sh"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure "$@"
