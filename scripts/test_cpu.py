#!/usr/bin/python3
"""The CPU time of every ctest test: what a test costs on a shared machine, where ctest's own
times (wall clock, two tests at a time) grow with whatever runs beside them.

    /usr/bin/python3 scripts/test_cpu.py [--preset release] [--jobs 2] [-R REGEX] OUT.tsv

Runs the tests ctest would run (`ctest --preset P --show-only=json-v1`), `--jobs` at a time,
longest first by tests/ctest_costs.txt, each with its working folder and environment, the
fixtures' set-up tests first and their clean-up tests last. OUT.tsv gets one line per test as
it finishes: name, CPU seconds (user + system of the test's process and every process it
waited for, from wait4), wall seconds, exit code. A summary goes to stdout. Exit 1 when a test
failed, 2 on bad arguments.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def properties(test):
    return {p["name"]: p["value"] for p in test.get("properties", [])}


def known_costs():
    costs = {}
    with open(os.path.join(ROOT, "tests", "ctest_costs.txt")) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 3:
                costs[fields[0]] = float(fields[2])
    return costs


def run_test(test):
    """(cpu_s, wall_s, exit_code) of one test."""
    props = properties(test)
    env = dict(os.environ)
    for assignment in props.get("ENVIRONMENT", []):
        key, value = assignment.split("=", 1)
        env[key] = value
    start = time.monotonic()
    process = subprocess.Popen(test["command"], cwd=props.get("WORKING_DIRECTORY"), env=env,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    return (usage.ru_utime + usage.ru_stime, time.monotonic() - start,
            os.waitstatus_to_exitcode(status))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output", help="TSV to write: name, CPU s, wall s, exit code")
    parser.add_argument("--preset", default="release")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("-R", dest="regex", help="only the tests whose name matches")
    args = parser.parse_args()
    if args.jobs < 1:
        parser.error("--jobs must be >= 1")
    listing = subprocess.run(["ctest", "--preset", args.preset, "--show-only=json-v1"],
                             cwd=ROOT, capture_output=True, text=True)
    if listing.returncode != 0:
        print(f"test_cpu: ctest could not list the tests:\n{listing.stderr}", file=sys.stderr)
        return 2
    tests = json.loads(listing.stdout)["tests"]
    setups = [t for t in tests if "FIXTURES_SETUP" in properties(t)]
    cleanups = [t for t in tests if "FIXTURES_CLEANUP" in properties(t)]
    tests = [t for t in tests if t not in setups and t not in cleanups]
    if args.regex:
        tests = [t for t in tests if re.search(args.regex, t["name"])]
    costs = known_costs()
    tests.sort(key=lambda t: -costs.get(t["name"], 0.0))

    lock = threading.Lock()
    rows = []
    with open(args.output, "w") as out:
        def record(test):
            cpu_s, wall_s, code = run_test(test)
            with lock:
                rows.append((test["name"], cpu_s, wall_s, code))
                out.write(f"{test['name']}\t{cpu_s:.2f}\t{wall_s:.2f}\t{code}\n")
                out.flush()

        for test in setups:
            record(test)
        with ThreadPoolExecutor(args.jobs) as pool:
            list(pool.map(record, tests))
        for test in cleanups:
            record(test)

    failed = [r for r in rows if r[3] != 0]
    total_cpu = sum(r[1] for r in rows)
    print(f"{len(rows)} tests, {total_cpu:.0f} s of CPU; the ten costliest:")
    for name, cpu_s, wall_s, _ in sorted(rows, key=lambda r: -r[1])[:10]:
        print(f"  {cpu_s:7.1f} s CPU {wall_s:7.1f} s wall  {name}")
    for name, _, _, code in failed:
        print(f"failed (exit {code}): {name}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
