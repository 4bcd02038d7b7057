#!/usr/bin/env bash
# The main job on the bundled default: set up, build, then render the default scene with the
# Verilated RTL and the golden model, check every fragment bit for bit and compare with the
# ideal model. Output in out/: render.png, the report (render.report.txt / .json), the error
# map against the ideal model. Exits non-zero on any mismatch.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}

"$root/scripts/build.sh"
"$build/tb/texsim" render "$root/scenes/default.json" --engine rtl --check golden --compare ideal --out "$root/out"
