#!/usr/bin/env bash
# `texsim sweep clipmap --no-synth`: it runs and writes its tables; a larger tile keeps more
# texels resident and serves fewer samples wayward, with a smaller error against the whole
# pyramid; a faster camera loads more texels a frame; the default tile's RTL equals golden;
# a tile as large as the texture is an error with exit 2. Usage:
# tests/sweep_clipmap_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"

out=$("$texsim" sweep clipmap --no-synth --log2-virtual 9 --settings "5;6" --out "$work" \
  --markdown "$work/table.md" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] && pass "exit 0" || fail "exit $code"
small=$(column "32 per-sample" "wayward % [model]")
large=$(column "64 per-sample" "wayward % [model]")
less "$large" "$small" && pass "wayward: 64-texel tiles $large % < 32-texel tiles $small %" ||
  fail "wayward: 64 '$large', 32 '$small'"
less "$(column "64 per-sample" "mean err [model]")" "$(column "32 per-sample" "mean err [model]")" &&
  pass "error falls with the tile" || fail "error: $(column "64 per-sample" "mean err [model]")"
[[ $(column "64 per-sample" "resident texels [formula]") == 17749 ]] &&
  pass "64-texel tiles of 512: three tiles and a 64 pyramid, 17749 texels resident" ||
  fail "resident: '$(column "64 per-sample" "resident texels [formula]")'"
speed="$work/table_speed.md"
grep -q "^| 4x |" "$speed" && pass "the speed table" || fail "no speed table"
grep -q "| yes |" "$work/table_hardware.md" && pass "rtl = golden at the default tile" ||
  fail "hardware: $(cat "$work/table_hardware.md")"
"$texsim" sweep clipmap --no-synth --log2-virtual 9 --settings "9" --out "$work" > "$work/bad.txt" 2>&1
code=$?
[[ $code -eq 2 ]] && grep -q "is not a log2 tile side" "$work/bad.txt" &&
  pass "a tile as large as the texture: exit 2, says why" || fail "tile 9: exit $code: $(cat "$work/bad.txt")"
finish
