"""The objects do what their C parts do, seen from Python."""
import subprocess
import sys

import numpy as np
import pytest

import modesplit as ms
from conftest import SCENES


def test_undamped_closed_basin_keeps_its_energy():
    s = ms.Surface(nx=64, ny=64, dx=0.01, wave_speed=0.5, damping=1.0, boundary="reflect")
    s.add_drop(0.3, 0.35, 0.05, 0.01)
    e0 = s.energy
    for _ in range(60):
        s.step(1 / 60)
    assert e0 > 0 and abs(s.energy / e0 - 1) < 1e-4
    assert s.info()["substeps"] > 60 and s.desc()["boundary"] == 0


def test_dispersive_surface_ring_travels_at_its_group_speed():
    """model="dispersive": a 2 cm drop in 10 cm of water sends its ring out
    at the group speed of its ~4 cm waves (~0.15 m/s), not at eq. 2's
    sqrt(g d) = 1 m/s; the model and its constants read back."""
    radius = {}
    for model in ("wave", "dispersive"):
        s = ms.Surface(nx=128, ny=128, dx=0.005, wave_speed=1.0, damping=1.0, model=model)
        s.add_drop(0.32, 0.32, 0.02, 0.005)
        e0 = s.energy
        s.step(0.15)
        assert abs(s.energy / e0 - 1) < 1e-3          # kept, undamped
        row = np.abs(s.height[64, 64:])
        radius[model] = (np.argmax(row) + 0.5) * 0.005
        d = s.desc()
        assert d["model"] == (1 if model == "dispersive" else 0)
        assert abs(d["gravity"] - 9.81) < 1e-6 and d["surface_tension"] > 0
    assert abs(radius["wave"] - 0.15) < 0.03
    assert radius["dispersive"] < 0.5 * radius["wave"]
    with pytest.raises(ms.InvalidArgument, match="airy"):
        ms.Surface(nx=8, ny=8, model="airy")


def test_current_carries_a_packet_at_c_plus_u():
    """set_current: a packet on a uniform 0.2 m/s current runs at c + U
    (its still-water speed plus U); None takes the current away."""
    speed = {}
    for U in (0.0, 0.2):
        s = ms.Surface(nx=512, ny=4, dx=0.01, wave_speed=0.5, damping=1.0, boundary="periodic")
        x = (np.arange(512) + 0.5) * 0.01 - 1.5
        h = 0.01 * np.exp(-x * x / 0.045) * np.cos(2 * np.pi * x / 0.16)
        s.set_height(np.tile(h, (4, 1)).astype(np.float32))
        if U:
            s.set_current(U, 0.0)
        s.step(2.0)
        f = s.height[0] ** 2
        mid = int((1.5 + 2.0 * U) / 0.01)
        speed[U] = (np.sum(f[mid:] * x[mid:]) / np.sum(f[mid:])) / 2.0
        s.set_current(None)
    assert abs(speed[0.2] - speed[0.0] - 0.2) < 0.005
    assert s.desc()["turbulence_damping"] > 1.0
    with pytest.raises(ms.InvalidArgument, match="100 m/s"):
        s.set_current(np.full((4, 512), 200.0, np.float32), 0.0)


def test_speed_map_zero_is_dry_and_mask_is_solid():
    s = ms.Surface(nx=32, ny=32, dx=0.01, damping=1.0)
    mask = np.zeros((32, 32), np.uint8)
    mask[:, 16:] = 1                       # the east half is solid
    s.set_obstacle_mask(mask)
    s.add_drop(0.08, 0.16, 0.04, 0.01)
    for _ in range(30):
        s.step(1 / 60)
    assert np.all(s.height[:, 16:] == 0) and np.abs(s.height[:, :16]).max() > 0
    s.set_obstacle_mask(None)


def test_volume_keeps_its_particles_in_the_box():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
    n = v.count
    for _ in range(20):
        v.step(1 / 60)
    p = v.positions
    assert v.count == len(v) == n > 100
    assert p.min() >= 0 and p.max() <= 0.4
    h = v.extract_height(20, 20)
    assert h.shape == (20, 20) and h.max() > 0.05 and v.kinetic_energy > 0
    assert v.info()["count"] == n and v.desc()["domain_max"] == pytest.approx([0.4] * 3)


def test_shape_distance_and_collider():
    with ms.Shape("sphere", {"radius": 0.1}) as sph:
        sph.set_pose((0.5, 0.5, 0.5))
        d, normal = sph.distance((0.5, 0.5, 0.8))
        assert d == pytest.approx(0.2, abs=1e-5) and normal == pytest.approx((0, 0, 1), abs=1e-5)
        assert sph.kind == "sphere"
        v = ms.Volume()
        v.add_collider(sph)
        v.remove_collider(sph)


def test_sim_from_desc_with_volume_and_surface():
    with ms.Sim.from_desc(volume=dict(domain_max=(0.5, 0.5, 0.3)),
                          surface=dict(nx=64, ny=64, dx=0.5 / 64), field=(16, 16),
                          threads=2) as sim:
        sim.volume.fill_box((0, 0, 0), (0.2, 0.5, 0.2))
        sim.surface.add_drop(0.35, 0.25, 0.03, 0.005)
        for _ in range(5):
            sim.step(1 / 60)
        assert sim.height.shape == (64, 64) and sim.volume_field.shape == (16, 16)
        info = sim.info()
        assert info["has_volume"] and info["has_surface"] and info["threads"] == 2
        assert sim.positions.shape == (sim.volume.count, 3)
        assert sim.frame == 5 and sim.stats()["frames"] == 5
        with pytest.raises(ms.InvalidArgument):
            sim.step()                   # no scene: frame_dt must be given


def test_writer_reader_round_trip(tmp_path):
    path = tmp_path / "run.h5"
    with ms.Sim(ms.Scene.load(SCENES / "fig1.json")) as sim:
        frames = []
        with ms.Writer(path, sim, ["combined", "particles"]) as w:
            for _ in range(4):
                sim.step()
                w.frame()
                frames.append((sim.height.copy(), sim.positions.copy()))
            assert w.frames == 4
    with ms.Reader(path) as r:
        assert r.frames == 4 and r.fields == ["combined", "particles"]
        data = r.read("combined")
        for i, (h, p) in enumerate(frames):
            assert np.array_equal(data[i], h) and np.array_equal(r.field("combined", i), h)
            pos, vel = r.particles(i)
            assert np.array_equal(pos, p) and vel.shape == p.shape
        assert r.frame_dt == pytest.approx(1 / 60, rel=1e-3) and '"name"' in r.scene
    with pytest.raises(ms.IoError):
        ms.Reader(tmp_path / "none.h5")


def test_renderer_writes_a_png(tmp_path):
    try:
        r = ms.Renderer(width=64, height=48, caustics_resolution=64)
    except ms.Unsupported as e:
        pytest.skip("no OSMesa in this build: %s" % e)
    with r, ms.Sim(ms.Scene.load(SCENES / "fig3.json")) as sim:
        with pytest.raises(ms.StateError):
            r.draw(sim)                  # before the sim's first step
        sim.step()
        r.draw(sim)
        r.write_png(tmp_path / "f.png")
        assert (tmp_path / "f.png").read_bytes()[:4] == b"\x89PNG"
        assert r.stats()["frames"] == 1
    with pytest.raises(ms.InvalidArgument, match="width"):
        ms.Renderer(width=1)


def test_main_version_and_export_dispatch(monkeypatch, capsys):
    import types

    from modesplit.__main__ import main
    assert main(["version"]) == 0 and "libmodesplit 0." in capsys.readouterr().out
    seen = []
    fake = types.ModuleType("modesplit.usd_export")
    fake.main = lambda argv: seen.append(argv) or 0
    monkeypatch.setitem(sys.modules, "modesplit.usd_export", fake)
    assert main(["export", "run.h5", "--out", "run.usda"]) == 0
    assert seen == [["run.h5", "--out", "run.usda"]]
    fake.main = lambda: seen.append(sys.argv[1:]) or 0     # an argparse main()
    assert main(["export", "b.h5"]) == 0 and seen[-1] == ["b.h5"]


def test_main_runs_as_a_module():
    r = subprocess.run([sys.executable, "-m", "modesplit", "version"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and r.stdout.startswith("libmodesplit ")


def test_a_moving_disturber_makes_waves_a_still_one_a_dent():
    s = ms.Surface(nx=96, ny=64, dx=0.01, wave_speed=0.3, damping=1.0, boundary="absorb")
    boat = s.add_disturber(0.2, 0.32, radius=0.04, depth=0.01, vx=0.25)
    for _ in range(60):
        s.step(1 / 60)
    x, y = s.disturber_position(boat)
    assert x == pytest.approx(0.45, abs=0.01) and y == pytest.approx(0.32, abs=1e-6)
    assert s.height.min() < -0.002 and s.energy > 0
    s.set_disturber_path(boat, [[0.45, 0.32], [0.6, 0.32]], 0.1)
    with pytest.raises(ms.InvalidArgument, match="shape"):
        s.set_disturber_path(boat, [[0.45, 0.32, 0.0]], 0.1)
    s.remove_disturber(boat)
    with pytest.raises(ms.InvalidArgument):
        s.move_disturber(boat, 0.1, 0.1)


def test_plugins_are_listed():
    kinds = {(p["name"], p["kind"]) for p in ms.plugins()}
    assert ("sphere", "shape") in kinds and ("water", "shader") in kinds


def test_sims_step_in_python_threads_with_their_own_errors():
    import concurrent.futures

    def run(i):
        with ms.Sim(ms.Scene.load(SCENES / "fig3.json")) as sim:
            for _ in range(20):
                sim.step()
            h = sim.height.tobytes()
        try:                    # the sentence is the calling thread's own
            ms.Surface(wave_speed=-(i + 1))
        except ms.InvalidArgument as e:   # a value outside its domain
            return h, e.message
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        out = list(pool.map(run, range(4)))
    assert len({h for h, _ in out}) == 1          # deterministic, any thread
    for i, (_, msg) in enumerate(out):
        assert "wave_speed %d m/s" % -(i + 1) in msg, msg
