#!/usr/bin/env bash
# `texsim sweep deflection --no-synth`: it runs, writes its pictures and table, the finer
# sphere grid has the smaller angle errors (the paper's 7.2: resolution is what reflections
# pay for), the floating angle-table index beats the paper's linear one at the same 128
# entries, every column is marked by how it was obtained (docs/accuracy.md's legend) and the
# units' RTL is simulated against golden where a model of the setting exists, a malformed
# setting is a clear error with exit 2; on a bundled scene (--scene) its
# own golden chain gives the deflection cache the hit rate `texsim render` reports for the
# same scene (two independent paths to one figure), and a scene without a deflection chain
# is a clear error. Usage:
# tests/sweep_deflection_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

out=$("$texsim" sweep deflection --no-synth --settings "8,4,5,10;9,4,5,10;9,1,7,10" \
  --out "$work/out" --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
[[ -s "$work/out/deflection_a9e4m5w10_reflect.png" ]] && pass "pictures written" || fail "no pictures"


for h in "N max deg [model]" "R mean deg [model]"; do
  coarse=$(column "8,4,5,10" "$h")
  fine=$(column "9,4,5,10" "$h")
  less "$fine" "$coarse" && pass "$h: 512x256 ($fine) < 256x128 ($coarse)" ||
    fail "$h: 512x256 ($fine) not below 256x128 ($coarse)"
done
floating=$(column "9,4,5,10" "N max deg [model]")
linear=$(column "9,1,7,10" "N max deg [model]")
less "$floating" "$linear" && pass "floating index ($floating) < linear index ($linear)" ||
  fail "floating index ($floating) not below linear index ($linear)"

header=$(head -1 "$work/table.md")
for h in "table bits [formula]" "cyc/px [formula]" "golden ns/px [model]" "rtl = golden [sim]" \
  "enc cells [synth]" "defl cells [synth]" "coord cells [synth]"; do
  [[ $header == *"| $h |"* ]] && pass "header marks '$h'" || fail "header lacks '$h': $header"
done
# Verilated: the default units and the linear-index encoder (e1m7); A = 8: no encoder port or
# deflection map at that grid, the coordinate generator under Icarus.
for row in "9,4,5,10=enc yes; defl yes; coord yes" "9,1,7,10=enc yes; defl yes; coord yes" \
  "8,4,5,10=enc no model; defl no model; coord yes"; do
  got=$(column "${row%%=*}" "rtl = golden [sim]")
  [[ $got == "${row#*=}"* ]] && pass "${row%%=*}: rtl = golden '$got'" ||
    fail "${row%%=*}: rtl = golden '$got', expected '${row#*=}...'"
done

"$texsim" sweep deflection --no-synth --settings "9,4,5" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "A,E,M,W" "$work/bad.txt" && pass "bad setting: exit 2, names the form" ||
  fail "bad setting: exit $code: $(cat "$work/bad.txt")"

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$texsim" sweep deflection --no-synth --settings "9,4,5,10" --scene "$root/scenes/bumps.json" \
  --markdown "$work/table.md" > "$work/scene.txt" 2>&1 || fail "scene sweep: $(cat "$work/scene.txt")"
sweep_rate=$(column "9,4,5,10" "hit rate [model]")
render_rate=$("$texsim" render "$root/scenes/bumps.json" --engine golden --out "$work/render" \
  --no-progress | sed -nE 's/.*deflection cache.*hit rate ([0-9.]+) %.*/\1/p')
[[ -n "$sweep_rate" && -n "$render_rate" ]] &&
  awk -v a="$sweep_rate" -v b="$render_rate" 'BEGIN { d = 100 * a - b; exit !(d < 0.051 && d > -0.051) }' &&
  pass "bumps.json hit rate: sweep $sweep_rate = render $render_rate %" ||
  fail "bumps.json hit rate: sweep '$sweep_rate', render '$render_rate' %"

"$texsim" sweep deflection --no-synth --settings "9,4,5,10" --scene "$root/scenes/plain.json" \
  > "$work/plain.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "materials" "$work/plain.txt" &&
  pass "scene without a chain: exit 2, names materials" || fail "plain scene: exit $code: $(cat "$work/plain.txt")"

finish
