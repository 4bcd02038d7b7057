#!/usr/bin/env bash
# `texsim sweep footprint --quick`: it runs, its table has every variant, footprint assembly at
# N max 16 beats isotropic trilinear against the reference, the probes per pixel grow with
# N max, and every column is marked a model's figure (no hardware runs: the cycles are the
# page model's prediction). Wall times are not asserted. `texsim sweep footprint-setup`: the
# default widths' RTL is simulated against golden, a setting without a model is marked
# synth only. Usage: tests/sweep_footprint_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

out=$("$texsim" sweep footprint --quick --out "$work/out" --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"

variants=("trilinear (isotropic)" "footprint N<=2" "footprint N<=4" "footprint N<=8" "footprint N<=16"
  "ideal ellipse axis N<=16" "ideal longer side N<=16" "OIIO aniso 16")
for v in "${variants[@]}"; do
  [[ -n $(column "$v" "PSNR dB [model]") ]] && pass "table has '$v'" || fail "table lacks '$v'"
done

iso=$(column "trilinear (isotropic)" "PSNR dB [model]")
n16=$(column "footprint N<=16" "PSNR dB [model]")
if awk -v a="$n16" -v b="$iso" 'BEGIN { exit !(a > b) }'; then
  pass "PSNR: footprint N<=16 ($n16 dB) > isotropic trilinear ($iso dB)"
else
  fail "PSNR: footprint N<=16 ($n16 dB) is not above isotropic trilinear ($iso dB)"
fi

previous=$(column "trilinear (isotropic)" "probes/px [model]")
for v in "footprint N<=2" "footprint N<=4" "footprint N<=8" "footprint N<=16"; do
  probes=$(column "$v" "probes/px [model]")
  if awk -v a="$probes" -v b="$previous" 'BEGIN { exit !(a > b) }'; then
    pass "probes/px grow: $v $probes > $previous"
  else
    fail "probes/px do not grow: $v $probes, the previous $previous"
  fi
  previous=$probes
done

[[ $(head -1 "$work/table.md") == *"| cycles/px [model] | wall s [model] |" ]] &&
  pass "cycles/px and wall s marked model" || fail "header: $(head -1 "$work/table.md")"

for f in footprint_sweep.png footprint_sweep_error.png footprint_reference.png \
  footprint_footprint_n16.png footprint_footprint_n16_error.png footprint_oiio_aniso16.png; do
  [[ -s "$work/out/$f" ]] && pass "wrote $f" || fail "no $f"
done

out=$("$texsim" sweep footprint-setup --no-synth --settings "12,7,8;8,5,8" --requests 2000 \
  --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "footprint-setup: exit 0" || fail "footprint-setup: exit $code"
[[ $(column "12,7,8" "rtl = golden [sim]") == yes ]] && pass "footprint-setup: 12,7,8 rtl = golden" ||
  fail "footprint-setup: 12,7,8 rtl = golden '$(column "12,7,8" "rtl = golden [sim]")'"
[[ $(column "8,5,8" "rtl = golden [sim]") == "no model" ]] &&
  pass "footprint-setup: 8,5,8 has no model" ||
  fail "footprint-setup: 8,5,8 rtl = golden '$(column "8,5,8" "rtl = golden [sim]")'"
[[ -n $(column "8,5,8" "lambda max err [model]") && -n $(column "8,5,8" "cells [synth]") ]] &&
  pass "footprint-setup: errors marked model, cells synth" ||
  fail "footprint-setup header: $(head -1 "$work/table.md")"

finish
