"""Arrays view the C memory: no copy, read-only where C is const, and after
step() the array a user reads is the new field."""
import ctypes

import numpy as np
import pytest

import modesplit as ms
from conftest import SCENES


def c_pointer(fn, handle):
    nx, ny = ctypes.c_int(), ctypes.c_int()
    return fn(handle._ptr, ctypes.byref(nx), ctypes.byref(ny)), (ny.value, nx.value)


def test_sim_height_is_the_c_buffer():
    with ms.Sim(ms.Scene.load(SCENES / "fig10.json"), threads=2) as sim:
        for _ in range(3):
            sim.step()
        h = sim.height
        ptr, shape = c_pointer(ms.lib().ms_sim_height, sim)
        assert h.shape == shape and h.dtype == np.float32
        assert not h.flags.owndata and not h.flags.writeable
        assert h.ctypes.data == ptr
        assert np.shares_memory(h, sim.height)
        vf = sim.volume_field
        ptr, shape = c_pointer(ms.lib().ms_sim_volume_height, sim)
        assert vf.ctypes.data == ptr and vf.shape == shape == (50, 50)


def test_after_step_the_array_read_is_the_new_field():
    with ms.Sim(ms.Scene.load(SCENES / "fig3.json")) as sim:
        sim.step()
        sim.step()
        before = sim.height.copy()
        sim.step()
        after = sim.height
        ptr, _ = c_pointer(ms.lib().ms_sim_height, sim)
        assert after.ctypes.data == ptr             # the buffer C publishes now
        assert not np.array_equal(before, after)    # waves moved (rain, drops)
        ref = (ctypes.c_float * after.size).from_address(ptr)
        assert np.array_equal(np.frombuffer(ref, np.float32).reshape(after.shape), after)


def test_surface_height_sees_c_writes():
    s = ms.Surface(nx=64, ny=32, dx=0.01)
    h = s.height
    assert h.shape == (32, 64) and not h.flags.owndata and not h.flags.writeable
    z = np.zeros((32, 64), np.float32)
    z[10, 20] = 0.5
    s.set_height(z)
    h = s.height
    assert h[10, 20] == np.float32(0.5) and h.ctypes.data == c_pointer(
        ms.lib().ms_surface_height, s)[0]


def test_sim_particles_are_zero_copy_n_by_3():
    with ms.Sim(ms.Scene.load(SCENES / "fig1.json"), threads=2) as sim:
        for _ in range(3):
            sim.step()
        p, v = sim.positions, sim.velocities
        assert p.shape == v.shape == (2000, 3)
        assert not p.flags.owndata and not p.flags.writeable
        n = ctypes.c_int()
        pos, vel = (ctypes.c_void_p * 3)(), (ctypes.c_void_p * 3)()
        ms.lib().ms_sim_particles(sim._ptr, ctypes.byref(n), pos, vel)
        for a in range(3):
            col = np.frombuffer((ctypes.c_float * n.value).from_address(pos[a]), np.float32)
            assert p[:, a].ctypes.data == pos[a] and np.array_equal(p[:, a], col)
            assert v[:, a].ctypes.data == vel[a]
        # positions inside the domain, some motion after three frames
        assert np.all(np.isfinite(p)) and np.abs(v).max() > 0


def c_particles(v):
    """What ms_volume_particles gives: n and the six column pointers."""
    n = ctypes.c_int()
    pos, vel = (ctypes.c_void_p * 3)(), (ctypes.c_void_p * 3)()
    ms.lib().ms_volume_particles(v._ptr, ctypes.byref(n), pos, vel)
    return n.value, list(pos), list(vel)


def ordered_copy(v):
    """ms_volume_get_particles' copy (insertion order), beside the views."""
    n = v.count
    pos, vel = np.empty((n, 3), np.float32), np.empty((n, 3), np.float32)
    ms.lib().ms_volume_get_particles(v._ptr, pos.ctypes.data, vel.ctypes.data)
    return pos, vel


def test_volume_particles_are_zero_copy_n_by_3():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    p, u = v.positions, v.velocities
    n, pos, vel = c_particles(v)
    assert p.shape == u.shape == (n, 3) == (v.count, 3) and p.dtype == np.float32
    assert not p.flags.owndata and not p.flags.writeable and not u.flags.writeable
    with pytest.raises(ValueError):
        p[0, 0] = 1.0                                  # read-only: C owns it
    for a in range(3):
        assert p[:, a].ctypes.data == pos[a] and u[:, a].ctypes.data == vel[a]
    assert p.strides == (4, pos[1] - pos[0]) and np.shares_memory(p, v.positions)
    want_p, want_u = ordered_copy(v)
    assert np.array_equal(p, want_p) and np.array_equal(u, want_u)
    # the solver's own arrays (internal order) hold the same particles
    (x, y, z), _ = v.particle_views()
    assert x.shape == (n,) and not x.flags.owndata and not x.flags.writeable
    assert np.array_equal(np.sort(x), np.sort(p[:, 0]))


def test_a_volume_view_taken_before_step_reads_the_new_state_after_it():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    p, u = v.positions, v.velocities
    start = p.copy()
    for _ in range(5):
        v.step(1 / 60)
        want_p, want_u = ordered_copy(v)
        assert np.array_equal(p, want_p) and np.array_equal(u, want_u)
    assert not np.array_equal(p, start) and np.abs(u).max() > 0   # the dam broke
    (x, _, _), _ = v.particle_views()
    assert not np.array_equal(x, p[:, 0])    # internal order differs: the view is ordered


def test_a_count_change_while_a_particle_view_lives_raises():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    n = v.count
    col = v.positions[:, 2]          # a slice of a view is a view too
    for call in (lambda: v.fill_box((0.2, 0, 0), (0.4, 0.4, 0.2)),
                 lambda: v.add_particles([[0.3, 0.3, 0.3]]),
                 lambda: v.remove_box((0, 0, 0), (0.1, 0.1, 0.1))):
        with pytest.raises(ms.ViewsAlive, match="del the views") as e:
            call()
        assert isinstance(e.value, BufferError) and isinstance(e.value, ms.StateError)
    assert v.count == n                # refused before C: nothing changed
    v.step(1 / 60)                     # a step is fine: the view follows it
    assert np.array_equal(col, ordered_copy(v)[0][:, 2])
    del col
    removed = v.remove_box((0, 0, 0), (0.1, 0.1, 0.1))
    assert removed > 0 and v.positions.shape == (n - removed, 3)
    v.add_particles(np.full((1, 3), 0.3, np.float32))
    v.fill_box((0.2, 0, 0), (0.4, 0.4, 0.4))    # grows past the storage: moves it
    p = v.positions
    assert p.shape == (v.count, 3) and np.array_equal(p, ordered_copy(v)[0])
    assert p[n - removed].tolist() == pytest.approx([0.3, 0.3, 0.3])


def test_a_sims_particle_views_guard_its_volume_too():
    with ms.Sim(ms.Scene.load(SCENES / "fig1.json")) as sim:
        sim.step()
        p = sim.positions
        vol = sim.volume
        with pytest.raises(ms.ViewsAlive):
            vol.fill_box((0, 0, 0), (0.1, 0.1, 0.1))
        q = vol.positions               # the volume's own block: current state
        assert q.shape == p.shape and np.array_equal(q, ordered_copy(vol)[0])
        del p
        with pytest.raises(ms.ViewsAlive):
            vol.add_particles([[0.5, 0.5, 0.5]])
        del q
        vol.add_particles([[0.5, 0.5, 0.5]])
        assert vol.count == sim.info()["particles"]


def test_a_volume_view_outliving_close_keeps_the_memory():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    v.step(1 / 60)
    p = v.positions
    want = p.copy()
    v.close()
    with pytest.raises(ms.Closed):
        v.positions
    assert v._finalizer.alive and np.array_equal(p, want)
    del p
    assert not v._finalizer.alive


def drawn_fig9a():
    """A fig9a sim stepped once and a small renderer that drew it."""
    sc = ms.Scene.load(SCENES / "fig9a.json")
    try:
        r = ms.Renderer(sc, width=64, height=48, caustics_resolution=64)
    except ms.Unsupported as e:
        pytest.skip("no OSMesa in this build: %s" % e)
    sim = ms.Sim(sc)
    sim.step()
    r.draw(sim)
    return sim, r


def test_renderer_pixels_view():
    sim, r = drawn_fig9a()
    with sim, r:
        px = r.pixels
        w, h = ctypes.c_int(), ctypes.c_int()
        ptr = ms.lib().ms_renderer_pixels(r._ptr, ctypes.byref(w), ctypes.byref(h))
        assert px.shape == (48, 64, 4) and px.dtype == np.uint8 and px.ctypes.data == ptr
        assert not px.flags.owndata and not px.flags.writeable
        assert px[..., 3].min() == 255 and px[..., :3].std() > 0


def test_a_view_outliving_close_keeps_the_memory_until_it_goes():
    sim = ms.Sim(ms.Scene.load(SCENES / "fig1.json"))
    sim.step()
    sim.step()
    h, p = sim.height, sim.positions
    want = h.copy()
    sim.close()
    with pytest.raises(ms.Closed):
        sim.height
    assert sim._finalizer.alive                  # not freed: views are alive
    assert np.array_equal(h, want) and np.isfinite(p).all()
    del h
    assert sim._finalizer.alive                  # p still views it
    del p
    assert not sim._finalizer.alive              # freed with the last view


def test_borrowed_views_hold_the_owner():
    sim = ms.Sim(ms.Scene.load(SCENES / "fig3.json"))
    sim.step()
    h = sim.surface.height                      # a view through a borrowed Surface
    sim.close()
    assert sim._finalizer.alive and h.shape == (300, 300)
    del h
    assert not sim._finalizer.alive


def test_floaters_ride_on_the_surface():
    with ms.Sim(ms.Scene.load(SCENES / "fig10.json")) as sim:
        for _ in range(3):
            sim.step()
        f = sim.floaters
        n = ctypes.c_int()
        ptr = ms.lib().ms_sim_floaters(sim._ptr, ctypes.byref(n))
        assert f.shape == (n.value, 3) and n.value > 0 and f.ctypes.data == ptr
        assert not f.flags.owndata and not f.flags.writeable
        g = sim.grid()
        assert np.all(f[:, 0] >= g["origin"][0]) and np.all(f[:, 0] <= g["origin"][0] + g["nx"] * g["dx"])


def test_caustics_light_map_view():
    sim, r = drawn_fig9a()
    with sim, r:
        c = r.caustics
        assert c.shape == (64, 64) and not c.flags.owndata
        # light is focused and spread, and none is lost: the mean stays 1
        assert c.max() > 1 > c.min() and abs(float(c.mean()) - 1) < 0.1


def test_particle_views_kept_across_a_growing_fill_box_are_refused_not_read_freed():
    # particle_views() are the C arrays themselves (internal order); a
    # fill_box that grows past their storage moves them, so it is refused
    # while a view lives (under `make check-python SAN=asan` a read of the
    # old arrays would be a heap-use-after-free).
    v = ms.Volume(domain_max=(0.8, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    n = v.count
    pos, vel = v.particle_views()
    x, vz = pos[0], vel[2]
    before = x.copy()
    with pytest.raises(ms.ViewsAlive, match="del the views"):
        v.fill_box((0.2, 0, 0), (0.8, 0.4, 0.4))
    assert v.count == n and np.array_equal(x, before) and vz.shape == (n,)
    del pos, vel
    with pytest.raises(ms.ViewsAlive):     # one view left is one too many
        v.fill_box((0.2, 0, 0), (0.8, 0.4, 0.4))
    del x, vz
    v.fill_box((0.2, 0, 0), (0.8, 0.4, 0.4))   # no view left: it grows (and moves)
    assert v.count > 4 * n
    (x, _, _), _ = v.particle_views()
    assert x.shape == (v.count,) and np.isfinite(x).all()


SPLASH = """{"domain": {"min": [0, 0, 0], "max": [0.4, 0.4, 0.5]}, "frame_dt": 0.016667,
 "volume": {"spacing": 0.04, "fill": [{"min": [0, 0, 0], "max": [0.4, 0.4, 0.12]},
            {"min": [0.12, 0.12, 0.3], "max": [0.28, 0.28, 0.45]}], "field": [16, 16]},
 "surface": {"cells": [64, 64], "wave_speed": 0.3, "damping": 0.9},
 "effects": {"spray": {"budget": 300}}}"""


def test_spray_and_foam_views(tmp_path):
    with ms.Sim(ms.Scene.parse(SPLASH)) as sim:
        w = ms.Writer(tmp_path / "s.h5", sim, "combined")
        most = 0
        for _ in range(20):
            sim.step()
            w.frame()
            s = sim.spray
            assert s.shape[1] == 3 and len(s) <= 300 and not s.flags.writeable
            most = max(most, len(s))
        last = sim.spray.copy()
        w.close()
        assert most > 10
        f = sim.foam
        assert f.shape == (64, 64) and f.max() > 0 and f.min() >= 0 and f.max() <= 1
        assert sim.foam_grid()["nx"] == 64 and sim.info()["spray_budget"] == 300
        assert sim.stats()["spray_emitted"] >= most
        with ms.Reader(tmp_path / "s.h5") as r:
            assert r.spray_budget == 300 and r.frames == 20
            assert np.array_equal(r.spray(19), last)
            assert np.array_equal(r.foam(19), f)
    with ms.Sim(ms.Scene.load(SCENES / "fig3.json")) as plain:
        plain.step()
        assert plain.spray.shape == (0, 3) and plain.foam.shape == (0, 0)
        with pytest.raises(ms.StateError):
            plain.foam_grid()
