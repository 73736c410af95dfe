"""A small parameter sweep run in parallel processes (concurrent.futures):
a drop in a closed basin for several wave speeds and dampings. For each case it
measures when the ring first reaches a probe 0.3 m away (it should scale as
1 / wave_speed) and the wave energy left after 2 s: the damping is the
fraction of the wave velocity kept per second, so the energy, which
oscillates between its kinetic and potential halves, keeps damping^t after
t seconds (damping^2 here) whatever the speed. Writes a table and a figure.

    python tools/python/examples/sweep.py --out sweep.png --workers 2

run_case() is a plain function of plain arguments returning a dict: the
same function runs unchanged under Dask (client.map(run_case, ...)) or Ray
(ray.remote(run_case)) when a sweep outgrows one machine.
"""
import argparse
import concurrent.futures
import itertools

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import modesplit as ms  # noqa: E402

N, DX = 128, 0.01            # 1.28 m basin
DROP = (0.64, 0.64)          # m, centre
PROBE = (0.94, 0.64)         # m, 0.3 m to the east
FRAME = 1 / 120              # s


def run_case(wave_speed, damping, seconds=2.0):
    with ms.Surface(nx=N, ny=N, dx=DX, wave_speed=wave_speed, damping=damping,
                    boundary="reflect") as s:
        s.add_drop(*DROP, radius=0.04, amplitude=0.01)
        e0 = s.energy
        i, j = int(PROBE[1] / DX), int(PROBE[0] / DX)
        arrival = None
        for k in range(int(round(seconds / FRAME))):
            s.step(FRAME)
            if arrival is None and abs(float(s.height[i, j])) > 2e-4:
                arrival = (k + 1) * FRAME
        return {"wave_speed": wave_speed, "damping": damping, "arrival_s": arrival,
                "energy_left": s.energy / e0}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="sweep.png")
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()
    speeds, dampings = [0.25, 0.5, 1.0], [1.0, 0.7, 0.4]
    cases = list(itertools.product(speeds, dampings))
    with concurrent.futures.ProcessPoolExecutor(max_workers=args.workers) as pool:
        results = list(pool.map(run_case, *zip(*cases)))
    print("%10s %8s %10s %12s" % ("speed m/s", "damping", "arrival s", "energy left"))
    for r in results:
        print("%10.2f %8.2f %10s %12.4f" % (r["wave_speed"], r["damping"],
                                            "-" if r["arrival_s"] is None
                                            else "%.3f" % r["arrival_s"], r["energy_left"]))
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for c in speeds:
        rs = [r for r in results if r["wave_speed"] == c]
        ax[1].plot([r["damping"] for r in rs], [r["energy_left"] for r in rs], "o-",
                   label="c = %.2f m/s" % c)
    und = [r for r in results if r["damping"] == 1.0]
    ax[0].loglog([r["wave_speed"] for r in und], [r["arrival_s"] for r in und], "o-",
                 label="measured")
    ax[0].loglog(speeds, [0.3 / c for c in speeds], "k--", label="0.3 m / c")
    ax[0].set_xlabel("wave speed (m/s)")
    ax[0].set_ylabel("arrival at the probe (s)")
    ax[0].legend()
    ax[1].set_xlabel("damping (fraction kept per s)")
    ax[1].set_ylabel("energy left after 2 s")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)
    print("sweep: %d cases on %d processes; wrote %s" % (len(results), args.workers, args.out))
    return results


if __name__ == "__main__":
    main()
