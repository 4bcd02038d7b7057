#!/usr/bin/env bash
# `texsim regress --slurm` on a single-node Slurm cluster started for the test
# (scripts/slurm_local.sh, Debian's slurm-wlm and munge): a small regression with one injected
# failure runs as a job array, and the merged JUnit XML and summary equal the local run's (the
# tests, their verdicts, the failure's reproduce command up to the output folder). The daemons
# the test started are stopped at its end, pass or fail. Needs root (the daemons); skipped (77)
# without. Usage: tests/regress_slurm_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
if [[ $(id -u) -ne 0 ]]; then
  echo "SKIP: starting slurmctld and slurmd needs root"
  exit 77
fi
export TMU_SLURM_DIR=$work/slurm
export SLURM_CONF=$TMU_SLURM_DIR/slurm.conf
trap '"$root/scripts/slurm_local.sh" stop; rm -rf "$work"' EXIT
cd "$work" || exit 1
"$root/scripts/slurm_local.sh" start && pass "single-node Slurm up" || { fail "slurm start"; finish; }

cat >list.txt <<LIST
cosim ccc_decoder --seeds 1..3 --count 300
cosim specular_combine --seeds 5..5 --count 200 --inject-fault 3
render $root/scenes/plain.json --engine golden
LIST
"$texsim" regress list.txt --out local --jobs 2 >local.txt 2>&1
local_code=$?
"$texsim" regress list.txt --out slurm --jobs 2 --slurm >slurm.txt 2>&1
slurm_code=$?
cat slurm.txt
[[ $local_code -eq 1 && $slurm_code -eq 1 ]] && pass "both exit 1 (one failure)" ||
  fail "exit codes: local $local_code, slurm $slurm_code"
grep -q "#SBATCH --array=0-4%2" slurm/slurm/array.sh && pass "a job array of 5 tasks, 2 at a time" ||
  fail "array.sh: $(cat slurm/slurm/array.sh)"
ls slurm/slurm/task_*.out >/dev/null 2>&1 && pass "Slurm ran the tasks (their outputs exist)" ||
  fail "no task outputs"
# The verdicts: each testcase's name and whether it failed, with times and paths left out.
verdicts() {
  sed -n 's/.*<testcase classname="\([a-z]*\)" name="\([^"]*\)".*/\1 \2/p; s/.*<failure message="\([^"]*\)".*/  failed: \1/p' "$1"
}
[[ "$(verdicts local/junit.xml)" == "$(verdicts slurm/junit.xml)" ]] &&
  pass "merged JUnit equals the local run's ($(grep -c '<testcase' slurm/junit.xml) tests)" ||
  fail "JUnit differs: $(diff <(verdicts local/junit.xml) <(verdicts slurm/junit.xml))"
strip() { grep -E '^(regression|FAIL|  reproduce)' "$1" | sed -e 's/, [0-9.]* s on.*//' \
  -e 's/ after [0-9.]* s//' -e "s|$work/[a-z]*/|OUT/|g"; }
[[ "$(strip local/summary.txt)" == "$(strip slurm/summary.txt)" ]] &&
  pass "merged summary equals the local run's" ||
  fail "summaries differ: $(diff <(strip local/summary.txt) <(strip slurm/summary.txt))"
[[ -s $(sed -n 's/^  waveform: //p' slurm/summary.txt) ]] && pass "the failure's waveform exists" ||
  fail "no waveform"
"$root/scripts/slurm_local.sh" stop && ! pgrep -x slurmctld >/dev/null && ! pgrep -x slurmd >/dev/null &&
  pass "every daemon the test started is stopped" || fail "daemons left running"
trap 'rm -rf "$work"' EXIT
finish
