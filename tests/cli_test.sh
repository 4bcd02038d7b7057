#!/usr/bin/env bash
# texsim from the user's side: help on every command, clear errors with a non-zero exit for
# bad files and arguments, and no output file left behind (or clobbered) by a failed run.
# Usage: tests/cli_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
cd "$work"

# expect NAME EXIT_CODE PATTERN -- command...: the exit code and a pattern in stdout+stderr.
expect() {
  local name=$1 code=$2 pattern=$3
  shift 4
  local out
  out=$("$@" 2>&1)
  local got=$?
  if [[ $got -ne $code ]]; then
    fail "$name: exit $got, expected $code"; echo "$out" | head -20; return
  fi
  if ! grep -qE -- "$pattern" <<<"$out"; then
    fail "$name: output lacks /$pattern/"; echo "$out" | head -20; return
  fi
  pass "$name"
}

# run NAME -- command...: a set-up run whose outputs later checks use; it must exit 0 (a
# failure here would otherwise show only as a confusing failure further on, or not at all).
run() {
  local name=$1
  shift 2
  local out
  out=$("$@" 2>&1)
  local got=$?
  if [[ $got -ne 0 ]]; then
    fail "$name: exit $got, expected 0"; echo "$out" | head -20; return
  fi
  pass "$name"
}

for cmd in "" "cosim" "ccc" "ccc encode" "ccc decode" "ccc roundtrip" "formats" "pattern" "sample" "mipgen" \
  "sweep" "render" "merge" "levels" "terrain" "nurbs" "drf" "volume-gen"; do
  # shellcheck disable=SC2086
  expect "help: texsim $cmd" 0 "Usage" -- "$texsim" $cmd --help
done

# The model-level table: every level of the noise unit, each equal to golden, as text, Markdown
# and CSV; an unknown block is a clear error.
expect "levels: every model level of the noise unit equals golden" 0 \
  "noise +rtl-fst +300 .* yes +FST of every signal" -- "$texsim" levels noise --count 300 --markdown lv.md
[[ -s lv.md && $(head -1 lv.csv) == '"block","level",'* ]] && pass "levels: Markdown and CSV" ||
  fail "levels: lv.md / lv.csv missing or malformed"
expect "levels: a wrong output is caught" 1 "noise +rtl +300 .* NO: output 7 field p" -- \
  "$texsim" levels perlin --count 300 --inject-fault 7
expect "levels: an unknown block" 2 "nosuch" -- "$texsim" levels nosuch

run "pattern: a 37x21 image" -- "$texsim" pattern default img.png --width 37 --height 21
expect "encode an odd-sized image" 0 "PSNR .* dB.*bits per texel" -- "$texsim" ccc encode img.png img.ccc
expect "decode through rtl, checked against golden" 0 "MATCH: golden = rtl, all 777 texels" -- \
  "$texsim" ccc decode img.ccc dec.png --engine rtl --check golden
expect "decode through hls" 0 "wrote dec_hls.png" -- "$texsim" ccc decode img.ccc dec_hls.png --engine hls
cmp -s <("$texsim" formats --sv-package) "$root/rtl/tmu_pkg.sv" && pass "formats --sv-package = rtl/tmu_pkg.sv" \
  || fail "formats --sv-package differs from rtl/tmu_pkg.sv"

# Bad input: a message naming the file and field, non-zero exit, nothing written.
expect "missing .ccc" 2 "nope.ccc" -- "$texsim" ccc decode nope.ccc x.png
printf 'CCC1\x04\x00\x00\x00' >short.ccc
expect "truncated .ccc names the header" 2 "short.ccc: header:" -- "$texsim" ccc decode short.ccc short.png
[[ ! -e short.png ]] && pass "no output after a failed decode" || fail "short.png written by a failed decode"
head -c 100 img.ccc >trunc.ccc
head -c 20000 /dev/zero >>trunc.ccc
cp img.ccc bad_magic.ccc
printf 'XXXX' | dd of=bad_magic.ccc bs=1 conv=notrunc 2>/dev/null
expect "wrong magic names the field" 2 "bad_magic.ccc: magic: not a CCC1 file" -- "$texsim" ccc decode bad_magic.ccc m.png
expect "wrong size names the blocks" 2 "trunc.ccc: blocks:" -- "$texsim" ccc decode trunc.ccc t.png
echo "not an image" >fake.png
expect "corrupt image names the file" 2 "fake.png" -- "$texsim" ccc encode fake.png fake.ccc
[[ ! -e fake.ccc ]] && pass "no .ccc after a failed encode" || fail "fake.ccc written by a failed encode"
echo keep >keep.png
expect "a failed decode onto an existing file" 2 "bad_magic.ccc" -- "$texsim" ccc decode bad_magic.ccc keep.png
[[ $(cat keep.png) == keep ]] && pass "existing output untouched by a failed run" || fail "keep.png clobbered"
expect "unwritable output directory" 2 "no_such_dir/x.ccc" -- "$texsim" ccc encode img.png no_such_dir/x.ccc
expect "unknown block lists the blocks" 2 "unknown block 'nope' \(blocks: " -- "$texsim" cosim nope
expect "bad engine" 2 "engine" -- "$texsim" ccc decode img.ccc x.png --engine fast
expect "out-of-range stall probability" 2 "in-idle" -- "$texsim" cosim ccc_decoder --in-idle 2

# Co-simulation verdicts and exit codes.
expect "cosim ccc_decoder matches" 0 "MATCH: all .* transactions bit-exact, golden = hls = rtl" -- \
  "$texsim" cosim ccc_decoder --count 3000 --seed 5
expect "a block's old name runs the block" 0 "cosim ccc_decoder: seed 5" -- \
  "$texsim" cosim ccc --count 300 --seed 5
expect "cosim with an injected fault fails" 1 "reproduce: texsim cosim ccc_decoder --seed 5" -- \
  "$texsim" cosim ccc_decoder --count 3000 --seed 5 --inject-fault 100 --wave-dir waves
[[ -s waves/ccc_decoder_mismatch.fst && -s waves/ccc_decoder_mismatch.gtkw ]] && pass "mismatch waveform written" \
  || fail "no mismatch waveform"
run "save a vector file" -- "$texsim" cosim ccc_decoder --count 500 --seed 8 --save-vectors vec.csv
[[ -s vec.csv ]] && pass "vector file written" || fail "no vec.csv"
expect "replay a saved vector file" 0 "MATCH" -- "$texsim" cosim ccc_decoder --vectors vec.csv
printf 'op,block\n0,0x1ffffffff\n' >bad.csv
expect "bad vector file names line and field" 2 "bad.csv: line 2: block" -- "$texsim" cosim ccc_decoder --vectors bad.csv

# The TEXRAM unit: sample request files, mipmap generation.
run "pattern: a 64x32 texture" -- "$texsim" pattern smooth tex.png --width 64 --height 32
printf 'u,v,lambda,shade\n10.5,3.25,0.5,0xFFFFFFFF\n-40,1000,-1,0x80FF80FF\n5,5,30,0xFFFFFFFF\n' >req.csv
expect "sample golden checked against ideal" 0 "error against ideal: max" -- \
  "$texsim" sample --texture tex.png --requests req.csv --out s.csv --check ideal
[[ $(head -1 s.csv) == "r,g,b,a" && $(wc -l <s.csv) -eq 4 ]] && pass "sample writes r,g,b,a per request" \
  || fail "sample output"
expect "sample through rtl, checked bit for bit against golden" 0 "MATCH: rtl = golden, all 3 results" -- \
  "$texsim" sample --texture tex.png --requests req.csv --out s_rtl.csv --engine rtl --check golden --config index
printf '1,2\n' >short.csv
expect "request with too few values names the line" 2 "short.csv: line 1" -- \
  "$texsim" sample --texture tex.png --requests short.csv --out x.csv
printf 'u,v,lambda\n1,2,40\n' >far.csv
expect "lambda beyond the port names the column" 2 "far.csv: line 2: lambda" -- \
  "$texsim" sample --texture tex.png --requests far.csv --out x.csv
printf 'u,v,lambda,u\n1,2,3,4\n' >dup.csv
expect "a request header naming a column twice" 2 "dup.csv: line 1: header: duplicate column 'u'" -- \
  "$texsim" sample --texture tex.png --requests dup.csv --out x.csv
expect "a texture that is not a power of two" 2 "img.png: size" -- \
  "$texsim" sample --texture img.png --requests req.csv --out x.csv
[[ ! -e x.csv ]] && pass "no result file after failed samples" || fail "x.csv written by a failed sample"
expect "mipgen through rtl, checked against golden" 0 "MATCH" -- \
  "$texsim" mipgen tex.png levels --engine rtl --check golden
[[ -s levels/level_0.png && -s levels/level_6.png ]] && pass "mipgen writes every level" || fail "mipgen levels"
expect "mipgen of a size that is not a power of two" 2 "img.png: size" -- "$texsim" mipgen img.png lv

# The renderer: verdicts, the exit code of a mismatch, scene errors, bands.
expect "render rtl checked against golden, compared with ideal" 0 "MATCH: rtl = golden.*" -- \
  "$texsim" render "$root/scenes/plain.json" --engine rtl --check golden --compare ideal --out r --no-progress
[[ -s r/render.png && -s r/render.report.json && -s r/render.report.txt && -s r/render.compare-error.png ]] \
  && pass "render writes the image, the report and the error map" || fail "render outputs"
expect "render --check with an altered result exits 1" 1 "MISMATCH" -- \
  "$texsim" render "$root/scenes/plain.json" --engine rtl --check golden --inject-fault 7 --out rf --no-progress
[[ -s rf/render.check-diff.png ]] && pass "mismatch heat map written" || fail "no render.check-diff.png"
expect "render --compare takes only ideal" 2 "compare" -- \
  "$texsim" render "$root/scenes/plain.json" --compare golden --out rx
expect "render a band out of range" 2 "tile" -- "$texsim" render "$root/scenes/plain.json" --tile 3/2 --out rx
sed 's/"fov"/"fovv"/' "$root/scenes/plain.json" >typo.json
expect "unknown scene key names file and field path" 2 "typo.json: camera.fovv" -- "$texsim" render typo.json --out rx
printf '{ "camera": ' >cut.json
expect "truncated scene names the file" 2 "cut.json" -- "$texsim" render cut.json --out rx
sed 's/"eye": \[600, 600, 60\]/"eye": [600, 600, -1]/' "$root/scenes/flyover.json" >under.json
expect "a fly-over's eye under the ground names the keyframe" 2 "under.json: flyover.path\[0\].eye" -- \
  "$texsim" render under.json --out rx
sed 's/"filter": "trilinear"/"filter": "footprint", "max_probes": 6/' "$root/scenes/flyover.json" >probes.json
expect "a fly-over's probe count that is not a power of two" 2 "probes.json: flyover.max_probes" -- \
  "$texsim" render probes.json --out rx
sed 's/"filter": "trilinear"/"filter": "trilinear", "max_probes": 8/' "$root/scenes/flyover.json" >probes2.json
expect "max_probes without the footprint filter" 2 'probes2.json: flyover.max_probes.*footprint' -- \
  "$texsim" render probes2.json --out rx
sed 's|"terrain": {"log2": 11, "seed": 3}|"file": "img.png"|' "$root/scenes/flyover.json" >given.json
expect "a fly-over's file that is not a square power of two names the field" 2 \
  'given.json: flyover.file: .*img.png: 37 x 21' -- "$texsim" render given.json --out rx
expect "fly-over frames beyond the path" 2 "frames 5..40 of a path of 12" -- \
  "$texsim" render "$root/scenes/flyover.json" --frames 5-40 --out rx
expect "a fly-over has no ideal render" 2 "golden, hls or rtl" -- \
  "$texsim" render "$root/scenes/flyover.json" --engine ideal --out rx
expect "--frames is for fly-overs" 2 "fly-over" -- \
  "$texsim" render "$root/scenes/plain.json" --frames 1 --out rx
# Volume scenes (docs/volume.md): errors name the file, the field and the reason; nothing is
# written (vx must not appear); a fault is injected only into the hls or rtl unit's output.
sed 's/"weight_bits": 8/"weight_bits": 9/' "$root/scenes/volume_marschner_lobb.json" >wbits.json
expect "a volume scene's weight bits out of range" 2 "wbits.json: volume.weight_bits: must be an integer in 1..8" -- \
  "$texsim" render wbits.json --out vx
sed 's/"step": 1/"stepp": 1/' "$root/scenes/volume_sphere.json" >vkey.json
expect "an unknown volume key" 2 "vkey.json: volume.stepp: unknown key" -- "$texsim" render vkey.json --out vx
expect "too many chips for the planes" 2 "--chips: 40 chips for 64 planes along x" -- \
  "$texsim" render "$root/scenes/volume_sphere.json" --chips 40 --out vx
expect "a volume scene's fault at golden" 2 \
  "--inject-fault: a volume scene's fault goes into an hls or rtl engine's output" -- \
  "$texsim" render "$root/scenes/volume_sphere.json" --engine golden --inject-fault 3 --out vx
[[ ! -e vx ]] && pass "no output directory after the failed volume renders" || fail "vx was written"
expect "volume-gen: the engine part as a raw file" 0 "wrote engine.raw: 16 x 16 x 16 raw 8-bit voxels" -- \
  "$texsim" volume-gen engine engine.raw --size 16,16,16
[[ $(stat -c %s engine.raw) -eq 4096 ]] && pass "volume-gen: 4096 bytes" || fail "engine.raw size"
# The TEXRAM chip (000 §14): a scene's DRF programs and memory map; too few chips is an error
# naming the material that did not fit.
expect "texsim drf prints the chain of a linked material" 0 \
  "varnish +chip 1, DRF 1 \| 2 -> 3 -> 4 -> 7" -- "$texsim" drf "$root/scenes/reflect.json"
expect "texsim drf --writes lists the write port's words" 0 "write port \(drf, field, value\)" -- \
  "$texsim" drf "$root/scenes/default.json" --writes
expect "texsim drf: a second palette needs a second chip" 2 \
  "materials.label: does not fit in the 1 chip given; chip 0: its CLUT holds another palette" -- \
  "$texsim" drf "$root/scenes/default.json" --chips 1
# NURBS (004): the tessellation report and its wireframe; a bad knot vector names the patch.
expect "texsim nurbs reports each patch's steps" 0 "patch   8: MC/DC .* steps" -- \
  "$texsim" nurbs "$root/scenes/nurbs_freeform.json" --dc 8 --wireframe wire.png
[[ -s wire.png ]] && pass "the wireframe is written" || fail "no wire.png"
expect "texsim nurbs: a threshold must be positive" 2 "--dc" -- \
  "$texsim" nurbs "$root/scenes/nurbs.json" --dc 0
sed -e 's/"knots_s": \[0, 0, 0, 0, 1, 1, 1, 1\]/"knots_s": [0, 0, 1, 0, 1, 1, 1, 1]/' \
  -e "s|images/default.png|$root/scenes/images/default.png|" "$root/scenes/nurbs_freeform.json" >knots.json
expect "a knot vector out of order names the patch" 2 \
  'knots.json: objects\[0\].patches\[0\]: knots_s: not non-decreasing' -- \
  "$texsim" render knots.json --out rx
[[ ! -e rx ]] && pass "no output after failed renders" || fail "rx written by a failed render"
for band in 0 1 2; do
  run "render band $band/3" -- "$texsim" render "$root/scenes/plain.json" --tile $band/3 --out bands --no-progress
done
expect "merge three bands" 0 "merged 3 bands" -- "$texsim" merge whole.png bands/render.tile-{2,0,1}-of-3.png
run "render the whole frame" -- "$texsim" render "$root/scenes/plain.json" --out whole --no-progress
# idiff exits 0 only when every pixel is equal (8-bit values: its 1e-6 threshold is exactness).
idiff -q whole.png whole/render.png >/dev/null && pass "merged bands equal the whole frame" \
  || fail "merged bands differ from the whole frame"
! idiff -q whole.png bands/render.tile-0-of-3.png >/dev/null 2>&1 && pass "idiff tells different images apart" \
  || fail "idiff cannot fail"

finish
