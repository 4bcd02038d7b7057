#!/usr/bin/env bash
# The main job on the bundled default: set up, build, then the CCC round trip of the bundled
# image through the golden and the RTL decoder with the bit-exact verdict. Output in out/.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}

"$root/scripts/build.sh"
"$build/tb/texsim" ccc roundtrip "$root/scenes/images/default.png" --out "$root/out"
