#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (fuzz/README.md): builds the clang fuzz targets
# (fuzz/CMakeLists.txt with TMU_FUZZ=ON: libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer),
# runs each target for a bounded time on a copy of its corpus, then merges the inputs that reach
# code the corpus does not back into fuzz/corpus/<target>/ (libFuzzer -merge=1 on edge coverage),
# those that reach the most first, keeping the corpus at most --max-corpus files.
#
#   scripts/fuzz.sh [--seconds N] [--max-corpus N] [--no-build] [--no-merge] [TARGET...]
#
#   --seconds N      run each target N seconds (default 60), one target after the other
#   --max-corpus N   files a target's corpus may grow to by merging (default 50)
#   --no-build       use the fuzzers already built (e.g. a second run beside a first one)
#   --no-merge       leave fuzz/corpus/ as it is
#   TARGET           ccc, scene, volume_scene, trace, request (default: all five)
#
# Prints per target the runs, executions per second, coverage, new corpus files and any finding
# (crash, sanitizer report, broken check, uncaught exception, timeout, out of memory) with the
# commands that reproduce it; exits 1 on a finding, 2 on a usage or build error.
# TMU_FUZZ_BUILD_DIR chooses the build directory (default: build-fuzz-clang/); the runs' working
# corpora, logs and findings go to its run/<target>/. Needs clang and libclang-rt-14-dev
# (scripts/setup.sh installs them).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_FUZZ_BUILD_DIR:-$root/build-fuzz-clang}
all_targets=(ccc scene volume_scene trace request)

seconds=60
max_corpus=50
do_build=1
do_merge=1
targets=()
while (($#)); do
  case $1 in
    --seconds)
      [[ $# -ge 2 && $2 =~ ^[0-9]+$ && $2 -gt 0 ]] || { echo "fuzz: --seconds needs a positive integer" >&2; exit 2; }
      seconds=$2
      shift
      ;;
    --max-corpus)
      [[ $# -ge 2 && $2 =~ ^[0-9]+$ ]] || { echo "fuzz: --max-corpus needs a number" >&2; exit 2; }
      max_corpus=$2
      shift
      ;;
    --no-build) do_build=0 ;;
    --no-merge) do_merge=0 ;;
    -h | --help)
      awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"
      exit 0
      ;;
    -*) echo "fuzz: unknown option $1 (--help)" >&2; exit 2 ;;
    *)
      [[ " ${all_targets[*]} " == *" $1 "* ]] || { echo "fuzz: unknown target '$1' (${all_targets[*]})" >&2; exit 2; }
      targets+=("$1")
      ;;
  esac
  shift
done
((${#targets[@]})) || targets=("${all_targets[@]}")

if ((do_build)); then
  if ! command -v clang++ >/dev/null; then
    echo "fuzz: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
    exit 2
  fi
  CC=clang CXX=clang++ cmake -S "$root/fuzz" -B "$build" -G Ninja -DTMU_FUZZ=ON >/dev/null
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]/%/_fuzz}"
fi

# merge_inputs TARGET FUZZER CORPUS RUN: adds to CORPUS the run's inputs that reach code the
# corpus does not (libFuzzer -merge=1 on edge coverage, -use_counters=0), those reaching the most
# first, until CORPUS holds max_corpus files; sets `added`. Merging only reads CORPUS.
merge_inputs() {
  local t=$1 fuzzer=$2 corpus=$3 run=$4
  # The merge writes into its first directory: a copy of CORPUS.
  rm -rf "$run/merge"
  cp -r "$corpus" "$run/merge"
  if ! (cd "$run" && "$fuzzer" -merge=1 -use_counters=0 -merge_control_file=merge.ctl -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 "$run/merge" "$run/corpus") >"$run/merge.log" 2>&1; then
    echo "fuzz $t: merge failed ($run/merge.log)" >&2
    return 1
  fi
  # merge.ctl: the number of inputs, how many of them are CORPUS's (empty files left out), their
  # paths (CORPUS's first, then the run's by size), then per input "FT <index> <the features no
  # earlier input had>".
  local room=$((max_corpus - $(ls "$corpus" | wc -l)))
  ((room > 0)) || return 0
  local f name
  while read -r f; do
    name=$(sha1sum <"$f" | cut -c1-40)
    [[ -e $corpus/$name ]] && continue
    cp "$f" "$corpus/$name"
    added=$((added + 1))
  done < <(awk '
      NR == 1 { files = $1; next }
      NR == 2 { first = $1; next }
      NR <= files + 2 { path[NR - 3] = $0; next }
      $1 == "FT" && $2 >= first && NF > 2 { print NF - 2, path[$2] }' "$run/merge.ctl" |
    sort -k1,1nr | head -n "$room" | cut -d' ' -f2-)
}

findings=0
for t in "${targets[@]}"; do
  fuzzer=$build/${t}_fuzz
  [[ -x $fuzzer ]] || { echo "fuzz: $fuzzer is not built" >&2; exit 2; }
  corpus=$root/fuzz/corpus/$t
  run=$build/run/$t
  rm -rf "$run"
  mkdir -p "$run/corpus" "$run/findings"
  cp "$corpus"/* "$run/corpus/"
  dict=()
  [[ -f $root/fuzz/dict/$t.dict ]] && dict=(-dict="$root/fuzz/dict/$t.dict")

  echo "fuzz $t: ${seconds} s on $(ls "$corpus" | wc -l) corpus files (log: $run/fuzz.log)"
  # -timeout: an input taking 10 s is a hang; -rss_limit_mb / -malloc_limit_mb: a reader
  # asking for more than 2 GB at once is a finding. The seeds are small; 64 KiB inputs let a
  # scene grow. The working directory is the run's, so nothing lands in the source tree.
  status=0
  (cd "$run" && "$fuzzer" "${dict[@]}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$run/findings/" corpus) >"$run/fuzz.log" 2>&1 || status=$?

  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$run/fuzz.log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$run/fuzz.log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$run/fuzz.log" | tail -1 || true)

  added=0
  if ((do_merge)); then
    merge_inputs "$t" "$fuzzer" "$corpus" "$run" || status=1
  fi
  echo "fuzz $t: ${runs:-?} runs, ${rate:-?} exec/s, ${cov:-no coverage line}, $added new corpus files"

  mapfile -t found < <(find "$run/findings" -type f | sort)
  if ((${#found[@]})) || ((status != 0)); then
    findings=$((findings + 1))
    echo "fuzz $t: FINDING (fuzzer exit $status); the report:"
    grep -m 12 -E 'ERROR|SUMMARY|runtime error|fuzz check failed|terminate called|what\(\)|#[0-9] 0x' "$run/fuzz.log" \
      | sed 's/^/    /' || true
    for f in "${found[@]}"; do
      echo "  finding: $f"
      echo "    reproduce: $fuzzer $f"
      echo "    or in the gcc build: build/fuzz/tmu_fuzz_replay $t $f"
    done
  fi
done

if ((findings)); then
  echo "fuzz: $findings target(s) with findings"
  exit 1
fi
echo "fuzz: no findings in ${targets[*]}"
