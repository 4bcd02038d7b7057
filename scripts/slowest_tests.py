#!/usr/bin/env python3
"""Prints the slowest tests of a JUnit XML file as ctest writes it (--output-junit).

    scripts/slowest_tests.py [-n N] JUNIT.xml     (default: the ten slowest)

scripts/test.sh calls it after ctest on build/ctest-junit.xml. Times are each test's own wall
time; the header gives their sum and the number of tests, failed ones marked. A report, never
a verdict: it exits 0 whatever the times, 2 when the file cannot be read.
"""
import argparse
import sys
import xml.etree.ElementTree as ET


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("junit", help="JUnit XML file written by ctest --output-junit")
    parser.add_argument("-n", type=int, default=10, help="how many tests to list (default 10)")
    args = parser.parse_args()
    try:
        cases = ET.parse(args.junit).getroot().iter("testcase")
    except (OSError, ET.ParseError) as e:
        print(f"slowest_tests: {args.junit}: {e}", file=sys.stderr)
        return 2
    tests = []
    for case in cases:
        try:
            seconds = float(case.get("time", "0"))
        except ValueError:
            print(f"slowest_tests: {args.junit}: test {case.get('name')}: time "
                  f"'{case.get('time')}' is not a number", file=sys.stderr)
            return 2
        failed = case.find("failure") is not None or case.get("status") == "fail"
        tests.append((seconds, case.get("name", "?"), failed))
    tests.sort(key=lambda t: -t[0])
    total = sum(t[0] for t in tests)
    print(f"slowest {min(args.n, len(tests))} of {len(tests)} tests "
          f"({total:.1f} s of test time in all, {args.junit}):")
    for seconds, name, failed in tests[: args.n]:
        print(f"  {seconds:8.1f} s  {name}{'  FAILED' if failed else ''}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
