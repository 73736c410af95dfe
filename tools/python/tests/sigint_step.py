"""Ctrl-C during a long step (run by test_interrupt.py in a process of its
own, so that a SIGINT landing elsewhere cannot stop the test session).

    python sigint_step.py surface|volume|sim

Starts a step that takes seconds, sends this process SIGINT 0.3 s later
(from a thread, as a terminal's Ctrl-C reaches the main thread), catches
the KeyboardInterrupt and prints one JSON line: the simulated time the step
reached, the time it asked for, the seconds from the signal to the
exception, and what the handle does next."""
import json
import os
import signal
import sys
import threading
import time

import modesplit as ms

DELAY = 0.3  # s after the step starts


def interrupt_during(step):
    sent = []

    def send():
        time.sleep(DELAY)
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)
    t = threading.Thread(target=send)
    t.start()
    try:
        step()
    except KeyboardInterrupt:
        caught = time.monotonic()
    else:
        caught = None
    t.join()
    return None if caught is None else caught - sent[0]


def main(kind):
    out = {"kind": kind}
    if kind == "surface":
        # 1024^2 cells, 10 s: ~7 000 sub-steps, far longer than DELAY
        s = ms.Surface(nx=1024, ny=1024, dx=1 / 1024, wave_speed=0.5, damping=1.0)
        s.add_drop(0.5, 0.5, 0.05, 0.01)
        out["asked"] = 10.0
        out["latency_s"] = interrupt_during(lambda: s.step(10.0))
        out["reached"] = s.info()["time"]
        s.step(1 / 60)  # usable: the next step runs from where it stopped
        out["after"] = s.info()["time"]
        out["finite"] = bool(abs(float(s.height.sum())) < float("inf"))
    elif kind == "volume":
        v = ms.Volume(domain_max=(0.6, 0.6, 0.6))
        v.fill_box((0, 0, 0), (0.3, 0.6, 0.3))
        out["asked"] = 10.0
        out["latency_s"] = interrupt_during(lambda: v.step(10.0))
        out["reached"] = v.info()["time"]
        v.step(1 / 60)
        out["after"] = v.info()["time"]
        out["finite"] = bool(abs(float(v.positions.sum())) < float("inf"))
    else:
        sim = ms.Sim.from_desc(volume=dict(domain_max=(1, 1, 0.4), spacing=0.04),
                               surface=dict(nx=256, ny=256, dx=1 / 256), field=(32, 32))
        sim.volume.fill_box((0, 0, 0), (0.4, 1, 0.2))
        sim.step(1 / 60)
        blob = sim.snapshot()
        t0 = sim.time
        out["volume_t0"] = sim.volume.info()["time"]
        out["asked"] = out["volume_t0"] + 10.0
        out["latency_s"] = interrupt_during(lambda: sim.step(10.0))
        out["reached"] = sim.volume.info()["time"]
        try:
            sim.step(1 / 60)
            out["step_after_cancel"] = "ran"
        except ms.StateError:
            out["step_after_cancel"] = "StateError"
        out["stats_frames"] = sim.stats()["frames"]
        sim.restore(blob)  # a restore clears the failed sim (sim.h)
        sim.step(1 / 60)
        out["after"] = sim.time
        out["t0"] = t0
        out["finite"] = bool(abs(float(sim.height.sum())) < float("inf"))
    print(json.dumps(out))


if __name__ == "__main__":
    main(sys.argv[1])
