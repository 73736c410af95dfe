#!/usr/bin/env python3
"""The speed and accuracy figures of README.md, docs/performance.md and
docs/accuracy.md against the committed CSVs.

data/bench/*.csv are the CSVs of one `make bench` on a quiet machine
(data/bench/README.md says which machine, commit and date);
data/accuracy/accuracy.csv is the study of one `make accuracy` (its
accuracy.md says which machine and commit), which rewrites the accuracy
figures. The pages quote them in two ways, both checked here:

  * a figure as a Markdown link to its CSV whose title picks the row and
    the column:
        [259](data/bench/scenes.csv "scene=fig1 threads=2 fps_median_per_s")
    (from docs/, the link reads ../data/bench/...). The row is the one
    whose columns equal every key=value; the last word is the column. The
    figure is checked at the decimals it is written with (259 against
    258.881 passes, 260 fails).
  * a generated table between <!-- bench-table NAME --> and
    <!-- /bench-table --> (NAME from TABLES below): rebuilt from the CSVs
    and compared line by line.

Figures that are not linked are not checked: link a figure that comes from
`make bench`; figures measured otherwise (a one-off comparison) say so in
their sentence. Each page named must link or generate at least one figure.

  figures.py --check [PAGE.md...]  exit 1 with one line per mismatch
  figures.py --write [PAGE.md...]  rewrite every linked figure and table
  figures.py --commit BENCH_DIR    copy BENCH_DIR/*.csv into data/bench,
                                   write data/bench/README.md, then --write
  PAGE.md defaults to README.md and docs/performance.md.
"""
import csv
import datetime
import glob
import math
import os
import re
import shlex
import shutil
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "data", "bench")
LINK = re.compile(r'\[([-+]?[0-9]+(?:\.[0-9]+)?)\]\((?:\.\./)?(data/(?:bench|accuracy)/[A-Za-z0-9_.-]+\.csv) '
                  r'"([^"]*)"\)')
PAGES = ["README.md", os.path.join("docs", "performance.md"), os.path.join("docs", "accuracy.md")]
TABLE = re.compile(r"<!-- bench-table ([a-z_]+) -->\n(.*?)<!-- /bench-table -->", re.S)


class Mismatch(Exception):
    pass


def load(name, cache={}):
    if name not in cache:
        path = os.path.join(ROOT, name)
        if not os.path.exists(path):
            raise Mismatch(f"{name} does not exist")
        with open(path, newline="") as f:
            cache[name] = list(csv.DictReader(f))
    return cache[name]


def lookup(name, selector):
    """The value a selector names: key=value words (a value with spaces in
    single quotes, as a shell reads it), then the column; a column ending
    in % is given in percent (the CSV's fraction times 100)."""
    try:
        words = shlex.split(selector)
    except ValueError as e:
        raise Mismatch(f'"{selector}": {e}')
    if not words or "=" in words[-1]:
        raise Mismatch(f'"{selector}" names no column (key=value ... column)')
    column, keys = words[-1], dict(w.split("=", 1) for w in words[:-1])
    scale = 100.0 if column.endswith("%") else 1.0
    column = column.rstrip("%")
    rows = [r for r in load(name) if all(r.get(k) == v for k, v in keys.items())]
    if len(rows) != 1:
        raise Mismatch(f'"{selector}" picks {len(rows)} rows of {name}, not one')
    if column not in rows[0]:
        raise Mismatch(f"{name} has no column {column}")
    return scale * float(rows[0][column])


def decimals(text):
    return len(text.split(".")[1]) if "." in text else 0


def fmt(value, places):
    return f"{value:.{places}f}"


def num(row, key, places):
    return fmt(float(row[key]), places)


def table_scenes():
    """Table 1 of the paper and the _x10 variants: frames/s."""
    rows = load("data/bench/scenes.csv")
    by = {(r["scene"], r["threads"]): r for r in rows}
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    out = ["| scene | particles | SPH field | wave grid | paper frames/s | frames/s, 1 thread "
           "(p10–p90) | frames/s, 2 threads (p10–p90) | 2 over 1 |",
           "|---|---|---|---|---|---|---|---|"]
    for s in scenes:
        one, two = by.get((s, "1")), by.get((s, "2"))
        if not one or not two:
            raise Mismatch(f"data/bench/scenes.csv lacks {s} with 1 or 2 threads")
        side = lambda n: f"{int(n) ** 0.5:.0f}²" if int(n) else "–"
        paper = one["paper_fps_per_s"] if one["paper_fps_per_s"] != "0" else "–"
        cell = lambda r: (f"{num(r, 'fps_median_per_s', 0)} ({num(r, 'fps_p10_per_s', 0)}–"
                          f"{num(r, 'fps_p90_per_s', 0)})")
        out.append(f"| {s} | {one['particles'] if one['particles'] != '0' else '–'} | "
                   f"{side(one['field_cells'])} | {side(one['wave_cells'])} | {paper} | "
                   f"{cell(one)} | {cell(two)} | {num(two, 'speedup_vs_1_thread', 2)}× |")
    return out


def table_parts():
    """One line per part bench: the solver costs behind the frames/s."""
    out = ["| bench (CSV) | case | median |", "|---|---|---|"]
    for r in load("data/bench/surface.csv"):
        out.append(f"| surface (`surface.csv`) | {r['grid']}² grid, {r['threads']} thread | "
                   f"{num(r, 'ns_per_cell_median', 3)} ns per cell-update, "
                   f"{num(r, 'ms_per_substep_median', 3)} ms per sub-step |")
    for r in load("data/bench/volume.csv"):
        out.append(f"| volume (`volume.csv`) | {r['particles']} particles, {r['threads']} "
                   f"thread{'s' if r['threads'] != '1' else ''} | "
                   f"{num(r, 'ms_per_step_median', 2)} ms per sub-step, "
                   f"{num(r, 'Mpairs_per_s', 0)} M pairs/s |")
    for r in load("data/bench/extract.csv"):
        if r.get("gather") == "c":  # the C gather: bench_extract's reference row
            continue
        if r.get("search") == "reference":  # the column search the band search replaced
            continue
        out.append(f"| extraction (`extract.csv`) | {r['scene']}, {r['nx']}×{r['ny']}, "
                   f"{r['threads']} thread{'s' if r['threads'] != '1' else ''} | "
                   f"{num(r, 'ms_median', 2)} ms per call |")
    for r in load("data/bench/dfsph.csv"):
        out.append(f"| pressure law (`dfsph.csv`) | {r['particles']} particles, {r['law']} | "
                   f"{num(r, 'ms_per_simulated_s', 0)} ms per simulated s |")
    for r in load("data/bench/render_scenes.csv"):
        out.append(f"| render (`render_scenes.csv`) | {r['scene']}, {r['width']}² | "
                   f"{num(r, 'draw_ms_median', 1)} ms per draw, "
                   f"{num(r, 'frame_fps', 1)} frames/s with the sim |")
    return out


def table_laws():
    """The shipped scenes under each pressure law (bench_laws)."""
    rows = load("data/bench/laws.csv")
    out = ["| scene | particles | law | frames/s, 1 thread (p10–p90) | over the scene's law | "
           "volume ms a frame | sub-steps a frame | DFSPH iterations a frame | "
           "max compression, median (largest) |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        law = r["law"] + (" (the scene's)" if r["law"] == r["scene_law"] else "")
        out.append(f"| {r['scene']} | {r['particles']} | {law} | "
                   f"{num(r, 'fps_median_per_s', 0)} ({num(r, 'fps_p10_per_s', 0)}–"
                   f"{num(r, 'fps_p90_per_s', 0)}) | {num(r, 'fps_over_scene_law', 2)}× | "
                   f"{num(r, 'volume_ms_per_frame', 2)} | {num(r, 'substeps_per_frame', 1)} | "
                   f"{num(r, 'iterations_per_frame', 1)} | "
                   f"{fmt(100 * float(r['max_compression_median']), 2)} % "
                   f"({fmt(100 * float(r['max_compression_max']), 2)} %) |")
    return out


ACCURACY = "data/accuracy/accuracy.csv"
SOLVERS = [("ideal_gas c=", "ideal gas"), ("tait c=", "Tait"), ("dfsph ", "DFSPH")]
COLUMN = "dam-break column H rel. RMS error"
COMPRESSION = "dam-break max compression"


def dam_configs():
    """The dam-break configurations of the committed study, one dict each:
    solver, knob, value, config, particles, CPU and wall ms per simulated
    s, column error and max compression (fractions)."""
    out = {}
    for r in load(ACCURACY):
        if r["study"] != "sph" or r["metric"] not in (COLUMN, COMPRESSION):
            continue
        solver = next((name for prefix, name in SOLVERS if r["config"].startswith(prefix)), None)
        if solver is None:
            continue
        key = r["config"]  # one run however many knobs list it
        c = out.setdefault(key, {"solver": solver, "knob": r["knob"], "value": r["value"],
                                 "config": r["config"], "particles": int(float(r["cells_or_particles"])),
                                 "cpu": float(r["cpu_ms_per_simulated_s"]),
                                 "wall": float(r["wall_ms_per_simulated_s"])})
        c["column" if r["metric"] == COLUMN else "compression"] = float(r["error"])
    return [c for c in out.values() if "column" in c and "compression" in c]


def setting(c):
    """A configuration in words: the config text without the particle count
    (given apart)."""
    words = c["config"].split(", ")
    return ", ".join(w for w in words if not w.endswith(" particles")).replace("_", " ")


def cheapest(configs, solver, column=None, compression=None):
    ok = [c for c in configs if c["solver"] == solver and
          (column is None or c["column"] <= column) and
          (compression is None or c["compression"] <= compression)]
    return min(ok, key=lambda c: c["cpu"]) if ok else None


def table_accuracy_choose():
    """How to choose an SPH solver and its settings: per solver the
    cheapest dam-break configuration (CPU time per simulated second) that
    reaches a residual-column error, a compression, and both."""
    configs = dam_configs()
    if not configs:
        raise Mismatch(f"{ACCURACY} has no dam-break rows")
    goals = [("column H error ≤ 5 %", 0.05, None), ("max compression ≤ 1 %", None, 0.01),
             ("max compression ≤ 0.1 %", None, 0.001), ("column ≤ 5 % and compression ≤ 0.1 %",
                                                         0.05, 0.001)]
    out = ["| solver | goal | cheapest configuration | particles | CPU s per simulated s | "
           "column H error | max compression |", "|---|---|---|---|---|---|---|"]
    for _, solver in SOLVERS:
        for goal, col, comp in goals:
            c = cheapest(configs, solver, col, comp)
            if c is None:
                out.append(f"| {solver} | {goal} | none of the "
                           f"{sum(1 for x in configs if x['solver'] == solver)} run | | | | |")
                continue
            out.append(f"| {solver} | {goal} | {setting(c)} | {c['particles']} | "
                       f"{c['cpu'] / 1000:.2f} | {100 * c['column']:.1f} % | "
                       f"{100 * c['compression']:.3f} % |")
        least = min((x for x in configs if x["solver"] == solver),
                    key=lambda x: (x["compression"], x["cpu"]), default=None)
        if least:
            out.append(f"| {solver} | the least compression of the study | {setting(least)} | "
                       f"{least['particles']} | {least['cpu'] / 1000:.2f} | "
                       f"{100 * least['column']:.1f} % | {100 * least['compression']:.3f} % |")
    return out


REST_MAX = "max compression at rest (all particles)"
REST_MEAN = "mean compression at rest (interior)"


def table_accuracy_choose_rest():
    """The column at rest: per solver the cheapest configuration (CPU time
    per simulated second at rest) whose largest compression reaches 1 %
    and 0.1 %, and the least compression of the study."""
    out_rows = {}
    for r in load(ACCURACY):
        if r["study"] != "sph" or not r["knob"].startswith("rest_") or \
                r["metric"] not in (REST_MAX, REST_MEAN):
            continue
        solver = next((name for prefix, name in
                       [("ideal_gas ", "ideal gas"), ("tait ", "Tait"), ("dfsph ", "DFSPH")]
                       if r["config"].startswith(prefix)), None)
        if solver is None:
            continue
        c = out_rows.setdefault(r["config"], {"solver": solver, "config": r["config"],
                                              "particles": int(float(r["cells_or_particles"])),
                                              "cpu": float(r["cpu_ms_per_simulated_s"])})
        c["max" if r["metric"] == REST_MAX else "mean"] = float(r["error"])
    configs = [c for c in out_rows.values() if "max" in c and "mean" in c]
    if not configs:
        raise Mismatch(f"{ACCURACY} has no rows of the column at rest")

    def words(c):
        return c["config"].split(" at rest, ")[1].replace("_", " ")

    out = ["| solver | goal | cheapest configuration | particles | CPU s per simulated s | "
           "max compression | mean compression |", "|---|---|---|---|---|---|---|"]
    for solver in ("ideal gas", "Tait", "DFSPH"):
        mine = [c for c in configs if c["solver"] == solver]
        for goal, lim in (("max compression ≤ 1 %", 0.01), ("max compression ≤ 0.1 %", 0.001)):
            ok = [c for c in mine if c["max"] <= lim]
            if not ok:
                out.append(f"| {solver} | {goal} | none of the {len(mine)} run | | | | |")
                continue
            c = min(ok, key=lambda c: c["cpu"])
            out.append(f"| {solver} | {goal} | {words(c)} | {c['particles']} | "
                       f"{c['cpu'] / 1000:.2f} | {100 * c['max']:.3f} % | "
                       f"{100 * c['mean']:.3f} % |")
        if mine:
            c = min(mine, key=lambda c: (c["max"], c["cpu"]))
            out.append(f"| {solver} | the least compression of the study | {words(c)} | "
                       f"{c['particles']} | {c['cpu'] / 1000:.2f} | {100 * c['max']:.3f} % | "
                       f"{100 * c['mean']:.3f} % |")
    return out


def table_accuracy_water():
    """Where eq. 2 (c = sqrt(g d)) holds against real water: per depth the
    shortest wavelength from which on every longer one is within 1 %, and
    the error there."""
    rows = [r for r in load(ACCURACY) if r["study"] == "water" and "depth_" in r["knob"]]
    if not rows:
        raise Mismatch(f"{ACCURACY} has no water rows")
    out = []
    for knob in dict.fromkeys(r["knob"] for r in rows):
        pts = sorted((float(r["value"]), float(r["error"])) for r in rows if r["knob"] == knob)
        depth = knob.split("depth_")[1]
        start = None
        for lam, err in reversed(pts):
            if err > 0.01:
                break
            start = (lam, err)
        short = [(lam, err) for lam, err in pts if lam <= 0.1]
        worst = max(err for _, err in short) if short else float("nan")
        if start is None:
            out.append(f"- depth {depth}: no wavelength of the study (up to {pts[-1][0]:g} m) is "
                       "within 1 %.")
        else:
            out.append(f"- depth {depth}: within 1 % from {start[0]:.3g} m on ({100 * start[1]:.2f} % "
                       f"there); at 1 mm to 10 cm off by up to {100 * worst:.0f} %.")
    return out


def table_accuracy_models():
    """Every surface model against real water, simulated: per depth and
    model where it is within 1 %, its worst error on ripples (1 mm to
    10 cm) and on longer waves, and what it costs per cell and sub-step."""
    rows = [r for r in load(ACCURACY) if r["study"] == "water" and
            r["knob"].startswith("lambda_m_model_")]
    if not rows:
        raise Mismatch(f"{ACCURACY} has no simulated surface-model rows (water-models)")
    names = {"lambda_m_model_wave": "eq. 2 (`wave`)",
             "lambda_m_model_dispersive": "dispersive"}
    out = ["| depth | model | within 1 % of real water | worst, 1 mm to 10 cm | "
           "worst, 10 cm to 10 m | CPU ns per cell per sub-step | "
           "CPU ms per simulated s (256², 1 cm cells) |",
           "|---|---|---|---|---|---|---|"]
    for metric in dict.fromkeys(r["metric"] for r in rows):
        depth = metric.split("depth ")[1]
        for knob in dict.fromkeys(r["knob"] for r in rows if r["metric"] == metric):
            sel = [r for r in rows if r["metric"] == metric and r["knob"] == knob]
            pts = sorted((float(r["value"]), float(r["error"])) for r in sel)
            start = None
            for lam, err in reversed(pts):
                if err > 0.01:
                    break
                start = lam
            where = ("every wavelength (1 mm to 10 m)" if start == pts[0][0] else
                     f"from {start:.3g} m on" if start is not None else "at no wavelength")
            short = max(err for lam, err in pts if lam <= 0.1)
            long_ = max(err for lam, err in pts if lam >= 0.1)
            r0 = sel[0]
            ns = 1e6 * float(r0["cpu_ms_per_step"]) / float(r0["cells_or_particles"])
            out.append(f"| {depth} | {names.get(knob, knob)} | {where} | {100 * short:.3g} % | "
                       f"{100 * long_:.3g} % | {ns:.3g} | {float(r0['cpu_ms_per_simulated_s']):.3g} |")
    return out


RERUN = "data/accuracy/rerun.csv"


def table_accuracy_rerun():
    """A second run of the study's cases (data/accuracy/rerun.csv, the same
    commit and machine) against the committed one: per study how many
    configurations both have, the spread of their CPU costs (rerun over
    committed; per simulated second, else per step) and whether every
    error is the same."""
    def cost(r):
        for col in ("cpu_ms_per_simulated_s", "cpu_ms_per_step"):
            v = float(r[col])
            if math.isfinite(v) and v > 0:
                return v
        return None

    first = {(r["study"], r["knob"], r["value"], r["config"], r["metric"]): r
             for r in load(ACCURACY)}
    again = load(RERUN)
    if not again:
        raise Mismatch(f"{RERUN} has no rows")
    out = ["| study | configurations in both runs | cost, rerun / committed: least | median | "
           "largest | within 10 % | errors the same |", "|---|---|---|---|---|---|---|"]
    for study in dict.fromkeys(r["study"] for r in again):
        ratios, seen, same, rows = [], set(), 0, 0
        for r in again:
            if r["study"] != study:
                continue
            o = first.get((r["study"], r["knob"], r["value"], r["config"], r["metric"]))
            if o is None:
                raise Mismatch(f"{RERUN}: {r['study']} {r['knob']} {r['config']} "
                               f"{r['metric']}: not in {ACCURACY} (a rerun of an older "
                               "study: `make accuracy-rerun`)")
            rows += 1
            same += o["error"] == r["error"]
            # (the water models' cost is one grid's for every wavelength)
            cfg = (r["knob"], r["config"]) + ((r["value"],) if study != "water" else ())
            a, b = cost(o), cost(r)
            if cfg in seen or a is None or b is None:
                continue
            seen.add(cfg)
            ratios.append(b / a)
        if not ratios:
            continue
        within = sum(1 for x in ratios if abs(x - 1) <= 0.1)
        out.append(f"| {study} | {len(ratios)} | {min(ratios):.3f} | "
                   f"{statistics.median(ratios):.3f} | {max(ratios):.3f} | "
                   f"{within} of {len(ratios)} | {same} of {rows} rows |")
    return out


def table_accuracy_nsurf():
    """What the wave grid buys in the coupler study: one line per N_surf,
    the band spectrum's distance from the reference and each band's."""
    rows = [r for r in load(ACCURACY) if r["study"] == "coupler" and r["knob"] == "n_surf"]
    if not rows:
        raise Mismatch(f"{ACCURACY} has no coupler n_surf rows")
    metrics = list(dict.fromkeys(r["metric"] for r in rows))
    bands = [m for m in metrics if m.startswith("energy at ")]
    out = ["| N_surf | wave grid | spectrum off by | " +
           " | ".join(m[len("energy at "):].replace(" rel. error", "") + " band off by"
                      for m in bands) + " | wave stages, CPU ms per frame |",
           "|---|---|---|" + "---|" * len(bands) + "---|"]
    for value in dict.fromkeys(r["value"] for r in rows):
        by = {r["metric"]: r for r in rows if r["value"] == value}
        first = by[metrics[0]]
        cells = [f"{100 * float(by[m]['error']):.1f} %" if m in by else "" for m in bands]
        out.append(f"| {float(value):g} | {first['config'].split(',')[0]} | "
                   f"{100 * float(first['error']):.1f} % | " + " | ".join(cells) +
                   f" | {float(first['cpu_ms_per_step']):.2f} |")
    return out


TABLES = {"scenes": table_scenes, "parts": table_parts, "laws": table_laws,
          "accuracy_choose": table_accuracy_choose, "accuracy_water": table_accuracy_water,
          "accuracy_nsurf": table_accuracy_nsurf, "accuracy_models": table_accuracy_models,
          "accuracy_rerun": table_accuracy_rerun,
          "accuracy_choose_rest": table_accuracy_choose_rest}


def process(text, write, page="README.md"):
    """(new text, mismatches)."""
    problems = []

    def line_of(pos):
        return text.count("\n", 0, pos) + 1

    def figure(m):
        quoted, name, selector = m.group(1), m.group(2), m.group(3)
        try:
            want = fmt(lookup(name, selector), decimals(quoted))
        except Mismatch as e:
            problems.append(f"{page}:{line_of(m.start())}: {e}")
            return m.group(0)
        if want != quoted:
            if not write:
                problems.append(f'{page}:{line_of(m.start())}: {quoted} is {want} in {name} '
                                f'("{selector}")')
            prefix = "../" if m.group(0).split("(", 1)[1].startswith("../") else ""
            return f'[{want}]({prefix}{name} "{selector}")'
        return m.group(0)

    def table(m):
        name = m.group(1)
        if name not in TABLES:
            problems.append(f"{page}:{line_of(m.start())}: no bench table {name!r} "
                            f"(known: {', '.join(TABLES)})")
            return m.group(0)
        try:
            want = "\n".join(TABLES[name]()) + "\n"
        except KeyError as e:
            problems.append(f"{page}:{line_of(m.start())}: bench table {name}: no column {e} "
                            "in its CSV")
            return m.group(0)
        except Mismatch as e:
            problems.append(f"{page}:{line_of(m.start())}: {e}")
            return m.group(0)
        if want != m.group(2) and not write:
            have = m.group(2).splitlines()
            for k, line in enumerate(want.splitlines()):
                if k >= len(have) or have[k] != line:
                    problems.append(f"{page}:{line_of(m.start(2)) + k}: bench table {name}: "
                                    f"the CSVs give\n    {line}")
                    break
            else:
                problems.append(f"{page}:{line_of(m.start(2))}: bench table {name} has "
                                f"extra lines")
        return f"<!-- bench-table {name} -->\n{want}<!-- /bench-table -->"

    new = LINK.sub(figure, text)
    new = TABLE.sub(table, new)
    return new, problems


def commit(bench_dir):
    csvs = sorted(glob.glob(os.path.join(bench_dir, "*.csv")))
    if not csvs:
        sys.exit(f"figures: no CSV in {bench_dir} (run `make bench` first)")
    commits, machines = set(), set()
    for path in csvs:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                commits.add(r.get("commit", "?"))
                machines.add(r.get("machine", "?"))
    os.makedirs(DATA, exist_ok=True)
    for old in glob.glob(os.path.join(DATA, "*.csv")):
        os.remove(old)
    for path in csvs:
        shutil.copy(path, DATA)
    today = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    write_readme(sorted(commits), sorted(machines), today, [os.path.basename(p) for p in csvs])


def write_readme(commits, machines, date, names):
    with open(os.path.join(DATA, "README.md"), "w") as f:
        f.write("# Committed bench results\n\n"
                "The CSVs of one `make bench` on a quiet machine; the speed figures\n"
                "of README.md and docs/performance.md link to them and `make check`\n"
                "(`check-bench-figures`, tools/bench/figures.py) fails when one differs.\n\n"
                f"- commit: {', '.join(commits)}\n"
                f"- machine: {', '.join(machines)} (as `make bench` names it in each row)\n"
                f"- date: {date}\n"
                f"- files: {', '.join(names)}\n\n"
                "To refresh: on a quiet machine `make bench`, then `make bench-commit`\n"
                "(copies bench/*.csv here, rewrites this file and every linked figure\n"
                "and generated table of README.md and docs/performance.md); read their\n"
                "diff, whose prose may need to follow the new figures, and commit them.\n")


def main(argv):
    if len(argv) >= 2 and argv[1] == "--commit":
        commit(argv[2] if len(argv) > 2 else os.path.join(ROOT, "bench"))
        argv = [argv[0], "--write"]
    if len(argv) < 2 or argv[1] not in ("--check", "--write"):
        sys.exit(__doc__)
    pages = argv[2:] or [os.path.join(ROOT, p) for p in PAGES]
    failed = 0
    for page in pages:
        name = os.path.relpath(page, ROOT) if os.path.isabs(page) else page
        with open(page) as f:
            text = f.read()
        new, problems = process(text, argv[1] == "--write", name)
        if argv[1] == "--write":
            if problems:
                print("\n".join(problems), file=sys.stderr)
                failed = 1
                continue
            if new != text:
                with open(page, "w") as f:
                    f.write(new)
            print(f"bench figures: {name} follows its CSVs")
            continue
        if problems:
            print("\n".join(problems), file=sys.stderr)
            print(f"check-bench-figures: {len(problems)} figure(s) of {name} differ from "
                  "data/bench/*.csv or data/accuracy/accuracy.csv (after a deliberate `make "
                  "bench`: `make bench-commit`; `make accuracy` rewrites its own)",
                  file=sys.stderr)
            failed = 1
            continue
        figures = len(LINK.findall(text))
        tables = len(TABLE.findall(text))
        if figures + tables == 0:
            print(f"check-bench-figures: {name} links no figure to data/", file=sys.stderr)
            failed = 1
            continue
        print(f"bench figures: {figures} linked figures and {tables} tables of {name} match "
              "their CSVs")
    return failed


if __name__ == "__main__":
    sys.exit(main(sys.argv))
