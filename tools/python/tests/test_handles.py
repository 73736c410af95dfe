"""Handles a Python user cannot crash: no copy or pickle of a C handle,
views that cannot be made writeable, integers checked before ctypes wraps
them, wrong scalar types as modesplit.InvalidArgument, and one call at a
time per handle (a second thread gets StateError, close() waits)."""
import copy
import pickle
import threading
import time

import numpy as np
import pytest

import modesplit as ms


def small_sim():
    return ms.Sim.from_desc(volume=dict(domain_max=(0.3, 0.3, 0.3)),
                            surface=dict(nx=64, ny=64, dx=0.3 / 64), field=(16, 16))


def handles():
    return [ms.Surface(nx=32, ny=32), ms.Volume(domain_max=(0.3, 0.3, 0.3)), small_sim()]


@pytest.mark.parametrize("how", ["copy", "deepcopy", "pickle"])
def test_copy_deepcopy_and_pickle_of_a_handle_raise_TypeError_naming_snapshot(how):
    for h in handles():
        with h:
            with pytest.raises(TypeError, match="snapshot"):
                if how == "copy":
                    copy.copy(h)
                elif how == "deepcopy":
                    copy.deepcopy(h)
                else:
                    pickle.dumps(h)
            assert not h.closed  # the refusal left the handle as it was


def test_a_sim_state_is_copied_through_snapshot_and_restore():
    a, b = small_sim(), small_sim()
    with a, b:
        for _ in range(3):
            a.step(1 / 60)
        blob = a.snapshot()
        assert isinstance(blob, bytes) and len(blob) > 72
        b.restore(blob)
        a.step(1 / 60)
        b.step(1 / 60)
        assert np.array_equal(a.height, b.height)
        with pytest.raises(ms.InvalidArgument):
            b.restore(blob[:50])
        with pytest.raises(ms.InvalidArgument):
            b.restore("not bytes")


def test_views_cannot_be_made_writeable():
    with ms.Surface(nx=32, ny=32) as s, small_sim() as sim, \
            ms.Volume(domain_max=(0.4, 0.4, 0.4)) as vol:
        sim.step(1 / 60)
        vol.fill_box((0, 0, 0), (0.2, 0.2, 0.2))
        views = [s.height, sim.height, vol.positions, vol.velocities]
        views += [sim.positions]  # no particles: an empty array, read-only all the same
        for v in views:
            assert not v.flags.writeable
            with pytest.raises(ValueError):
                v.setflags(write=True)
            with pytest.raises(ValueError):
                v.flags.writeable = True
            if v.size:
                assert not v.flags.owndata
                with pytest.raises(ValueError):
                    v[(0,) * v.ndim] = 1.0
        del views


def test_integers_are_range_checked_before_ctypes():
    for nx in (2**32 + 64, 2**40, 2**31, -2**31 - 1):
        with pytest.raises(ms.InvalidArgument, match="range"):
            ms.Surface(nx=nx, ny=64)
    for bad in (True, 64.0, "64", None.__class__):
        with pytest.raises(ms.InvalidArgument):
            ms.Surface(nx=bad, ny=64)
    with ms.Surface(nx=64, ny=64) as s:
        with pytest.raises(ms.InvalidArgument, match="range"):
            s.remove_disturber(2**32 + 1)


def test_wrong_scalar_types_raise_InvalidArgument():
    with ms.Surface(nx=64, ny=64) as s:
        for call in (lambda: s.step("0.1"), lambda: s.step(None),
                     lambda: s.add_drop("a", 0.5, 0.1, 0.01),
                     lambda: ms.Surface(nx=64, ny=64, dx="x"),
                     lambda: ms.Surface(nx=64, ny=64, wave_speed=[1])):
            with pytest.raises(ms.InvalidArgument):
                call()
        s.step(0.01)  # still usable


def busy_step(h, dt, done):
    try:
        h.step(dt)
    finally:
        done.set()


def test_a_second_thread_on_a_handle_gets_StateError_and_close_waits():
    """One rule for Surface, Volume and Sim (docs/python.md): a call while
    another thread is in a call on the same handle raises StateError at once;
    close() from another thread waits for the running call, then closes."""
    s = ms.Surface(nx=2048, ny=2048)
    done = threading.Event()
    t = threading.Thread(target=busy_step, args=(s, 4.0, done))
    t.start()
    refused = 0
    while not done.is_set():
        try:
            s.step(0.001)
        except ms.StateError as e:
            assert "another thread" in str(e)
            refused += 1
            break
        time.sleep(0.0005)
    assert refused == 1, "the long step ended before a second call could meet it"
    # close() while the step still runs: it waits for the step
    s.close()
    assert done.is_set(), "close() returned while the step ran"
    t.join()
    assert s.closed
    with pytest.raises(ms.Closed):
        s.step(0.01)


@pytest.mark.parametrize("make", [lambda: ms.Volume(domain_max=(0.4, 0.4, 0.4)), small_sim])
def test_volume_and_sim_follow_the_same_rule(make):
    h = make()
    lock = h._root()._lock
    lock.acquire()  # as a call running in this thread would hold it
    try:
        err = []
        t = threading.Thread(target=lambda: err.append(
            pytest.raises(ms.StateError, h.step, 1 / 60)))
        t.start()
        t.join()
        assert err and "another thread" in str(err[0].value)
        closed = threading.Event()
        c = threading.Thread(target=lambda: (h.close(), closed.set()))
        c.start()
        time.sleep(0.2)
        assert not closed.is_set(), "close() did not wait for the running call"
    finally:
        lock.release()
    c.join(5)
    assert closed.is_set() and h.closed
