#!/usr/bin/env bash
# `texsim sweep volume --quick`: it runs and writes its tables; the ideal against itself has no
# error and an infinite PSNR; the value's and the gradient's errors fall as the weight bits
# grow; raw mode reads eight times a resample; the patent's two data sets on four chips come out
# near its figures at step 1 (simulated time from the page model's counts, not wall-clock); a
# bad setting is exit 2 with the reason. Usage: tests/sweep_volume_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

# --no-synth: Yosys on tmu_volume is minutes of a fresh build (the long test
# rtl_synth_figures_tmu_volume covers it); the sweep then leaves its cells and depth out.
out=$("$texsim" sweep volume --quick --no-synth --settings "8,1;6,1;4,1;2,1" \
  --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
[[ $(column "ideal,1" "PSNR [model]") == inf && $(column "ideal,1" "value max [model]") == 0.000 ]] &&
  pass "the ideal against itself: no error, PSNR inf" ||
  fail "ideal row: PSNR '$(column "ideal,1" "PSNR [model]")'"
for what in "value RMS [model]" "grad RMS [model]"; do
  e8=$(column "8,1" "$what") e6=$(column "6,1" "$what") e4=$(column "4,1" "$what")
  e2=$(column "2,1" "$what")
  less "$e8" "$e6" && less "$e6" "$e4" && less "$e4" "$e2" &&
    pass "$what falls with W: $e2 > $e4 > $e6 > $e8" || fail "$what: W 2..8: $e2 $e4 $e6 $e8"
done
less 35 "$(column "8,1" "PSNR [model]")" && pass "W = 8: PSNR $(column "8,1" "PSNR [model]") dB" ||
  fail "W = 8: PSNR '$(column "8,1" "PSNR [model]")'"
[[ $(column "8,1" "cells [synth]") == - ]] && pass "--no-synth: no cells" ||
  fail "--no-synth: cells '$(column "8,1" "cells [synth]")'"
[[ $(column "8,1" "acc/res [model]") == 8.00 ]] && pass "raw mode: 8 accesses a resample" ||
  fail "accesses a resample: '$(column "8,1" "acc/res [model]")'"

cp "$work/table_patent.md" "$work/table.md"
rgba=$(column "RGBA 64x128x128, 1" "time [model]") raw=$(column "raw 256x128x128, 1" "time [model]")
[[ $(column "RGBA 64x128x128, 1" "acc/res [model]") == 2.00 &&
  $(column "raw 256x128x128, 1" "acc/res [model]") == 8.00 ]] &&
  pass "the data sets: 2 and 8 accesses a resample" || fail "data sets: $(cat "$work/table.md")"
less 60 "${rgba% ms}" && less "${rgba% ms}" 80 && pass "RGBA set on four chips: $rgba (patent: about 70 ms)" ||
  fail "RGBA set: '$rgba'"
less 0.25 "${raw% s}" && less "${raw% s}" 0.35 && pass "raw set on four chips: $raw (patent: about 0.28 s)" ||
  fail "raw set: '$raw'"

"$texsim" sweep volume --quick --settings "9,1" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "W is 1..8" "$work/bad.txt" && pass "W = 9: exit 2, says why" ||
  fail "W = 9: exit $code: $(cat "$work/bad.txt")"
finish
