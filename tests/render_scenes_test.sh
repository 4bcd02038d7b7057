#!/usr/bin/env bash
# A bundled scene renders on every engine: ideal, and hls and rtl each checked bit for bit against
# golden (rendered inside each check), pixel by pixel and unit by unit (outputs, memory requests,
# counters); and at rtl through four TEXRAM chips, checked against golden through them.
# A volume scene (a "volume" section) renders at ideal and golden (against the ideal), on four
# chips bit for bit as on one, and small copies at rtl (32 x 32, one chip and four) and hls
# (16 x 16) through the co-simulated volume unit (render/volume_engine_block.hpp), checked against
# golden resample by resample, counter by counter and run by run of the block, with an injected
# fault caught.
#   tests/render_scenes_test.sh PATH/TO/texsim [SCENE.json ...]   (default: every bundled scene)
# CTest runs one scene per test (render_scene_<name>), so that the scenes spread over the cores.
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
shift
scenes=("$@")
((${#scenes[@]})) || scenes=("$root"/scenes/*.json)
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  # golden renders inside every --check golden run (its fragments and units are the reference),
  # so it is not rendered on its own as well.
  runs=("ideal" "hls --check golden" "rtl --check golden")
  # A fly-over (render/flyover.hpp) has no ideal render: its frames at hls and rtl, and a frame
  # rendered alone equals the same frame of the range (the clip-map is the eye's alone).
  grep -q '"flyover"' "$scene" && runs=("${runs[@]:1}")
  # Through the TEXRAM chips (--chips, render/chip_stage.hpp) too, at rtl against golden through
  # the same chips; its report lists each material's chip, or why a material stays on separate
  # units.
  chips=("rtl --check golden --chips 4")
  grep -q '"flyover"' "$scene" && chips=()  # the clip-map unit's (003), not the TEXRAM's
  # A detail scene (docs/detail.md): only the chip samples detail maps, so hls and rtl run on the
  # chips, each checked bit for bit against golden on the same chips (ideal has its own exact
  # detail sample); without --chips it is refused (exit 2, the field named, no output).
  detail=false
  grep -q '"detail"' "$scene" && detail=true && runs=("ideal" "hls --check golden --chips 4")
  # A video scene (docs/video.md "Rendering a video"): only the chip samples a video map, so hls
  # renders its first two frames on a chip and rtl every frame on four, each checked against
  # golden on the same chips; without --chips it is refused like a detail scene.
  video=false
  grep -q '"video"' "$scene" && video=true && runs=("hls --check golden --chips 1 --frames 0:1")
  volume=false
  # A volume scene (docs/volume.md): ideal, and golden against it; its --chips are slabs (below).
  grep -q '"volume"' "$scene" && volume=true && runs=("ideal" "golden --compare ideal") && chips=()
  # A copy at half the resolution (images resolved against the scene's folder), a quarter of the
  # pixels: hls (the SystemC models, sequential: 3 to 5 times rtl's time) renders it, its
  # models shown equal item by item in the conformance suite and at full size by --long's
  # render_scene_full_NAME (label long); a fly-over's hls run takes its first four frames. And
  # footprint materials on the chips: the full frame takes about 10 s at rtl (grazing), so the
  # chips render the copy too (the full frame in render_scene_full_NAME).
  half="$work/$name-half.json"
  perl -pe 's{"resolution": \[(\d+), (\d+)\]}{sprintf(q("resolution": [%d, %d]), $1 / 2, $2 / 2)}e;
    s{"((?:images|models)/)}{"'"$root"'/scenes/$1}g' "$scene" >"$half"
  if grep -q '"resolution"' "$scene" && cmp -s "$scene" "$half"; then fail "$name: no half-size copy"; fi
  full=${TMU_RENDER_FULL:-0}
  chip_scene=$scene
  grep -q '"footprint"' "$scene" && [[ $full != 1 ]] && chip_scene=$half
  for run in "${runs[@]}" ${chips[@]+"${chips[@]}"}; do
    at=$scene
    [[ $run == "${chips[0]:-}" ]] && at=$chip_scene
    if [[ $run == hls* && $full != 1 ]]; then
      at=$half
      grep -q '"flyover"' "$scene" && at=$scene && run+=" --frames 0-3"
    fi
    # shellcheck disable=SC2086
    if out=$("$texsim" render "$at" --engine $run --out "$work/$name" --no-progress 2>&1); then
      verdict=$(grep -oE "MATCH[^,]*|MISMATCH[^,]*" <<<"$out" | head -1)
      on_chips=""
      [[ $run == "${chips[0]:-}" ]] && ! grep -qE "^    .*: chip [0-9]+, DRF" <<<"$out" &&
        on_chips=", no material on the chips: $(grep -m1 "separate units" <<<"$out" | sed 's/^ *//')"
      echo "ok   $name: $run ${verdict:+($verdict)}$on_chips"
    else
      echo "FAIL $name: $run"; echo "$out" | tail -15
      failures=$((failures + 1))
    fi
  done
  if $detail || $video; then
    key=detail
    $video && key=video
    for refused_run in "rtl --check golden|render with --chips N" "golden|render with --chips N"; do
      run=${refused_run%%|*} why=${refused_run#*|} refused="$work/$name-refused"
      # shellcheck disable=SC2086
      out=$("$texsim" render "$scene" --engine $run --out "$refused" --no-progress 2>&1)
      code=$?
      if [[ $code -eq 2 && $out == *"materials."*".$key: "*"$why"* && ! -e $refused ]]; then
        echo "ok   $name: $run refused (exit 2, no output): $why"
      else
        echo "FAIL $name: $run: exit $code: $out"
        failures=$((failures + 1))
      fi
    done
  fi
  if $volume; then
    chips="$work/$name-chips"
    if "$texsim" render "$scene" --engine golden --chips 4 --out "$chips" --no-progress >/dev/null &&
      cmp -s "$work/$name/render.png" "$chips/render.png"; then
      echo "ok   $name: golden on 4 chips = golden on 1, bit for bit"
    else
      echo "FAIL $name: golden on 4 chips differs from 1 chip"
      failures=$((failures + 1))
    fi
    # The co-simulated unit: small copies of the scene (the frame's rays, not the volume, are
    # what costs), rtl at 32 x 32 on 1 and 4 chips, hls (slower: sequential) at 16 x 16.
    for size in 32 16; do
      sed "s/\"resolution\": \[[0-9]*, [0-9]*\]/\"resolution\": [$size, $size]/" "$scene" \
        >"$work/$name-$size.json"
      grep -q "\"resolution\": \[$size, $size\]" "$work/$name-$size.json" ||
        fail "$name: no $size x $size copy"
    done
    small="$work/$name-32.json"
    for run in "rtl --chips 1:32" "rtl --chips 4:32" "hls --chips 1:16"; do
      size=${run##*:}
      run=${run%:*}
      # shellcheck disable=SC2086
      if out=$("$texsim" render "$work/$name-$size.json" --engine $run --check golden \
        --out "$work/$name-co" --no-progress 2>&1) &&
        grep -q "check: MATCH: .*unit by unit: [0-9]* runs" <<<"$out"; then
        echo "ok   $name ($size x $size): $run --check golden ($(grep -oE "MATCH: [^;]*; unit by unit: [0-9]* runs" <<<"$out"))"
      else
        echo "FAIL $name ($size x $size): $run --check golden"; echo "$out" | tail -15
        failures=$((failures + 1))
      fi
    done
    # The check can fail: one output's bit flipped in the rtl engine is found, exit 1.
    out=$("$texsim" render "$small" --engine rtl --check golden --inject-fault 100 \
      --out "$work/$name-fault" --no-progress 2>&1)
    code=$?
    if [[ $code -eq 1 && $out == *"check: MISMATCH: "*"; 1 of "*" runs of the block differ"* ]]; then
      echo "ok   $name (32 x 32): an injected fault is caught (exit 1)"
    else
      echo "FAIL $name (32 x 32): the injected fault: exit $code"; echo "$out" | tail -15
      failures=$((failures + 1))
    fi
  fi
  if grep -q '"flyover"' "$scene"; then
    alone="$work/$name-alone"
    mkdir -p "$alone" && cp "$work/$name"/terrain-*.tx "$alone/" 2>/dev/null
    if "$texsim" render "$scene" --engine golden --frames 3 --out "$alone" --no-progress >/dev/null &&
      cmp -s "$work/$name/flyover.frame-0003.png" "$alone/flyover.frame-0003.png"; then
      echo "ok   $name: frame 3 alone = frame 3 after frames 0..2"
    else
      echo "FAIL $name: frame 3 alone differs from frame 3 after frames 0..2"
      failures=$((failures + 1))
    fi
    # The footprint unit on the clip-map (filter "footprint", tmu_footprint_clip): frame 3 at rtl,
    # every fragment, probe, load and counter checked against golden.
    sed 's/"filter": "[a-z]*"/"filter": "footprint", "max_probes": 8/' "$scene" >"$alone/fp.json"
    if out=$("$texsim" render "$alone/fp.json" --engine rtl --check golden --frames 3 \
      --out "$alone" --no-progress 2>&1) && grep -q "footprint unit" <<<"$out"; then
      echo "ok   $name: filter footprint, frame 3 ($(grep -oE "MATCH[^,]*" <<<"$out" | head -1))"
    else
      echo "FAIL $name: filter footprint"; echo "$out" | tail -15
      failures=$((failures + 1))
    fi
  fi
done
finish
