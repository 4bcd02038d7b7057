#!/usr/bin/env bash
# `texsim sweep perlin --no-synth`: it runs, writes its pictures and tables, the wider setting
# has the smaller noise error (what the widths buy), the default widths' RTL (the one verilated)
# equals golden while the other setting has no model, both fractal configurations' cycles per
# sample are measured on their RTL, and a malformed setting or a scene without procedural
# materials is a clear error with exit 2. Usage:
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

for h in "P max [model]" "sums max [model]"; do
  wide=$(column "8,8,8,4" "$h")
  narrow=$(column "4,4,4,0" "$h")
  less "$wide" "$narrow" && pass "$h: 8,8,8,4 ($wide) < 4,4,4,0 ($narrow)" ||
    fail "$h: 8,8,8,4 ($wide) not below 4,4,4,0 ($narrow)"
done
marble=$(column "8,8,8,4" "marble dB [model]")
less 30 "$marble" && pass "marble at the default widths: $marble dB" || fail "marble: '$marble' dB"

[[ $(column "8,8,8,4" "rtl = golden [sim]") == yes && $(column "4,4,4,0" "rtl = golden [sim]") == "no model" ]] &&
  pass "rtl = golden: 8,8,8,4 yes, 4,4,4,0 no model" ||
  fail "rtl = golden: '$(column "8,8,8,4" "rtl = golden [sim]")', '$(column "4,4,4,0" "rtl = golden [sim]")'"
[[ $(head -1 "$work/table.md") == *"| fade bits [formula] |"*"| noise cells [synth] | depth [synth] |" ]] &&
  pass "fade bits marked formula, Yosys columns synth" || fail "header: $(head -1 "$work/table.md")"
cp "$work/table_configs.md" "$work/table.md"
pipelined=$(column tmu_fractal_pipelined "cycles/sample [sim]")
shared=$(column tmu_fractal_shared "cycles/sample [sim]")
[[ $pipelined == 1.00 && $shared == 4.00 ]] && pass "cycles/sample on the RTL: pipelined 1, shared 4" ||
  fail "cycles/sample: pipelined '$pipelined', shared '$shared'"

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
