#!/usr/bin/env bash
# A bundled scene renders on every engine: ideal, golden, and hls and rtl each checked bit for
# bit against golden, pixel by pixel and unit by unit (outputs, memory requests, counters).
#   tests/render_scenes_test.sh PATH/TO/texsim [SCENE.json ...]   (default: every bundled scene)
# CTest runs one scene per test (render_scene_<name>), so that the scenes spread over the cores.
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
shift
scenes=("$@")
((${#scenes[@]})) || scenes=("$root"/scenes/*.json)
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  for run in "ideal" "golden" "hls --check golden" "rtl --check golden"; do
    # shellcheck disable=SC2086
    if out=$("$texsim" render "$scene" --engine $run --out "$work/$name" --no-progress 2>&1); then
      verdict=$(grep -oE "MATCH[^,]*|MISMATCH[^,]*" <<<"$out" | head -1)
      echo "ok   $name: $run ${verdict:+($verdict)}"
    else
      echo "FAIL $name: $run"; echo "$out" | tail -15
      failures=$((failures + 1))
    fi
  done
done
finish
