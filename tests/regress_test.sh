#!/usr/bin/env bash
# `texsim regress LIST`: a list of cosim seeds and a render runs on two jobs; the JUnit XML counts
# every test and the one failure (an injected fault), whose summary entry gives the command that
# reproduces it (run again, it fails the same way), its waveform and its log; a test past the
# timeout is killed and fails; a frame's bands run as tests and are joined equal to the whole
# frame; a fly-over's frame ranges run as tests and are gathered equal to one process's frames;
# a malformed list is exit 2 naming the line. Usage:
# tests/regress_test.sh PATH/TO/texsim
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
cd "$work" || exit 1

cat >list.txt <<LIST
# cosim seeds, a fault injected into one, a render checked against golden
cosim ccc_decoder --seeds 1..3 --count 300
cosim specular_combine --seeds 5..5 --count 200 --inject-fault 3
render $root/scenes/plain.json --engine golden
LIST
"$texsim" regress list.txt --out out --jobs 2 >run.txt 2>&1
code=$?
cat run.txt
[[ $code -eq 1 ]] && pass "exit 1 with a failure" || fail "exit $code"
grep -q 'tests="5" failures="1"' out/junit.xml && pass "JUnit: 5 tests, 1 failure" ||
  fail "JUnit: $(head -3 out/junit.xml)"
grep -q '<testcase classname="render" name="render.plain.4"' out/junit.xml &&
  pass "JUnit names the render" || fail "no render in the JUnit XML"
repro=$(sed -n 's/^  reproduce: //p' out/summary.txt)
[[ $repro == *"cosim specular_combine --seed 5 --count 200 --inject-fault 3 --wave-dir"* ]] &&
  pass "the summary gives the reproduce command" || fail "reproduce: '$repro'"
wave=$(sed -n 's/^  waveform: //p' out/summary.txt)
[[ -s $wave ]] && pass "the failure's waveform is written ($wave)" || fail "waveform: '$wave'"
[[ -s out/logs/cosim.specular_combine.seed5.log ]] && pass "its log is kept" || fail "no log"
eval "$repro" >again.txt 2>&1
again=$?
[[ $again -eq 1 ]] && grep -q "MISMATCH rtl" again.txt &&
  pass "the reproduce command fails the same way" || fail "reproduce ran: exit $again"

# A frame split into bands, each a test (through Slurm too), joined equal to the whole frame.
echo "render $root/scenes/plain.json --engine golden --bands 3" >bands.txt
"$texsim" regress bands.txt --out bands --jobs 2 >bands_run.txt 2>&1
joined=$(sed -n 's/^bands of render.plain.1 joined: //p' bands/summary.txt)
"$texsim" render "$root/scenes/plain.json" --engine golden --out whole >/dev/null 2>&1
[[ -s $joined ]] && idiff -q "$joined" whole/render.png >/dev/null 2>&1 &&
  pass "3 bands as 3 tests, joined equal to the whole frame" || fail "$(cat bands_run.txt)"

# A fly-over's frames split into ranges, each a test, gathered equal to the one-process frames.
echo "render $root/scenes/flyover.json --engine golden --frames 0-4 --frames-per-test 2" >fly.txt
"$texsim" regress fly.txt --out fly --jobs 2 >fly_run.txt 2>&1
gathered=$(sed -n 's/^frames of render.flyover.1 gathered: \(.*\) (5 frames)$/\1/p' fly/summary.txt)
names=$(ls fly/renders | grep -c '^render.flyover.1.frames')
"$texsim" render "$root/scenes/flyover.json" --engine golden --frames 0-4 --out fly_whole \
  >/dev/null 2>&1
same=0
for f in fly_whole/flyover.frame-000{0..4}.png; do
  idiff -q "$f" "$gathered/$(basename "$f")" >/dev/null 2>&1 && same=$((same + 1))
done
[[ -n $gathered && $names -eq 3 && $same -eq 5 ]] &&
  pass "frames 0-4 as 3 tests of 2, 2 and 1 frames, gathered equal to one process's frames" ||
  fail "tests: $names, equal frames: $same; $(cat fly_run.txt)"
printf 'render %s --frames-per-test 2\n' "$root/scenes/plain.json" >notfly.txt
"$texsim" regress notfly.txt --out notfly >notfly_run.txt 2>&1
[[ $? -eq 2 ]] && grep -q "notfly.txt: line 1: --frames-per-test is for a fly-over scene" \
  notfly_run.txt && pass "--frames-per-test on a surface scene names the line" ||
  fail "$(cat notfly_run.txt)"
printf 'render %s --frames 3-99 --frames-per-test 2\n' "$root/scenes/flyover.json" >far.txt
"$texsim" regress far.txt --out far >far_run.txt 2>&1
[[ $? -eq 2 ]] && grep -q "far.txt: line 1: --frames: frames 3..99 of a path of 12 frames" \
  far_run.txt && pass "a range past the path names the line" || fail "$(cat far_run.txt)"

echo "render $root/scenes/grazing.json --engine hls" >slow.txt
"$texsim" regress slow.txt --out slow --jobs 1 --timeout 1 >slow_run.txt 2>&1
[[ $? -eq 1 ]] && grep -q "killed after the timeout" slow/summary.txt &&
  pass "a test past the timeout is killed and fails" || fail "$(cat slow_run.txt)"

printf 'cosim ccc_decoder --seeds 3..1\n' >bad.txt
"$texsim" regress bad.txt --out bad >bad_run.txt 2>&1
[[ $? -eq 2 ]] && grep -q "bad.txt: line 1: --seeds: '3..1' is empty" bad_run.txt &&
  pass "an empty seed range names the line" || fail "$(cat bad_run.txt)"
printf '\nsimulate everything\n' >bad2.txt
"$texsim" regress bad2.txt --out bad2 >bad2_run.txt 2>&1
[[ $? -eq 2 ]] && grep -q "line 2: unknown command 'simulate'" bad2_run.txt &&
  pass "an unknown command names the line" || fail "$(cat bad2_run.txt)"
finish
