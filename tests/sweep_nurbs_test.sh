#!/usr/bin/env bash
# `texsim sweep nurbs --quick`: it runs and writes its three tables; finer thresholds make more
# triangles and a smaller error against the reference; on the wave map the spline grid beats the
# linear one at the same cells (from 4, where the grid resolves the wave) and both improve with
# the cells; the affine rows are exact; every
# composition order's rtl equals golden, and the texture sampled at the vertices (claim 17) is
# the furthest from the reference; a bad threshold is an error with exit 2. Usage:
# tests/sweep_nurbs_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

cell() {  # the cell of row $2 under header $3 in the Markdown table $1
  awk -F'|' -v v="$2" -v h="$3" '
    function trim(x) { gsub(/^ +| +$/, "", x); return x }
    NR == 1 { for (i = 2; i < NF; ++i) if (trim($i) == h) c = i; next }
    c && trim($2) == v { print trim($c) }' "$1"
}

out=$("$texsim" sweep nurbs --quick --requests 20000 --settings "dc=16;dc=2;tc=32;tc=4" \
  --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
[[ -f "$work/table.csv" && -f "$work/table_tau.md" && -f "$work/table_orders.md" ]] &&
  pass "the three tables and the CSV" || fail "missing tables: $(ls "$work")"

# The reference puts every NURBS fragment on the surface: Newton finds a hit for each.
for what in thresholds orders; do
  line=$(grep "reference for the $what" <<<"$out")
  [[ $line =~ \(([0-9]+)\ moved,\ 0\ kept ]] && ((BASH_REMATCH[1] > 1000)) &&
    pass "reference for the $what: ${BASH_REMATCH[1]} fragments on the surface, none kept" ||
    fail "reference for the $what: '$line'"
done

for pair in "DC 16:DC 2" "TC 32:TC 4"; do
  coarse=${pair%%:*} fine=${pair##*:}
  tc=$(column "$coarse" "triangles [model]") tf=$(column "$fine" "triangles [model]")
  less "$tc" "$tf" && pass "$fine makes more triangles than $coarse ($tf > $tc)" ||
    fail "triangles: $coarse '$tc', $fine '$tf'"
  pc=$(column "$coarse" "PSNR dB [model]") pf=$(column "$fine" "PSNR dB [model]")
  less "$pc" "$pf" && pass "$fine is closer to the reference than $coarse ($pf > $pc dB)" ||
    fail "PSNR: $coarse '$pc', $fine '$pf'"
done

tau="$work/table_tau.md"
# At 1 cell the spline's stencil holds two extrapolated nodes (a line): it is the linear grid; at
# 2 cells neither resolves the wave's 1.5 periods.
for cells in 4 8 16; do
  lin=$(cell "$tau" "wave $cells linear" "uv mean texels [model]")
  spl=$(cell "$tau" "wave $cells spline" "uv mean texels [model]")
  less "$spl" "$lin" && pass "wave, $cells cells: spline $spl < linear $lin texels" ||
    fail "wave, $cells cells: spline '$spl', linear '$lin'"
done
for interp in linear spline; do
  e1=$(cell "$tau" "wave 1 $interp" "uv max texels [model]")
  e4=$(cell "$tau" "wave 4 $interp" "uv max texels [model]")
  e16=$(cell "$tau" "wave 16 $interp" "uv max texels [model]")
  less "$e4" "$e1" && less "$e16" "$e4" && pass "wave $interp improves with the cells: $e1 > $e4 > $e16" ||
    fail "wave $interp: 1 '$e1', 4 '$e4', 16 '$e16'"
done
for row in "affine 8 linear" "affine 8 spline"; do
  e=$(cell "$tau" "$row" "uv max texels [model]")
  [[ -n $e ]] && [[ $e == 0 ]] && pass "$row: exact" || fail "$row: '$e'"
done
[[ $(grep -c "| yes |" "$tau") -eq 13 ]] && pass "the tau unit's rtl = golden on every row" ||
  fail "tau rtl: $(cat "$tau")"

orders="$work/table_orders.md"
for order in pc tc texture composed "pc, grid cells x 2"; do
  [[ $(cell "$orders" "$order" "rtl = golden") == yes ]] && pass "order $order: rtl = golden" ||
    fail "order $order: '$(cell "$orders" "$order" "rtl = golden")'"
done
less "$(cell "$orders" pc "PSNR dB [model]")" "$(cell "$orders" "pc, grid cells x 2" "PSNR dB [model]")" &&
  pass "order pc comes closer with twice the tau grid's cells" || fail "orders: $(cat "$orders")"
for order in pc tc; do
  less "$(cell "$orders" texture "PSNR dB [model]")" "$(cell "$orders" $order "PSNR dB [model]")" &&
    pass "the texture sampled at the vertices is further from the reference than order $order" ||
    fail "orders: $(cat "$orders")"
done

"$texsim" sweep nurbs --quick --settings "dc=4;qc=2" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "is not a tessellation row" "$work/bad.txt" &&
  pass "an unknown threshold: exit 2, says why" || fail "qc=2: exit $code: $(cat "$work/bad.txt")"
"$texsim" sweep nurbs --quick --settings "dc=0" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "is not a tessellation row" "$work/bad.txt" &&
  pass "a threshold of 0: exit 2, says why" || fail "dc=0: exit $code: $(cat "$work/bad.txt")"
finish
