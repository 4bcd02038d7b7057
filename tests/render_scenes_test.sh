#!/usr/bin/env bash
# Every bundled scene renders on every engine: ideal, golden, and hls and rtl each checked
# bit for bit against golden. Usage: tests/render_scenes_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
for scene in "$root"/scenes/*.json; do
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
