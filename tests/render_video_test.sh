#!/usr/bin/env bash
# texsim render of a scene with a video map (docs/video.md "Rendering a video"): the bundled
# scenes/video.json at rtl checked against golden on the chips for a range of frames (A:B and
# A-B), interlaced one-plane and progressive four-plane copies, a video from numbered image
# files; the check failing on an injected fault (exit 1); refusals with exit 2, the field named
# and nothing written: no --chips, a missing or wrongly sized file, frames beyond the video.
#   tests/render_video_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
scene="$root/scenes/video.json"
render() { "$texsim" render "$@" --no-progress 2>&1; }
verdict() {  # $1 0 when the check held, $2 what it checks
  if [[ $1 -eq 0 ]]; then pass "$2"; else fail "$2"; return 1; fi
}

out=$(render "$scene" --engine rtl --check golden --chips 1 --frames 1:2 --out "$work/a")
code=$?
if [[ $code -eq 0 && $out == *"check: MATCH: rtl = golden on every frame (2 frames"* &&
  -f $work/a/video.frame-0001.png && -f $work/a/video.frame-0002.png &&
  ! -e $work/a/video.frame-0000.png && -f $work/a/video.report.json ]]; then
  pass "scenes/video.json frames 1:2 at rtl = golden on the chip, two frames written"
else
  fail "scenes/video.json frames 1:2: exit $code"; echo "$out" | tail -20
fi
# Each frame shows its own video frame (the report's "shown" column).
shown=$(grep -E '^ +[0-9]+ screen ' <<<"$out" | awk '{print $1 "=" $3}' | tr '\n' ' ')
[[ $shown == "1=1 2=2 " ]]
verdict $? "render f shows video frame f ($shown)"
# Frame 2 alone (frames 0..1 fed, not rendered) is frame 2 of the range.
if render "$scene" --engine golden --chips 1 --frames 2 --out "$work/alone" >/dev/null &&
  cmp -s "$work/a/video.frame-0002.png" "$work/alone/video.frame-0002.png"; then
  pass "frame 2 alone = frame 2 after frame 1"
else
  fail "frame 2 alone differs"
fi
grep -q "video unit = golden path on every frame: [0-9]* row writes, MATCH" <<<"$out"
verdict $? "the video unit at rtl writes every frame as the golden path does"
grep -q "video unit of screen at rtl: .*check: MATCH against golden" <<<"$out"
verdict $? "the video unit's rtl run = its golden run"
grep -q "host work:" <<<"$out" && grep -q "video timing of screen" <<<"$out"
verdict $? "the golden video timing is named as host work"

for variant in 'interlaced, one plane|"interlaced": true, "planes": 1' \
  'interlaced, four planes|"interlaced": true, "planes": 4' \
  'progressive, one plane|"interlaced": false, "planes": 1'; do
  what=${variant%%|*} keys=${variant#*|}
  perl -pe 's{"interlaced": false, "planes": 4}{'"$keys"'}' "$scene" >"$work/v.json"
  out=$(render "$work/v.json" --engine rtl --check golden --chips 1 --frames 0-1 --out "$work/v")
  code=$?
  [[ $code -eq 0 && $out == *"check: MATCH"* ]]
  verdict $? "$what: rtl = golden, frames 0-1" || echo "$out" | tail -15
done

out=$(render "$scene" --engine golden --check golden --chips 1 --frames 0:0 --inject-fault 10 \
  --out "$work/f")
code=$?
[[ $code -eq 1 && $out == *"MISMATCH"* ]]
verdict $? "an injected fault is caught (exit 1)" || echo "$out" | tail -10

refused() {  # $1 what, $2 the text the message must hold, then render's arguments
  local what=$1 want=$2
  shift 2
  local msg code
  msg=$(render "$@" --out "$work/refused")
  code=$?
  if [[ $code -eq 2 && $msg == *"$want"* && ! -e $work/refused ]]; then
    pass "$what refused (exit 2, no output): $(head -1 <<<"$msg")"
  else
    fail "$what: exit $code: $msg"
  fi
}
refused "no --chips" "materials.screen.video: " "$scene" --engine golden
refused "frames beyond the video" "frames 2..9 of a video of 4 frames" "$scene" --chips 1 --frames 2:9

# Numbered image files.
mkdir -p "$work/clip"
for k in 0 1 2; do
  "$texsim" pattern noise "$work/clip/clip-000$k.png" --width 32 --height 32 --seed $((k + 1)) >/dev/null
done
perl -pe 's{"source": "generated", "pattern": "bars", "size": \[64, 64\]}{"files": "clip/clip-%04d.png"}; s{"frames": 4}{"frames": 3}' \
  "$scene" >"$work/files.json"
out=$(render "$work/files.json" --engine rtl --check golden --chips 1 --out "$work/files-out")
code=$?
[[ $code -eq 0 && $out == *"files "*"clip-%04d.png"*"3 frames"* && -f $work/files-out/video.frame-0002.png ]]
verdict $? "a video of three files renders, rtl = golden" || echo "$out" | tail -15
rm "$work/clip/clip-0001.png"
refused "a missing file" "materials.screen.video.files: frame 1: file not found: " "$work/files.json" --chips 1
"$texsim" pattern noise "$work/clip/clip-0001.png" --width 16 --height 32 >/dev/null
refused "a file of the wrong size" "frame 1: $work/clip/clip-0001.png is 16x32, the video 32x32" \
  "$work/files.json" --chips 1
finish
