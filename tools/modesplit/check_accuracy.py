#!/usr/bin/env python3
"""The committed accuracy study against the code (`make check-accuracy`).

Runs `modesplit accuracy --quick`, whose cases are a subset of the full
study's at the same settings (fewer knob values, the smallest particle
counts), two cases at a time, and compares every row's error with the row
of data/accuracy/accuracy.csv that has the same study, knob, value,
configuration and metric. A row that moved beyond the tolerance, or that
the committed study lacks, fails with the case and both values: a change
that changes results regenerates data/accuracy/ (`make accuracy`) in the
same commit, as a change of the golden hash does.

Tolerance: |quick - committed| <= REL * |committed| + ABS. The study runs
one thread and its results are the same bytes run after run (the CSV
writes errors to 6 significant digits, so REL covers its rounding and
nothing more). Another compiler or NATIVE=1 may differ in the last bits,
which the chaotic dam break grows into percent: this check, like the
golden hash, is for the default build.

  check_accuracy.py MODESPLIT [COMMITTED_CSV]
"""
import csv
import os
import shlex
import subprocess
import sys
import tempfile

REL = 1e-4
ABS = 1e-9
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
KEY = ("study", "knob", "value", "config", "metric")


def rows_of(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_quick(tool, out, jobs=2):
    lines = subprocess.run([tool, "accuracy", "--quick", "--jobs", "--out", out], check=True,
                           capture_output=True, text=True).stdout.splitlines()
    pending = [shlex.split(line) for line in lines if line.strip()]
    running, failed = [], []
    while pending or running:
        while pending and len(running) < jobs:
            argv = pending.pop(0)
            running.append((argv, subprocess.Popen(argv, stdout=subprocess.DEVNULL,
                                                   stderr=subprocess.PIPE, text=True)))
        argv, p = running.pop(0)
        err = p.communicate()[1]
        if p.returncode != 0:
            failed.append(f"{' '.join(argv)} exited {p.returncode}:\n{err}")
    return failed


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    tool = argv[1]
    committed_path = argv[2] if len(argv) > 2 else os.path.join(ROOT, "data", "accuracy",
                                                                "accuracy.csv")
    committed = {}
    for r in rows_of(committed_path):
        committed[tuple(r[k] for k in KEY)] = r
    with tempfile.TemporaryDirectory(prefix="check-accuracy-") as tmp:
        failed = run_quick(tool, tmp)
        if failed:
            print("\n".join(failed), file=sys.stderr)
            return 1
        parts = os.path.join(tmp, "parts")
        quick = []
        for name in sorted(os.listdir(parts)):
            if name.endswith(".csv"):
                quick += [(name[:-4], r) for r in rows_of(os.path.join(parts, name))]
    problems, compared = [], 0
    for case, r in quick:
        key = tuple(r[k] for k in KEY)
        c = committed.get(key)
        what = f"{case}: {r['knob']}={r['value']} ({r['config']}), {r['metric']}"
        if c is None:
            problems.append(f"{what}: no such row in {os.path.relpath(committed_path, ROOT)}")
            continue
        got, want = float(r["error"]), float(c["error"])
        compared += 1
        same_nan = got != got and want != want
        if not same_nan and not abs(got - want) <= REL * abs(want) + ABS:
            problems.append(f"{what}: {got:.6g} now, {want:.6g} committed")
    if problems:
        print("\n".join(problems), file=sys.stderr)
        print(f"check-accuracy: {len(problems)} of {len(quick)} rows of `modesplit accuracy "
              f"--quick` differ from the committed study (tolerance {REL:g} relative + {ABS:g}); "
              "if the change is meant, run `make accuracy` and commit data/accuracy/ with it",
              file=sys.stderr)
        return 1
    if compared == 0:
        print("check-accuracy: the quick study gave no row", file=sys.stderr)
        return 1
    print(f"check-accuracy: {compared} rows of the quick study equal the committed study's "
          f"(within {REL:g} relative)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
