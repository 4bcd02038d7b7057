#!/usr/bin/env bash
# Builds the project with AddressSanitizer and UndefinedBehaviorSanitizer (TMU_SANITIZE=ON,
# RelWithDebInfo) in its own build directory and runs the test suite there. Any ASan report or
# undefined behaviour aborts the process, which fails the test.
#
#   scripts/sanitize.sh [--ci] [--no-build] [ctest args...]
#
#   --ci        the CI subset (below) instead of the whole suite
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

# halt_on_error / abort_on_error: the first report ends the process with a failure.
# detect_leaks=0: LeakSanitizer is off. The leaks it finds at exit are SystemC's (Debian's
#   libsystemc is not instrumented, and its simulation context, processes and coroutine stacks
#   are never freed: SystemC has no way to end an elaboration) and Verilator's per-process
#   singletons; none of them grows with a run, and with LSan on every hls test failed on them.
# detect_stack_use_after_return=0: SystemC threads run on stacks that libsystemc switches
#   between without telling ASan (it is not built with the fiber annotations); the fake stacks
#   of use-after-return detection do not survive that switching.
# Anything the caller puts in ASAN_OPTIONS / UBSAN_OPTIONS comes after, so it wins.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:detect_leaks=0:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1:detect_odr_violation=2${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:report_error_type=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

if ((run_build)); then
  TMU_BUILD_DIR=$build "$root/scripts/build.sh" -DTMU_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi

select=(-LE 'lint|synth')
if ((ci)); then
  # The CI subset (docs/robustness.md): every golden, host and render unit test, the texsim
  # command-line tests, the harness tests, and per co-simulated block its fast directed and
  # random runs; the long random runs, throughput and mutant tests are the full run's.
  select+=(-R "$(tr -d ' \n' <"$root/scripts/sanitize_ci.regex")")
fi

start=$SECONDS
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure "${select[@]}" "${ctest_args[@]}"
echo "sanitize: tests passed under ASan+UBSan in $((SECONDS - start)) s"
