#!/usr/bin/env python3
"""figures.py refuses what it must (run by `make check-bench-figures`):
a linked figure off by one in its last written decimal, a row selector
that picks no row or several, an unknown column, an edited generated
table; it accepts the figure at any decimals that round the CSV value."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "figures.py")
ROW = 'data/bench/scenes.csv "scene=fig1 threads=2 fps_median_per_s"'  # 258.881


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


expect(True, f"[259]({ROW}) and [258.9]({ROW}) and [258.88]({ROW})\n")
expect(False, f"[260]({ROW})\n", "259")
expect(False, f"[258.8]({ROW})\n", "258.9")
expect(False, '[1](data/bench/scenes.csv "scene=fig1 fps_median_per_s")\n', "2 rows")
expect(False, '[1](data/bench/scenes.csv "scene=nope threads=1 fps_median_per_s")\n', "0 rows")
expect(False, '[1](data/bench/scenes.csv "scene=fig1 threads=1 fps")\n', "no column")
expect(False, '[1](data/bench/nope.csv "scene=fig1 threads=1 fps")\n', "does not exist")
expect(False, "no figure at all\n", "links no figure")
code, _, fixed = run(f"[260]({ROW})\n", "--write")
if code != 0 or not fixed.startswith("[259]("):
    sys.exit(f"test_figures: --write left {fixed!r}")
# a generated table: --write fills it, --check then passes, an edit fails
_, _, table = run("<!-- bench-table scenes -->\n<!-- /bench-table -->\n", "--write")
expect(True, table)
expect(False, table.replace("| fig1 | 2000 |", "| fig1 | 2001 |", 1), "bench table scenes")
expect(False, "<!-- bench-table nope -->\n<!-- /bench-table -->\n", "no bench table")
print("bench figures: the check refuses wrong figures, selectors and tables (12 cases)")
