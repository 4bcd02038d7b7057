#!/usr/bin/env bash
# `texsim sweep perlin --no-synth`: it runs, writes its pictures and tables, the wider setting
# has the smaller noise error (what the widths buy), and a malformed setting or a scene
# without procedural materials is a clear error with exit 2. Usage:
# tests/sweep_perlin_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

out=$("$texsim" sweep perlin --no-synth --settings "8,8,8,4;4,4,4,0" --requests 20000 \
  --out "$work/out" --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
[[ -s "$work/out/perlin_marble_f8s8b8x4.png" && -s "$work/out/perlin_fire_ideal.png" ]] &&
  pass "pictures written" || fail "no pictures"
[[ -s "$work/table_configs.md" ]] && pass "configurations table written" || fail "no configurations table"

for h in "P max" "sums max"; do
  wide=$(column "8,8,8,4" "$h")
  narrow=$(column "4,4,4,0" "$h")
  less "$wide" "$narrow" && pass "$h: 8,8,8,4 ($wide) < 4,4,4,0 ($narrow)" ||
    fail "$h: 8,8,8,4 ($wide) not below 4,4,4,0 ($narrow)"
done
marble=$(column "8,8,8,4" "marble dB")
less 30 "$marble" && pass "marble at the default widths: $marble dB" || fail "marble: '$marble' dB"

"$texsim" sweep perlin --no-synth --settings "8,9,8,4" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "fade_index_bits" "$work/bad.txt" && pass "bad setting: exit 2, names it" ||
  fail "bad setting: exit $code: $(cat "$work/bad.txt")"
"$texsim" sweep perlin --no-synth --settings "8,8,8,4" --scene "$root/scenes/plain.json" \
  > "$work/plain.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "no procedural material" "$work/plain.txt" &&
  pass "scene without procedural materials: exit 2" || fail "plain: exit $code: $(cat "$work/plain.txt")"

finish
