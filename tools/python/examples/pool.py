"""The paper's Fig. 1 pool from Python: load data/scenes/fig1.json, step 120
frames, and save one figure with the combined height field, the particles
coloured by speed, and the per-stage cost of each frame.

    python tools/python/examples/pool.py --out pool.png
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import modesplit as ms  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[3]
STAGES = ["volume_ms", "extract_ms", "surface_ms", "combine_ms", "total_ms"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=str(ROOT / "data" / "scenes" / "fig1.json"))
    ap.add_argument("--frames", type=int, default=120)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default="pool.png")
    args = ap.parse_args()

    cost = {s: [] for s in STAGES}
    with ms.Sim(ms.Scene.load(args.scene), threads=args.threads) as sim:
        last = sim.stats()
        for _ in range(args.frames):
            sim.step()
            now = sim.stats()
            for s in STAGES:            # stats are totals since creation
                cost[s].append(now[s] - last[s])
            last = now
        g = sim.grid("combined")
        height = sim.height.copy()      # views are valid until the next step
        pos, vel = sim.positions.copy(), sim.velocities.copy()
        t = sim.time

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    x0, y0 = g["origin"]
    extent = [x0, x0 + g["nx"] * g["dx"], y0, y0 + g["ny"] * g["dy"]]
    im = ax[0].imshow(height, origin="lower", extent=extent, cmap="viridis")
    fig.colorbar(im, ax=ax[0], label="height above the floor (m)")
    ax[0].set_title("combined height field, t = %.2f s" % t)
    speed = np.linalg.norm(vel, axis=1)
    sc = ax[1].scatter(pos[:, 0], pos[:, 1], c=speed, s=4, cmap="plasma")
    fig.colorbar(sc, ax=ax[1], label="speed (m/s)")
    ax[1].set_aspect("equal")
    ax[1].set_title("%d SPH particles (top view)" % len(pos))
    for s in STAGES:
        ax[2].plot(cost[s], label=s[:-3])
    ax[2].set_xlabel("frame")
    ax[2].set_ylabel("ms per frame")
    ax[2].set_title("per-stage cost, %d thread(s)" % args.threads)
    ax[2].legend()
    for a in ax[:2]:
        a.set_xlabel("x (m)")
        a.set_ylabel("y (m)")
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)
    print("pool: %d frames, %d particles, mean %.2f ms/frame; wrote %s"
          % (args.frames, len(pos), float(np.mean(cost["total_ms"])), args.out))


if __name__ == "__main__":
    main()
