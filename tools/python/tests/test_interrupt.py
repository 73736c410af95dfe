"""Ctrl-C during a long step raises KeyboardInterrupt at the step's next
sub-step (ms_*_cancel), not when the whole step is done, and leaves the
handle usable. Each case runs sigint_step.py in a process of its own."""
import json
import os
import subprocess
import sys
import pathlib

import pytest

HERE = pathlib.Path(__file__).resolve().parent


def run(kind):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    r = subprocess.run([sys.executable, str(HERE / "sigint_step.py"), kind],
                       capture_output=True, text=True, env=env, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    out = json.loads(r.stdout.strip().splitlines()[-1])
    # the latency is printed for a reader (pytest -s), never asserted: a
    # shared machine's clock says nothing about the code
    print("%s: KeyboardInterrupt %.3f s after SIGINT" % (kind, out["latency_s"] or -1))
    return out


@pytest.mark.parametrize("kind", ["surface", "volume"])
def test_sigint_stops_a_long_step_which_stays_usable(kind):
    out = run(kind)
    assert out["latency_s"] is not None, "the step ended without KeyboardInterrupt"
    # stopped part-way: some time simulated, not the whole step asked for
    assert 0 < out["reached"] < out["asked"]
    # and the handle steps on from there
    assert out["after"] == pytest.approx(out["reached"] + 1 / 60, abs=1e-6)
    assert out["finite"]


def test_sigint_stops_a_long_sim_step_and_restore_makes_it_step_again():
    out = run("sim")
    assert out["latency_s"] is not None, "the step ended without KeyboardInterrupt"
    assert out["volume_t0"] < out["reached"] < out["asked"]
    # as in C (sim.h): a canceled sim is failed, its stats still readable
    assert out["step_after_cancel"] == "StateError" and out["stats_frames"] >= 1
    assert out["after"] == pytest.approx(out["t0"] + 1 / 60, abs=1e-6)
    assert out["finite"]
