#!/usr/bin/env bash
# Set up, build, and run every test: GoogleTest suites (golden, hls, rtl, equiv), the CLI
# tests, the RTL lint and the Yosys check of every block; then the sanitizer subset
# (scripts/sanitize.sh --ci: the golden models, the host front end and the fuzz corpus under
# ASan and UBSan, in build-asan/). CI runs exactly this (.ci/run).
#
#   scripts/test.sh [--long] [ctest args...]      e.g. scripts/test.sh -L equiv
#
# --long (or TMU_LONG=1) also runs the tests labelled `long`, which the default run leaves
#   out: the full Yosys synthesis of every block (rtl_synth_figures_<top>, docs/synth.md), the
#   scenes' renders at full size; and builds and runs every mutant (the default run: each
#   block's first and one x-leak, -DTMU_MUTANTS=ci). A -LE of your own is added to the exclusion.
# TMU_SKIP_SANITIZE=1 leaves the sanitizer subset out (a quick local run); TMU_TEST_TIMEOUT sets
# the seconds after which a test fails (default 600, with --long 3600).
# ctest writes JUnit XML to $build/ctest-junit.xml (TMU_JUNIT overrides the path); the ten
# slowest tests are printed from it at the end (scripts/slowest_tests.py), with the time of
# each phase. Times are a report: nothing here fails on them.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${TMU_BUILD_DIR:-$root/build}
junit=${TMU_JUNIT:-$build/ctest-junit.xml}

# ctest keeps no exclusion at all when given two -LE, so a -LE of the caller's is joined with
# the default one into a single regex.
long=${TMU_LONG:-0}
exclude=""
ctest_args=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --long) long=1; shift ;;
    -LE | --label-exclude) exclude=$2; shift 2 ;;
    *) ctest_args+=("$1"); shift ;;
  esac
done
[[ "$long" != 1 ]] && exclude=${exclude:+($exclude)|}long
# A test that hangs fails after this many seconds instead of eating CI's budget (the slowest
# test takes about 35 s on two cores; the long set's full synthesis of tmu_material ~10 min).
timeout=${TMU_TEST_TIMEOUT:-600}
[[ "$long" == 1 ]] && timeout=${TMU_TEST_TIMEOUT:-3600}
select=()
[[ -n "$exclude" ]] && select=(-LE "$exclude")

export TMU_SETUP=${TMU_SETUP:-tests}  # the packages the tests need (scripts/setup.sh)
start=$SECONDS
mutants=ci  # each block's first mutant and one x-leak (rtl/CMakeLists.txt); --long: all
[[ "$long" == 1 ]] && mutants=all
"$root/scripts/build.sh" -DTMU_MUTANTS=$mutants
build_s=$((SECONDS - start))

status=0
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure --output-junit "$junit" \
  --timeout "$timeout" "${select[@]}" "${ctest_args[@]}" || status=$?
ctest_s=$((SECONDS - start - build_s))
"$root/scripts/slowest_tests.py" "$junit" || true  # a report: a missing file is not the verdict

sanitize_s=0
if [[ $status -eq 0 && "${TMU_SKIP_SANITIZE:-0}" != 1 ]]; then
  "$root/scripts/sanitize.sh" --ci || status=$?
  sanitize_s=$((SECONDS - start - build_s - ctest_s))
fi
echo "test.sh: build ${build_s} s, ctest ${ctest_s} s, sanitizer subset ${sanitize_s} s," \
  "total $((SECONDS - start)) s; JUnit $junit"
exit $status
