#!/usr/bin/env bash
# RTL coverage of each block's co-simulation (docs/coverage.md).
#
# Usage: scripts/coverage.sh [--count N] [--out DIR] [--no-build] [BLOCK...]
#
# Configures and builds build-cov (TMU_COVERAGE_BUILD_DIR) with -DTMU_RTL_COVERAGE=ON (only
# texsim, `nice`, TMU_COVERAGE_JOBS jobs, default 2), then runs `texsim cosim BLOCK --engines
# rtl` for every block given (default: all) in the configurations the tests run (texel
# configurations, filters, border modes, fractal configurations, ...: the list `runs` below),
# each with N random items (default 2000) after the directed ones. Every rtl run writes its
# coverage data to OUT/BLOCK/runs/; the script merges them per block (verilator_coverage
# --write OUT/BLOCK/coverage.dat), annotates the sources (OUT/BLOCK/annotated/: each line's
# count, % before a line with a point never hit; a signal's toggles summed over its bits) and
# writes the per-module table OUT/summary.md (lines, branches, toggles: points covered of
# total; scripts/coverage_summary.py) with every point not covered, a signal's bits named,
# in OUT/summary.uncovered.txt. Lines count from the start (initialisation and reset
# included), toggles after reset, and a bit toggled when it rose and fell in one run. OUT
# defaults to build-cov/coverage; the runs' logs are OUT/BLOCK/run<n>.log.
#
# Options:
#   --count N    random items per run (default 2000)
#   --out DIR    where the data, logs, annotated sources and summary go
#   --no-build   use build-cov's texsim as it is
#   -h, --help   this text
#
# Exits 1 when a co-simulation run fails (the others still run; the failing commands are
# listed at the end), 2 on a bad argument.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_COVERAGE_BUILD_DIR:-$root/build-cov}
jobs=${TMU_COVERAGE_JOBS:-2}
count=2000
out=""
do_build=1
blocks=()

usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    -h | --help) usage; exit 0 ;;
    --count) [[ $# -ge 2 && "$2" =~ ^[0-9]+$ ]] || { echo "--count needs a number" >&2; exit 2; }
      count=$2; shift 2 ;;
    --out) [[ $# -ge 2 ]] || { echo "--out needs a directory" >&2; exit 2; }
      out=$2; shift 2 ;;
    --no-build) do_build=0; shift ;;
    -*) echo "unknown option $1 (see --help)" >&2; exit 2 ;;
    *) blocks+=("$1"); shift ;;
  esac
done
out=$(realpath -m "${out:-$build/coverage}")

all_blocks=(ccc ccc-bilinear mipgen trilinear footprint coord-gen cube-map deflect normal-encoder
  specular-combine perlin turbulence material)
[[ ${#blocks[@]} -gt 0 ]] || blocks=("${all_blocks[@]}")
for b in "${blocks[@]}"; do
  [[ " ${all_blocks[*]} " == *" $b "* ]] || {
    echo "unknown block '$b' (blocks: ${all_blocks[*]})" >&2
    exit 2
  }
done

# The runs of a block, one a line: the seed, then texsim cosim options. They follow the
# configurations of tests/<block>_cosim_test.cpp.
runs() {
  local kinds=(luminance index rgba single ccc) filters=(nearest bilinear trilinear)
  local borders=(wrap clamp border mirror) combines=(one constant shade)
  case "$1" in
    ccc)
      echo "1"
      echo "2 --in-idle 0 --out-stall 0"
      echo "3 --in-idle 0.6 --out-stall 0.6" ;;
    ccc-bilinear)
      for seed in 1 2 20; do
        echo "$seed"
        echo "$seed --no-lookahead"
      done
      echo "35 --in-idle 0 --out-stall 0"
      echo "12 --in-idle 0.6 --out-stall 0.6"
      # The random textures are at most 300 texels a side: the largest the unit takes (4096 x
      # 4096) toggles the upper bits of the texel and block coordinates and block addresses.
      echo "5 --texture $textures/noise4096.ccc"
      echo "6 --texture $textures/noise4096.ccc --no-lookahead" ;;
    mipgen)
      # The formats of seeds 1..7 (8 x 16, 64 x 32 interlaced, 2 x 1024, ...), then the
      # directed formats of the test: 1 x 1, 1024-texel lines, one texel wide, ...
      for seed in 1 2 3 4 5 6 7; do echo "$seed"; done
      for f in 0,0,0 0,0,1 10,0,0 10,0,1 0,6,1 0,1,0 1,1,1 6,1,1 5,2,1 2,5,0 4,4,1; do
        IFS=, read -r w h i <<<"$f"
        echo "11 --mip-log2-w $w --mip-log2-h $h --mip-interlaced $i"
      done
      echo "21 --mip-log2-w 5 --mip-log2-h 3 --mip-interlaced 1 --in-idle 0.6 --out-stall 0.6"
      echo "3 --mip-log2-w 4 --mip-log2-h 5 --mip-interlaced 1 --in-idle 0 --out-stall 0"
      # One random 1024 x 1024 frame, interlaced: the upper bits of the bank addresses.
      echo "8 --mip-log2-w 10 --mip-log2-h 10 --mip-interlaced 1 --no-directed --count 1"
      echo "9 --mip-log2-w 10 --mip-log2-h 9 --mip-interlaced 0 --no-directed --count 1" ;;
    trilinear)
      # Every texel configuration x filter, the borders of u and v, the combine and the
      # texture's shape varying from run to run (as EveryKindFilterAndBorder).
      local seed=100 k f
      for k in 0 1 2 3 4; do
        for f in 0 1 2; do
          seed=$((seed + 1))
          echo "$seed --config ${kinds[k]} --filter ${filters[f]}" \
            "--border-u ${borders[(k + f) % 4]} --border-v ${borders[(k + 2 * f + 1) % 4]}" \
            "--combine ${combines[seed % 3]} --log2-w $((seed % 7)) --log2-h $(((seed / 7) % 7))"
        done
      done
      local c
      for c in r g b a; do echo "12 --config single --channel $c --filter bilinear"; done
      echo "41 --config rgba --filter trilinear --border-u mirror --border-v wrap --log2-w 10" \
        "--log2-h 10 --pattern smooth"
      # 1024 x 512: the level offsets of a large texture whose sides' log2 sum is odd.
      echo "42 --config luminance --filter trilinear --log2-w 10 --log2-h 9 --pattern smooth"
      echo "5 --config luminance --filter trilinear --in-idle 0 --out-stall 0"
      echo "6 --config rgba --filter trilinear --in-idle 0.6 --out-stall 0.6"
      # The width variants verilated besides 8,8,8.
      echo "7 --config rgba --filter trilinear --widths 6,6,6"
      echo "8 --config luminance --filter trilinear --widths 4,4,4" ;;
    footprint)
      # Every maximum probe count with both q rules, the border modes, texel configuration,
      # filter and combine varying (as EveryConfiguration), then the other setup widths.
      local seed=500 m rule
      for m in 1 2 4 8 16; do
        for rule in heights sides; do
          seed=$((seed + 1))
          echo "$seed --max-probes $m --q-rule $rule --border-u ${borders[seed % 4]}" \
            "--border-v ${borders[(seed / 4 + seed) % 4]} --config ${kinds[seed % 5]}" \
            "--filter $( ((seed % 3 == 0)) && echo bilinear || echo trilinear)" \
            "--combine $( ((seed % 2 == 0)) && echo one || echo shade)" \
            "--log2-w $((4 + seed % 4)) --log2-h $((4 + (seed / 2) % 4))"
        done
      done
      # The texel configuration the loop above leaves out (single channel A), and the largest
      # texture (the bank addresses' upper bits).
      echo "37 --config single --channel a --filter trilinear --max-probes 4"
      echo "41 --config rgba --log2-w 10 --log2-h 10 --pattern smooth --max-probes 16"
      echo "42 --config luminance --log2-w 9 --log2-h 10 --pattern smooth --max-probes 8"
      # The setup's other widths (rtl/CMakeLists.txt: TMU_FOOTPRINT_VARIANTS), both q rules.
      for rule in heights sides; do
        echo "36 --fp-widths 8,4,5 --max-probes 16 --q-rule $rule"
        echo "43 --fp-widths 16,10,12 --max-probes 16 --q-rule $rule"
      done
      echo "5 --max-probes 16 --in-idle 0 --out-stall 0"
      echo "9 --max-probes 8 --in-idle 0.6 --out-stall 0.6" ;;
    deflect)
      echo "41 --map-latency 4"
      echo "42 --map-latency 1"
      echo "43 --map-latency 2 --map-jitter 5"
      echo "44 --in-idle 0 --out-stall 0"
      echo "45 --map-latency 9 --map-jitter 9 --in-idle 0.6 --out-stall 0.6" ;;
    normal-encoder)
      echo "1"
      echo "23 --encoder 7,1,7"
      echo "2 --in-idle 0 --out-stall 0"
      echo "3 --in-idle 0.6 --out-stall 0.6" ;;
    turbulence | material)
      local fr
      for fr in pipelined shared; do
        echo "1 --fractal $fr"
        echo "2 --fractal $fr --in-idle 0 --out-stall 0"
        echo "3 --fractal $fr --in-idle 0.6 --out-stall 0.6"
      done ;;
    *)
      echo "1"
      echo "2 --in-idle 0 --out-stall 0"
      echo "3 --in-idle 0.6 --out-stall 0.6" ;;
  esac
}

start=$(date +%s)
if [[ $do_build -eq 1 ]]; then
  if ! grep -qs '^TMU_RTL_COVERAGE:BOOL=ON' "$build/CMakeCache.txt"; then
    cmake -S "$root" -B "$build" -G Ninja -DTMU_RTL_COVERAGE=ON
  fi
  nice -n 10 cmake --build "$build" -j "$jobs" --target texsim
fi
texsim=$build/tb/texsim
[[ -x "$texsim" ]] || { echo "no $texsim: build it first (without --no-build)" >&2; exit 2; }
built=$(date +%s)

# The largest texture of the CCC low-cost unit (MaxTexSize = 4096 texels a side), made once.
textures=$out/textures
if [[ " ${blocks[*]} " == *" ccc-bilinear "* && ! -s "$textures/noise4096.ccc" ]]; then
  mkdir -p "$textures"
  "$texsim" pattern noise "$textures/noise4096.png" --width 4096 --height 4096 >/dev/null
  "$texsim" ccc encode "$textures/noise4096.png" "$textures/noise4096.ccc" >/dev/null
  rm "$textures/noise4096.png"
fi

failed=()
merged=()
for block in "${blocks[@]}"; do
  dir=$out/$block
  rm -rf "$dir"
  mkdir -p "$dir/runs"
  n=0
  while read -r seed args; do
    n=$((n + 1))
    # --no-x-check: the X check's second rtl run repeats the stimulus with other initial
    # values, which coverage does not count (toggles start after reset).
    read -ra extra <<<"$args"
    # A run that names its own --count (a whole 1024 x 1024 frame, ...) keeps it.
    counted=(--count "$count")
    [[ " $args " == *" --count "* ]] && counted=()
    cmd=("$texsim" cosim "$block" --seed "$seed" "${counted[@]}" --engines rtl --no-x-check
      --wave-dir "$dir/waves" "${extra[@]}")
    if TMU_COVERAGE_DIR=$dir/runs "${cmd[@]}" >"$dir/run$n.log" 2>&1; then
      echo "$block run $n: MATCH (seed $seed $args)"
    else
      echo "$block run $n: FAILED: ${cmd[*]} (log $dir/run$n.log)"
      failed+=("${cmd[*]}")
    fi
  done < <(runs "$block")
  # Each rtl run wrote <pid>_<n>_reset.dat (initialisation and reset) and <pid>_<n>.dat (the
  # run after reset). The reset part counts for lines and branches only: its toggles are the
  # flops' random initial values changing into reset. A bit toggled in a run when it changed
  # at least twice there (it rose and fell): one change may be a flop's random initial value
  # replaced by a constant, so a count of 1 becomes 0 before the runs are merged.
  shopt -s nullglob
  for f in "$dir"/runs/*_reset.dat; do
    grep -av $'\x02v_toggle/' "$f" >"${f%_reset.dat}_init.dat" || true
    rm "$f"
  done
  for f in "$dir"/runs/*.dat; do
    [[ "$f" == *_init.dat ]] && continue
    awk -v tog=$'\x02v_toggle/' 'index($0, tog) && $NF == 1 { sub(/ 1$/, " 0") } { print }' \
      "$f" >"$f.tmp"
    mv "$f.tmp" "$f"
  done
  data=("$dir"/runs/*.dat)
  shopt -u nullglob
  if [[ ${#data[@]} -eq 0 ]]; then
    echo "$block: no coverage data (is $build configured with -DTMU_RTL_COVERAGE=ON?)" >&2
    failed+=("$block: no coverage data")
    continue
  fi
  verilator_coverage --write "$dir/coverage.dat" "${data[@]}" >/dev/null
  verilator_coverage --annotate "$dir/annotated" --annotate-min 1 "$dir/coverage.dat" \
    >"$dir/annotate.log"
  merged+=("$block=$dir/coverage.dat")
done

if [[ ${#merged[@]} -gt 0 ]]; then
  (cd "$root" && python3 "$root/scripts/coverage_summary.py" "$out/summary.md" "${merged[@]}")
fi
end=$(date +%s)
echo "coverage: ${#blocks[@]} blocks, count $count: build $((built - start)) s, runs and" \
  "merge $((end - built)) s"
if [[ ${#merged[@]} -gt 0 ]]; then
  echo "table $out/summary.md, not covered $out/summary.uncovered.txt, annotated sources" \
    "$out/BLOCK/annotated/"
fi
if [[ ${#failed[@]} -gt 0 ]]; then
  printf 'FAILED: %s\n' "${failed[@]}" >&2
  exit 1
fi
