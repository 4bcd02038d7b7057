#!/usr/bin/env bash
# Builds the project with AddressSanitizer and UndefinedBehaviorSanitizer (TMU_SANITIZE=ON,
# RelWithDebInfo) in its own build directory and runs the test suite there. Any ASan report or
# undefined behaviour aborts the process, which fails the test.
#
#   scripts/sanitize.sh [--ci] [--no-build] [ctest args...]
#
#   --ci        build and run only the CI subset (below) instead of the whole suite
#   --no-build  run the tests of an existing sanitizer build
#
# Extra arguments go to ctest (e.g. -R cube_map, -j 1). The lint and synthesis tests (labels
# lint, synth: Verilator --lint-only, Yosys, clang-format) run no code of ours and are left out.
# TMU_ASAN_BUILD_DIR chooses the build directory (default: build-asan/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_ASAN_BUILD_DIR:-$root/build-asan}

ci=0
run_build=1
ctest_args=()
for arg in "$@"; do
  case $arg in
    --ci) ci=1 ;;
    --no-build) run_build=0 ;;
    -h | --help)
      sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) ctest_args+=("$arg") ;;
  esac
done

# halt_on_error / abort_on_error: the first report ends the process with a failure. (An
#   hls run is a forked child: its abort shows as "hls child killed by signal 6" after ASan's
#   report, and fails the run.) LeakSanitizer stays on: the suite leaks nothing.
# detect_stack_use_after_return=0 (GCC's default; spelled out because turning it on breaks):
#   SystemC threads run on coroutine stacks that Debian's libsystemc switches between without
#   telling ASan, and the fake frames of use-after-return detection do not survive the switch;
#   with it on, every hls run dies in ScDriver::run (SEGV in a fake frame). The switching also
#   makes ASan print "WARNING: ASan is ignoring requested __asan_handle_no_return" once per
#   SystemC process that unwinds (sc_stop); it is a warning, nothing failed.
# new_delete_type_mismatch=0: OpenImageIO 2.4's TextureSystem::destroy (inside
#   libOpenImageIO, not instrumented) deletes its 184-byte implementation through a pointer
#   ASan sizes at 1 byte; the OIIO comparisons (texram_ideal_oiio_test, texsim sweep
#   footprint) died there. Our own polymorphic deletes are covered by -Wdelete-non-virtual-dtor
#   (-Wall) at compile time.
# check_initialization_order / detect_odr_violation=2 / strict_string_checks: stricter than the
#   defaults, and quiet: no static-initialisation-order problem, no ODR violation between the
#   Verilated models (each has its own prefix; the Verilator runtime is compiled once).
# Anything the caller puts in ASAN_OPTIONS / UBSAN_OPTIONS comes after, so it wins.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:detect_stack_use_after_return=0:new_delete_type_mismatch=0:strict_string_checks=1:check_initialization_order=1:detect_odr_violation=2${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:report_error_type=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

# The CI subset (docs/robustness.md): the golden models, the host front end (scene, mesh,
# raster, traces) and the fuzz corpus replay, whose executables need neither Verilator nor
# SystemC; with ASan the Verilated models are the bulk of a build that takes an hour on two
# cores, while these build in minutes. The whole suite is the full run's (scripts/sanitize.sh).
# So --ci configures with TMU_RTL=OFF. Configuring rtl/ runs Verilator over all 84 models (the
# variants and mutants too), and the first ninja step ran it over them again (build.ninja
# depends on the file lists Verilator writes, and ninja reruns a command it has no log entry
# of): none of it serves these targets. Measured from an empty build directory and ccache, on
# two cores shared with other builds: the configure took 29 s of CPU (37-42 s wall), now 2.4 s
# (4-6 s); the second Verilator pass 18 s of CPU, now none; the whole --ci command 429 s of CPU
# and 925 s wall before, 380 s and 846 s after, the two run side by side (another pair, one
# after the other: 392 and 355 s of CPU).
ci_targets=(tmu_fixed_tests tmu_ccc_encoder_tests tmu_ccc_bilinear_tests tmu_footprint_tests
  tmu_texram_tests tmu_texram_oiio_tests tmu_clipmap_tests tmu_mipgen_tests tmu_deflect_tests
  tmu_perlin_tests tmu_host_tests tmu_fuzz_replay)

# Tests the CI subset leaves out: the exhaustive proofs and large inputs, which run the same
# code as their small siblings in the same executable (those run here) over many more values, so
# they cost most of the subset's time under ASan and find nothing its siblings do not. They run
# in the main build's ctest, and under the sanitizers in the full run (sanitize.sh without --ci).
# Under ASan on two cores they took 67 s of the subset's 100 s of CPU (measured 2026-12-02).
declare -A ci_skip=(
  [tmu_texram_tests]="TexramLayoutTest.EveryBorderModeReadsEachBankAtMostOnce:TexramLayoutTest.EveryTrilinearFootprintOf1024ReadsEveryBankExactlyOnce:TexramLayoutTest.CellsAreDistinctAndInsideTheBanks"
  [tmu_ccc_encoder_tests]="CccEncoderTest.FitMatchesExhaustivePairSearch:CccEncoderTest.LargeImageEncodesQuickly"
  [tmu_mipgen_tests]="MipgenTest.StreamEqualsPyramidForEverySizeBothModes"
)

# -O1 -g1 instead of RelWithDebInfo's -O2 -g: what ASan's documentation advises, and the build
# takes about half the CPU time (the test files' gtest and JSON templates dominate it); -g1
# keeps the file and line of every frame in a report. NDEBUG as in the main build. The test
# files themselves compile at -O0 (tests/CMakeLists.txt): the --ci subset took 164 s instead of
# 195 from a cold cache, its tests 31 s instead of 19.
# As scripts/build.sh: ccache hits for precompiled headers and for another clone's compiles.
export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
flags=(-DTMU_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG")
if ((run_build)); then
  # TMU_RTL is given either way: the cache would keep the other mode's value in the same
  # directory.
  if ((ci)); then
    "$root/scripts/setup.sh"
    cmake -S "$root" -B "$build" -G Ninja "${flags[@]}" -DTMU_RTL=OFF
    cmake --build "$build" -j "$(nproc)" --target "${ci_targets[@]}"
  else
    TMU_BUILD_DIR=$build "$root/scripts/build.sh" "${flags[@]}" -DTMU_RTL=ON
  fi
fi

start=$SECONDS
if ((ci)) && ((${#ctest_args[@]} == 0)); then
  # The CI subset runs each executable once, all its tests in one process, instead of one
  # process per test as ctest does: ASan's start-up and LeakSanitizer's exit scan were most
  # of the time of the 205 short tests. The same tests run (every test of the golden and fuzz
  # labels), largest first so that the small ones fill the gaps.
  logs=$build/sanitize-logs
  mkdir -p "$logs"
  run_one() {  # NAME DIR EXECUTABLE [ARGS...]: its log in $logs/NAME.log, a line of verdict
    local name=$1 dir=$2 t0=$SECONDS arg command=()
    shift 2
    for arg in "$@"; do [[ -n $arg ]] && command+=("$arg"); done  # xargs gives empty ones too
    if (cd "$dir" && "${command[@]}" >"$logs/$name.log" 2>&1); then
      echo "ok     $name ($((SECONDS - t0)) s)"
    else
      echo "FAILED $name ($((SECONDS - t0)) s), $logs/$name.log:"
      tail -40 "$logs/$name.log"
      return 1
    fi
  }
  export -f run_one
  export logs
  status=0
  for t in "${ci_targets[@]}"; do  # NAME DIR COMMAND ARGS, as ctest would run them
    if [[ $t == tmu_fuzz_replay ]]; then
      printf '%s\0' fuzz_corpus_replay "$build/fuzz" "$build/fuzz/$t" "$root/fuzz/corpus" ""
    else
      printf '%s\0' "$t" "$build/tests" "$build/tests/$t" --gtest_brief=1 \
        "${ci_skip[$t]:+--gtest_filter=-${ci_skip[$t]}}"
    fi
  done >"$logs/jobs"
  xargs -0 -n 5 -P "$(nproc)" bash -c 'run_one "$@"' _ <"$logs/jobs" || status=1
  if ((status)); then
    echo "sanitize: FAILED under ASan+UBSan (logs in $logs/)"
    exit 1
  fi
else
  select=(-LE 'lint|synth')
  ((ci)) && select=(-L '^(golden|fuzz)$')
  ctest --test-dir "$build" -j "$(nproc)" --output-on-failure "${select[@]}" "${ctest_args[@]}"
fi
echo "sanitize: tests passed under ASan+UBSan in $((SECONDS - start)) s"
