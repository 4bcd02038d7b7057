#!/usr/bin/env python3
"""What texsim costs to start: CPU time (user + sys), peak memory and the shared objects the
dynamic linker loads, per command, the median of repeated runs (docs/harness.md, "texsim's
start-up").

Figures only, never a verdict: the test suite does not run this (tests never fail on time).

  scripts/startup_bench.py                        # the short commands, 11 runs each
  scripts/startup_bench.py --heavy                # and an rtl render of scenes/default.json
  scripts/startup_bench.py --before OLD/texsim    # runs of OLD and build/tb/texsim interleaved
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_once(argv):
    """CPU seconds (user + sys) and max RSS (KB) of one run, from wait4's rusage (microseconds,
    not /usr/bin/time's hundredths)."""
    with open(os.devnull, "wb") as null:
        proc = subprocess.Popen(argv, stdout=null, stderr=null, cwd=ROOT)
        _, status, usage = os.wait4(proc.pid, 0)
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        sys.exit(f"startup_bench: {' '.join(argv)} exited {code}")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss


def shared_objects(argv):
    """How many shared objects the dynamic linker maps (at start and by dlopen), from
    LD_DEBUG=files; ld.so itself and the vDSO are not counted."""
    env = dict(os.environ, LD_DEBUG="files")
    err = subprocess.run(argv, cwd=ROOT, env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, check=False).stderr
    return sum("generating link map" in line for line in err.decode(errors="replace").splitlines())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n", maxsplit=1)[0])
    p.add_argument("--texsim", default=os.path.join(ROOT, "build", "tb", "texsim"))
    p.add_argument("--before", help="another texsim, run interleaved with --texsim")
    p.add_argument("--runs", type=int, default=11, help="runs per short command")
    p.add_argument("--heavy", action="store_true",
                   help="also `render scenes/default.json --engine rtl`, alone and with "
                   "--check golden --compare ideal (9 runs each)")
    a = p.parse_args()
    binaries = [os.path.abspath(b) for b in ([a.before] if a.before else []) + [a.texsim]]
    out = tempfile.mkdtemp(prefix="startup_bench.")
    commands = [
        (["--help"], a.runs),
        (["cosim", "--help"], a.runs),
        (["render", "--help"], a.runs),
        (["formats"], a.runs),
        (["formats", "--sv-package"], a.runs),
        (["pattern", "checker", os.path.join(out, "checker.png")], a.runs),
    ]
    if a.heavy:
        render = ["render", "scenes/default.json", "--engine", "rtl", "--out", out, "--no-progress"]
        commands.append((render, 9))
        commands.append((render + ["--check", "golden", "--compare", "ideal"], 9))
    for i, b in enumerate(binaries):
        print(f"[{i}] {b}")
    print(f"median of the runs; {'runs of the binaries interleaved' if a.before else ''}")
    print(f"  {'command':<58} {'':>3} {'runs':>4} {'CPU ms':>8} {'max RSS MB':>10} "
          f"{'shared objects':>14}")
    for args, runs in commands:
        samples = {b: [] for b in binaries}
        for _ in range(runs):
            for b in binaries:
                samples[b].append(run_once([b] + args))
        shown = " ".join(x.replace(out, "OUT") for x in args)
        for i, b in enumerate(binaries):
            cpu = statistics.median(s[0] for s in samples[b]) * 1e3
            rss = statistics.median(s[1] for s in samples[b]) / 1024
            print(f"  {shown:<58} [{i}] {runs:>4} {cpu:>8.1f} {rss:>10.1f} "
                  f"{shared_objects([b] + args):>14}")


if __name__ == "__main__":
    main()
