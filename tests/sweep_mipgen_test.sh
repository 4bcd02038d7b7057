#!/usr/bin/env bash
# `texsim sweep mipgen --no-synth`: it runs and writes its table, the exact carry keeps every
# level within 0.5 of the ideal while carry 0 drifts beyond it, the exact carry's RTL (the one
# verilated) equals golden while carry 0 has no model, the columns are marked by how they were
# obtained, and a malformed setting or a picture of the wrong size is a clear error with exit 2. Usage:
# tests/sweep_mipgen_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

out=$("$texsim" sweep mipgen --no-synth --settings "0;20" --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
exact=$(column 20 "max abs err [model]")
rounded=$(column 0 "max abs err [model]")
[[ -n "$exact" ]] && ! less 0.5 "$exact" && pass "exact carry: largest error $exact <= 0.5" ||
  fail "exact carry: largest error '$exact'"
less 0.5 "$rounded" && pass "carry 0: largest error $rounded > 0.5" ||
  fail "carry 0: largest error '$rounded'"
[[ $(column 20 "FIFO bits [formula]") == 11233 ]] && pass "exact carry: 11233 FIFO bits" ||
  fail "exact carry: FIFO bits '$(column 20 "FIFO bits [formula]")'"
[[ $(column 20 "rtl = golden [sim]") == yes && $(column 0 "rtl = golden [sim]") == "no model" ]] &&
  pass "rtl = golden: carry 20 yes, carry 0 no model" ||
  fail "rtl = golden: carry 20 '$(column 20 "rtl = golden [sim]")', 0 '$(column 0 "rtl = golden [sim]")'"
[[ $(head -1 "$work/table.md") == *"| cells [synth] | logic [synth] | depth [synth] |" ]] &&
  pass "Yosys columns marked synth" || fail "header: $(head -1 "$work/table.md")"

"$texsim" sweep mipgen --no-synth --settings "0;21" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "'21' is not a carry 0..20" "$work/bad.txt" &&
  pass "carry 21: exit 2, says why" || fail "carry 21: exit $code: $(cat "$work/bad.txt")"
oiiotool --pattern constant:color=0.5,0.5,0.5 96x64 3 -o "$work/odd.png" >/dev/null 2>&1
"$texsim" sweep mipgen --no-synth --image "$work/odd.png" > "$work/odd.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "powers of two" "$work/odd.txt" &&
  pass "96 x 64 picture: exit 2, says why" || fail "96 x 64: exit $code: $(cat "$work/odd.txt")"
finish
