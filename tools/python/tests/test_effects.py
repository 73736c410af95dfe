"""The scene's effects driven from Python (sim.h's hand controls), cancel()
from another thread, stats, and the surface's excitation: each call does
what its C function promises, and refuses what C refuses."""
import threading

import numpy as np
import pytest

import modesplit as ms
from conftest import SCENES


def test_boat_steered_by_hand_moves_at_the_velocity_given():
    with ms.Sim(ms.Scene.load(SCENES / "fig10.json")) as sim:
        sim.step()
        x0, y0 = sim.boat
        sim.steer_boat((0.1, 0.0))          # m/s, from the next frame on
        sim.run(30)
        x1, y1 = sim.boat
        # 30 frames of 1/60 s at 0.1 m/s: 0.05 m, unless it met the edge
        assert x1 - x0 == pytest.approx(30 * sim.scene.frame_dt * 0.1, rel=0.1)
        assert y1 == pytest.approx(y0, abs=1e-4)
        with pytest.raises(ms.InvalidArgument):
            sim.steer_boat((1e3, 0.0))       # each in [-100, 100] m/s


def test_rain_on_adds_drops_and_off_stops_them():
    with ms.Sim(ms.Scene.load(SCENES / "fig10.json")) as sim:
        sim.set_rain(False)
        sim.run(5)
        drops = sim.surface.info()["drops"]
        sim.run(20)
        assert sim.surface.info()["drops"] == drops
        sim.set_rain(True)
        sim.run(60)
        assert sim.surface.info()["drops"] > drops


def test_the_container_is_moved_and_turned_by_hand():
    with ms.Sim(ms.Scene.load(SCENES / "glass.json")) as sim:
        sim.step()
        pos, q = sim.container_pose
        target = (pos[0] + 0.01, pos[1], pos[2])
        sim.move_container(target)
        tilt = (np.cos(0.1), np.sin(0.1), 0.0, 0.0)   # 0.2 rad about x
        sim.turn_container(tilt)
        sim.step()
        pos2, q2 = sim.container_pose
        assert pos2 == pytest.approx(target, abs=1e-5)
        assert q2 == pytest.approx(tilt, abs=1e-5)
        with pytest.raises(ms.InvalidArgument):
            sim.turn_container((0, 0, 0, 0))          # a zero quaternion
        with pytest.raises(ms.StateError):
            sim.steer_boat((0.1, 0))                   # the glass has no boat


def test_an_obstacle_is_moved_by_hand_and_a_wrong_index_refused():
    with ms.Sim(ms.Scene.load(SCENES / "stir.json")) as sim:
        sim.step()
        sim.move_obstacle(0, (0.4, 0.5, 0.2))
        sim.turn_obstacle(0, (1, 0, 0, 0), omega=(0, 0, 1))
        sim.step()
        with pytest.raises(ms.Error):
            sim.move_obstacle(5, (0.4, 0.5, 0.2))
        with pytest.raises(ms.StateError):
            sim.move_container((0, 0, 0))              # stir has no container


def test_stats_count_the_frames_stepped():
    with ms.Sim(ms.Scene.load(SCENES / "fig1.json")) as sim:
        sim.run(3)
        st = sim.stats()
        assert st["frames"] == 3 and st["volume_steps"] >= 3


def test_cancel_from_another_thread_raises_Canceled_and_the_surface_steps_on():
    s = ms.Surface(nx=512, ny=512, dx=1 / 512, wave_speed=0.5, damping=1.0)
    s.add_drop(0.25, 0.25, 0.03, 0.01)
    errors = []

    def long_step():
        try:
            s.step(10.0)     # ~29 000 sub-steps: far longer than the wait below
        except ms.Canceled as e:
            errors.append(e)
    t = threading.Thread(target=long_step)
    t.start()
    t.join(0.2)
    # the one call another thread may make mid-step; once: a cancel after
    # the step ended would stop the next step at once (as in C)
    s.cancel()
    t.join()
    assert len(errors) == 1 and errors[0].status_name == "MS_ERR_CANCELED"
    reached = s.info()["time"]
    assert 0 <= reached < 10.0
    s.step(1 / 60)
    assert s.info()["time"] == pytest.approx(reached + 1 / 60, abs=1e-6)


def test_excite_adds_gain_times_dh_to_the_field():
    s = ms.Surface(nx=16, ny=8, dx=0.01)
    dh = np.zeros((8, 16), np.float32)
    dh[3, 5] = 0.01
    s.excite(dh, 0.5)
    assert s.height[3, 5] == pytest.approx(0.005) and s.height.sum() == pytest.approx(0.005)
    with pytest.raises(ms.InvalidArgument):
        s.excite(np.zeros((8, 15), np.float32))
