#!/usr/bin/env bash
# Set up, build, and run every test: GoogleTest suites (golden, hls, rtl, equiv), the RTL
# lint and the Yosys synthesis check; then the sanitizer subset (scripts/sanitize.sh --ci:
# the golden models, the host front end and the fuzz corpus under ASan and UBSan, in
# build-asan/). Extra arguments go to the main ctest run (e.g. -L equiv).
# TMU_SKIP_SANITIZE=1 leaves the sanitizer subset out (a quick local run).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}

"$root/scripts/build.sh"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure "$@"
if [[ "${TMU_SKIP_SANITIZE:-0}" != 1 ]]; then
  "$root/scripts/sanitize.sh" --ci
fi
