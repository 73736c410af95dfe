#!/usr/bin/env python3
"""How well two runs of `modesplit accuracy` agree: errors and costs.

    tools/modesplit/cost_spread.py A/parts B/parts

A and B are the parts directories of two runs (`--jobs ... --out A`, or
`--case NAME --out A/parts`) of the same commit. For every case that both
ran, each configuration's CPU cost in B over its cost in A (per simulated
second where the row has it, else per step), and whether every error is
the same. Prints a line per case (configurations, least / median / largest
ratio) and the spread over all; exits 1 when an error differs.
"""
import csv
import math
import os
import statistics
import sys


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cost(r):
    for col in ("cpu_ms_per_simulated_s", "cpu_ms_per_step"):
        v = float(r[col])
        if math.isfinite(v) and v > 0:
            return v
    return None


def main(a_dir, b_dir):
    cases = sorted(n[:-4] for n in os.listdir(a_dir)
                   if n.endswith(".csv") and os.path.exists(os.path.join(b_dir, n)))
    if not cases:
        print(f"no case in both {a_dir} and {b_dir}")
        return 1
    every, bad = [], 0
    print(f"{'case':20s} {'configs':>7s} {'least':>7s} {'median':>7s} {'largest':>7s}  (cost B / A)")
    for case in cases:
        a = rows(os.path.join(a_dir, case + ".csv"))
        b = {(r["knob"], r["value"], r["config"], r["metric"]): r
             for r in rows(os.path.join(b_dir, case + ".csv"))}
        ratios, seen = [], set()
        for r in a:
            key = (r["knob"], r["value"], r["config"], r["metric"])
            o = b.get(key)
            if o is None or o["error"] != r["error"]:
                print(f"  {case}: {key}: error {r['error']} in A, "
                      f"{o['error'] if o else 'no row'} in B")
                bad += 1
                continue
            # one ratio a configuration (its metrics share the run's cost)
            # (the water models' cost is one grid's for every wavelength)
            cfg = (r["knob"], r["config"]) + ((r["value"],) if r["study"] != "water" else ())
            ca, cb = cost(r), cost(o)
            if cfg in seen or ca is None or cb is None:
                continue
            seen.add(cfg)
            ratios.append(cb / ca)
        every += ratios
        if ratios:
            print(f"{case:20s} {len(ratios):7d} {min(ratios):7.3f} {statistics.median(ratios):7.3f} "
                  f"{max(ratios):7.3f}")
    if every:
        within = sum(1 for x in every if abs(x - 1) <= 0.1)
        print(f"{'all':20s} {len(every):7d} {min(every):7.3f} {statistics.median(every):7.3f} "
              f"{max(every):7.3f}  ({within} of {len(every)} within 10 %)")
    print("errors: " + ("all the same" if not bad else f"{bad} differ"))
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
