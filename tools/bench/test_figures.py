#!/usr/bin/env python3
"""figures.py refuses what it must (run by `make check-bench-figures`):
a linked figure off by one in its last written decimal, a row selector
that picks no row or several, an unknown column, an edited generated
table; it accepts the figure at any decimals that round the CSV value."""
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "figures.py")
ROW = 'data/bench/scenes.csv "scene=fig1 threads=2 fps_median_per_s"'


def committed_value():
    """The row's value in the committed CSV: the cases follow whatever
    `make bench-commit` last wrote, so they never pin a measurement."""
    with open(os.path.join(HERE, "..", "..", "data", "bench", "scenes.csv"), newline="") as f:
        for r in csv.DictReader(f):
            if r["scene"] == "fig1" and r["threads"] == "2":
                return float(r["fps_median_per_s"])
    sys.exit("test_figures: data/bench/scenes.csv has no fig1 row with 2 threads")


V = committed_value()
V0, V1, V2 = f"{V:.0f}", f"{V:.1f}", f"{V:.2f}"


def run(text, mode="--check"):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "README.md")
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([sys.executable, TOOL, mode, path], capture_output=True, text=True)
        with open(path) as f:
            return p.returncode, p.stdout + p.stderr, f.read()


def expect(ok, text, word=None):
    code, out, _ = run(text)
    if (code == 0) != ok or (word and word not in out):
        sys.exit(f"test_figures: {text!r}: exit {code}, wanted {'0' if ok else '1'}"
                 f"{' and ' + repr(word) if word else ''}; said:\n{out}")


expect(True, f"[{V0}]({ROW}) and [{V1}]({ROW}) and [{V2}]({ROW})\n")
expect(True, f"from docs/: [{V0}](../{ROW})\n")
expect(False, f"from docs/: [{float(V0) + 1:.0f}](../{ROW})\n", V0)
expect(False, f"[{float(V0) + 1:.0f}]({ROW})\n", V0)
expect(False, f"[{float(V1) - 0.1:.1f}]({ROW})\n", V1)
expect(False, '[1](data/bench/scenes.csv "scene=fig1 fps_median_per_s")\n', "2 rows")
expect(False, '[1](data/bench/scenes.csv "scene=nope threads=1 fps_median_per_s")\n', "0 rows")
expect(False, '[1](data/bench/scenes.csv "scene=fig1 threads=1 fps")\n', "no column")
expect(False, '[1](data/bench/nope.csv "scene=fig1 threads=1 fps")\n', "does not exist")
expect(False, "no figure at all\n", "links no figure")
code, _, fixed = run(f"[{float(V0) + 1:.0f}]({ROW})\n", "--write")
if code != 0 or not fixed.startswith(f"[{V0}]("):
    sys.exit(f"test_figures: --write left {fixed!r}")
# a generated table: --write fills it, --check then passes, an edit fails
_, _, table = run("<!-- bench-table scenes -->\n<!-- /bench-table -->\n", "--write")
expect(True, table)
expect(False, table.replace("| fig1 | 2000 |", "| fig1 | 2001 |", 1), "bench table scenes")
expect(False, "<!-- bench-table nope -->\n<!-- /bench-table -->\n", "no bench table")
# the accuracy study: a selector value with spaces in single quotes, a
# column in percent (the CSV's fraction times 100)
with open(os.path.join(HERE, "..", "..", "data", "accuracy", "accuracy.csv"), newline="") as f:
    A = next(r for r in csv.DictReader(f) if r["study"] == "sph" and r["knob"] == "particles")
AVALUE, AMETRIC, AERROR = A["value"], A["metric"], float(A["error"])
AROW = (f'data/accuracy/accuracy.csv "study=sph knob=particles value={AVALUE} '
        f"metric='{AMETRIC}' error%\"")
AV = f"{100 * AERROR:.2f}"
expect(True, f"[{AV}]({AROW}) %\n")
expect(False, f"[{float(AV) + 0.01:.2f}]({AROW}) %\n", AV)
expect(False, f"[{AV}]({AROW.replace(' error%', ' error')}) %\n", "is")
expect(False, f'[1](data/accuracy/accuracy.csv "study=sph knob=particles metric=\'oops error")\n',
       "closing quotation")
_, _, table = run("<!-- bench-table accuracy_choose -->\n<!-- /bench-table -->\n", "--write")
expect(True, table)
print("bench figures: the check refuses wrong figures, selectors and tables (19 cases)")
