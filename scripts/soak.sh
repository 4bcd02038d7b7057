#!/usr/bin/env bash
# Soak: long random co-simulation of every block, until a count or a time is reached; stops at
# the first failure and prints the command that reproduces it. Run with --help for the options.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

usage() {
  cat <<'EOF'
Usage: scripts/soak.sh [--count N] [--hours H] [--seed S] [--chunk C] [--out DIR]
                       [--texsim PATH] [--extra 'ARGS'] [BLOCK...]

Repeated random co-simulations `texsim cosim BLOCK --seed <s> --count <c>` (golden vs hls vs
rtl, bit for bit, with the rtl X check), round-robin over the blocks, each run with a fresh
seed and freshly drawn options: input idles and output stalls, and the block's configuration
where texsim offers one (ccc-bilinear lookahead, deflect map latency and jitter, normal-encoder
tables, footprint setup widths, turbulence/material fractal unit, now and then a trilinear or
footprint texture of 512 or 1024 texels a side; the rest of the trilinear and footprint
environment, mipgen's frame, ... is drawn by texsim from the seed).

Stops at the first failing run (a mismatch, an X-check difference, a deadlock, a crash) and
prints the exact command that reproduces it, the seed and texsim's report; exits 1.
On success prints per block the runs, random transactions and seconds; exits 0.

  --count N     random transactions per block (default 20000, or unbounded with --hours)
  --hours H     stop starting new runs after H hours (decimals allowed, e.g. 0.5)
                (with both, whichever is reached first ends the soak)
  --seed S      base seed (default: random, printed); run k uses seed S + k and every option
                draw follows from S, so the same S replays the same soak
  --chunk C     random transactions per run (default 10000)
  --out DIR     logs of failing runs and mismatch waveforms (default: soak_out)
  --texsim PATH the texsim binary (default: ${TMU_BUILD_DIR:-build}/tb/texsim)
  --extra ARGS  more texsim cosim arguments for every run, e.g. --extra '--inject-fault 500'
                (may be repeated; also taken from the environment variable TMU_SOAK_EXTRA)
  BLOCK...      blocks to soak (default: every block `texsim cosim --help` lists)
EOF
}

count="" hours="" base_seed="" chunk=10000 out=soak_out texsim="" blocks=()
extra=()
if [[ -n ${TMU_SOAK_EXTRA:-} ]]; then read -r -a extra <<<"$TMU_SOAK_EXTRA"; fi
die() {
  echo "soak: $*" >&2
  exit 2
}
need() { [[ $# -ge 2 && -n $2 ]] || die "$1 needs a value (--help)"; }
is_uint() { [[ $1 =~ ^[0-9]+$ ]]; }
while (($#)); do
  case $1 in
    -h | --help)
      usage
      exit 0
      ;;
    --count) need "$@"; count=$2; shift 2 ;;
    --hours) need "$@"; hours=$2; shift 2 ;;
    --seed) need "$@"; base_seed=$2; shift 2 ;;
    --chunk) need "$@"; chunk=$2; shift 2 ;;
    --out) need "$@"; out=$2; shift 2 ;;
    --texsim) need "$@"; texsim=$2; shift 2 ;;
    --extra)
      need "$@"
      read -r -a more <<<"$2"
      extra+=("${more[@]}")
      shift 2
      ;;
    -*) die "unknown option $1 (--help)" ;;
    *) blocks+=("$1"); shift ;;
  esac
done

[[ -z $count ]] || is_uint "$count" || die "--count '$count' is not a whole number"
[[ -z $hours ]] || [[ $hours =~ ^[0-9]*\.?[0-9]+$ ]] || die "--hours '$hours' is not a number"
[[ -z $base_seed ]] || is_uint "$base_seed" || die "--seed '$base_seed' is not a whole number"
is_uint "$chunk" && ((chunk > 0)) || die "--chunk '$chunk' is not a positive whole number"
if [[ -z $count && -z $hours ]]; then count=20000; fi

if [[ -z $texsim ]]; then
  build=${TMU_BUILD_DIR:-build}
  [[ $build == /* ]] || build=$root/$build
  texsim=$build/tb/texsim
fi
[[ -x $texsim ]] || die "no texsim at $texsim (build first: scripts/build.sh, or --texsim PATH)"

# The blocks texsim knows: the lines between "Blocks:" and the usage in `cosim --help`.
mapfile -t known < <("$texsim" cosim --help | sed -n '/^Blocks:/,/^Usage:/{/^  [a-z]/s/^  \([^ ]*\).*/\1/p}')
((${#known[@]})) || die "cannot read the block list from '$texsim cosim --help'"
if ((${#blocks[@]} == 0)); then blocks=("${known[@]}"); fi
for b in "${blocks[@]}"; do
  [[ " ${known[*]} " == *" $b "* ]] || die "unknown block '$b' (blocks: ${known[*]})"
done

if [[ -z $base_seed ]]; then base_seed=$(od -An -N4 -tu4 /dev/urandom | tr -d ' '); fi
RANDOM=$base_seed # every option draw below follows from the base seed
mkdir -p "$out"

# pick WORD...: appends one of the words, uniformly, to the array opts. ($RANDOM is read in
# this shell, not in a $(...) subshell, which would reseed it and lose the replay by --seed.)
pick() {
  local words=("$@")
  opts+=("${words[RANDOM % ${#words[@]}]}")
}

# The options of one run of block $1, drawn with $RANDOM, into the array opts.
draw_options() {
  local stalls=(0 0.1 0.25 0.5 0.75)
  opts=(--in-idle)
  pick "${stalls[@]}"
  opts+=(--out-stall)
  pick "${stalls[@]}"
  case $1 in
    ccc-bilinear) if ((RANDOM % 2)); then opts+=(--no-lookahead); fi ;;
    deflect)
      opts+=(--map-latency) && pick 1 2 4 4 8 16 40
      opts+=(--map-jitter) && pick 0 0 1 3 8
      ;;
    normal-encoder) opts+=(--encoder) && pick 7,4,5 7,1,7 ;; # the two Verilated table sets
    turbulence | material) opts+=(--fractal) && pick pipelined shared ;;
    footprint | trilinear)
      # Texture sides from the seed are at most 256; now and then a side of 512 or 1024.
      if ((RANDOM % 8 == 0)); then opts+=(--log2-w) && pick 9 10; fi
      if ((RANDOM % 8 == 0)); then opts+=(--log2-h) && pick 9 10; fi
      # The setup widths the rtl was verilated at (rtl/CMakeLists.txt TMU_FOOTPRINT_VARIANTS).
      if [[ $1 == footprint ]]; then opts+=(--fp-widths) && pick 12,7,8 12,7,8 8,4,5 16,10,12; fi
      ;;
  esac
  return 0
}

declare -A runs=() done_count=() txns=() msecs=()
for b in "${blocks[@]}"; do runs[$b]=0 done_count[$b]=0 txns[$b]=0 msecs[$b]=0; done
now_ms() { echo $((${EPOCHREALTIME/./} / 1000)); }
secs() { printf '%d.%d' $(($1 / 1000)) $(($1 % 1000 / 100)); } # milliseconds as s.d
start=$SECONDS
deadline=""
if [[ -n $hours ]]; then deadline=$((start + $(awk -v h="$hours" 'BEGIN { printf "%d", h * 3600 }'))); fi

summary() {
  printf '%-18s %6s %14s %14s %10s\n' block runs "random txns" "all txns" seconds
  for b in "${blocks[@]}"; do
    printf '%-18s %6d %14d %14d %10s\n' "$b" "${runs[$b]}" "${done_count[$b]}" "${txns[$b]}" \
      "$(secs "${msecs[$b]}")"
  done
}
trap 'echo; echo "soak: interrupted after $((SECONDS - start)) s, base seed $base_seed"; summary; exit 130' INT TERM

echo "soak: ${#blocks[@]} blocks (${blocks[*]}), ${count:-unbounded} random transactions per block${hours:+, at most $hours h}, chunk $chunk, base seed $base_seed"
echo "soak: texsim $texsim${extra[*]:+, extra: ${extra[*]}}"

k=0
while :; do
  progressed=0
  for b in "${blocks[@]}"; do
    if [[ -n $deadline ]] && ((SECONDS >= deadline)); then break 2; fi
    n=$chunk
    if [[ -n $count ]]; then
      left=$((count - done_count[$b]))
      ((left > 0)) || continue
      ((n < left)) || n=$left
    fi
    seed=$((base_seed + k))
    k=$((k + 1))
    draw_options "$b"
    cmd=("$texsim" cosim "$b" --seed "$seed" --count "$n" "${opts[@]}" --wave-dir "$out" "${extra[@]}")
    log=$out/$b.seed$seed.log
    t0=$(now_ms)
    printf '[%s] %-16s run %-4d seed %-10s count %-6d %s ... ' "$(date +%H:%M:%S)" "$b" \
      $((runs[$b] + 1)) "$seed" "$n" "${opts[*]}"
    status=0
    "${cmd[@]}" >"$log" 2>&1 || status=$?
    dt=$(($(now_ms) - t0))
    runs[$b]=$((runs[$b] + 1))
    msecs[$b]=$((msecs[$b] + dt))
    if ((status == 0)) && grep -q '^MATCH: all' "$log"; then
      echo "ok ($(secs $dt) s)"
      done_count[$b]=$((done_count[$b] + n))
      all=$(sed -n 's/^MATCH: all \([0-9]*\) transactions.*/\1/p' "$log")
      txns[$b]=$((txns[$b] + ${all:-0}))
      rm -f "$log"
      progressed=1
      continue
    fi

    echo "FAILED (exit $status, $(secs $dt) s)"
    echo
    echo "---- texsim's report (full log: $log) ----"
    # The mismatch report and verdict; a crash or deadlock shows as the end of the log.
    if grep -q '^FAIL' "$log"; then
      sed -n '/^MISMATCH/,/^coverage:/{/^coverage:/!p}' "$log" | head -60
      grep '^FAIL' "$log"
    else
      tail -n 30 "$log"
    fi
    echo "-------------------------------------------"
    echo
    echo "soak: FAILED: block $b, run ${runs[$b]}, seed $seed (base seed $base_seed), after $((SECONDS - start)) s"
    # texsim's own lines name the engine but not the --extra arguments (an injected fault).
    grep -o '^  reproduce: texsim .*' "$log" | sed "s/^  /soak: texsim's /" || true
    echo "soak: reproduce exactly: $(printf '%q ' "${cmd[@]}")"
    echo
    summary
    exit 1
  done
  ((progressed)) || break
done

echo
echo "soak: PASSED in $((SECONDS - start)) s, base seed $base_seed"
summary
