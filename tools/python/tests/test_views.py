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


def test_volume_particle_views_and_copies():
    v = ms.Volume()
    v.fill_box((0, 0, 0), (0.2, 0.2, 0.2))
    (x, y, z), (vx, vy, vz) = v.particle_views()
    assert x.shape == (v.count,) and not x.flags.owndata and not x.flags.writeable
    pos = v.positions
    assert pos.flags.owndata and pos.shape == (v.count, 3)
    assert np.array_equal(np.sort(pos[:, 0]), np.sort(x))


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
