"""modesplit export --usd: read the USD back with pxr and compare with the run file.

Run by tools/usd_tests/check.sh (make check-usd): MODESPLIT builds the run
with the C tool, PYTHONPATH holds tools/python.
"""
import os
import subprocess
import sys

import h5py
import numpy as np
import pytest
from pxr import Usd, UsdGeom

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.environ.get("MODESPLIT", os.path.join(ROOT, "build", "bin", "modesplit"))
SCENE = os.path.join(ROOT, "data", "scenes", "default.json")


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    d = tmp_path_factory.mktemp("usd")
    h5 = str(d / "run.h5")
    subprocess.run([TOOL, "run", SCENE, "--frames", "9", "--out", h5, "--quiet"], check=True)
    return h5


def export_py(h5, usd, *extra):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "tools", "python"))
    return subprocess.run([sys.executable, "-m", "modesplit.usd_export", h5, "--usd", usd, *extra],
                          env=env, capture_output=True, text=True)


def test_mesh_and_points_match_the_run_file(run, tmp_path):
    usd = str(tmp_path / "run.usdc")
    r = export_py(run, usd)
    assert r.returncode == 0, r.stderr
    stage = Usd.Stage.Open(usd)
    with h5py.File(run, "r") as f:
        frames = int(f.attrs["frames"])
        assert frames == 5  # 9 frames, every 2nd written
        fps = 1.0 / (float(f.attrs["frame_dt"]) * int(f.attrs["output_every"]))
        assert stage.GetTimeCodesPerSecond() == pytest.approx(fps, rel=1e-4)
        assert stage.GetStartTimeCode() == 0 and stage.GetEndTimeCode() == frames - 1
        assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
        mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Run/Surface"))
        assert mesh
        pts = mesh.GetPointsAttr()
        assert pts.GetTimeSamples() == [float(k) for k in range(frames)]
        ds = f["fields/combined"]
        _, ny, nx = ds.shape
        for k in (0, frames // 2, frames - 1):
            p = np.asarray(pts.Get(k))
            assert p.shape == (nx * ny, 3)
            # a frame's heights equal the run file's, bit for bit (float32)
            assert np.array_equal(p[:, 2], ds[k].ravel())
            n = np.asarray(mesh.GetNormalsAttr().Get(k))
            assert n.shape == (nx * ny, 3)
            assert np.allclose(np.linalg.norm(n, axis=1), 1, atol=1e-5) and (n[:, 2] > 0).all()
        # cell centres in x and y
        dx, dy = ds.attrs["dx"]
        x0, y0 = ds.attrs["origin"]
        p0 = np.asarray(pts.Get(0))
        assert p0[0, 0] == pytest.approx(x0 + 0.5 * dx) and p0[0, 1] == pytest.approx(y0 + 0.5 * dy)
        assert p0[nx, 1] == pytest.approx(y0 + 1.5 * dy)
        counts = np.asarray(mesh.GetFaceVertexCountsAttr().Get())
        assert len(counts) == (nx - 1) * (ny - 1) and (counts == 4).all()
        st = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("st")
        uv = np.asarray(st.Get())
        assert uv.shape == (nx * ny, 2) and uv.min() > 0 and uv.max() < 1
        # particles: counts, positions, velocities, ids per frame
        pts = UsdGeom.Points(stage.GetPrimAtPath("/Run/Particles"))
        assert pts
        assert pts.GetPointsAttr().GetTimeSamples() == [float(k) for k in range(frames)]
        for k in (0, frames - 1):
            s = f[f"Step#{k}"]
            p = np.asarray(pts.GetPointsAttr().Get(k))
            v = np.asarray(pts.GetVelocitiesAttr().Get(k))
            assert len(p) == len(s["x"])
            assert np.array_equal(p, np.stack([s["x"][:], s["y"][:], s["z"][:]], 1))
            assert np.array_equal(v, np.stack([s["vx"][:], s["vy"][:], s["vz"][:]], 1))
            assert np.array_equal(np.asarray(pts.GetIdsAttr().Get(k)), np.arange(len(p)))


def test_the_tool_runs_the_exporter(run, tmp_path):
    usd = str(tmp_path / "t.usda")
    r = subprocess.run([TOOL, "export", run, "--usd", usd], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert Usd.Stage.Open(usd).GetPrimAtPath("/Run/Surface")


def test_refusals_name_the_problem(run, tmp_path):
    r = export_py(run, str(tmp_path / "x.obj"))
    assert r.returncode == 2 and "must end in .usdc" in r.stderr
    bad = tmp_path / "not_a_run.h5"
    with h5py.File(bad, "w") as f:
        f["x"] = 1
    r = export_py(str(bad), str(tmp_path / "y.usdc"))
    assert r.returncode == 2 and "not a modesplit run file" in r.stderr
    r = export_py(str(tmp_path / "missing.h5"), str(tmp_path / "z.usdc"))
    assert r.returncode == 1 and "cannot open" in r.stderr
    r = subprocess.run([TOOL, "export", run], capture_output=True, text=True)
    assert r.returncode == 2 and "--usd" in r.stderr


def test_time_codes_per_second_are_exact_for_1_over_n():
    sys.path.insert(0, os.path.join(ROOT, "tools", "python"))
    from modesplit.usd_export import frame_rate
    assert frame_rate(0.016667, 1) == 60.0  # 1/60 s as a scene writes it
    assert frame_rate(1 / 60, 1) == 60.0
    assert frame_rate(0.016667, 2) == 30.0
    assert frame_rate(0.04, 1) == 25.0
    assert frame_rate(1 / 24, 1) == 24.0
    assert frame_rate(0.3, 1) == pytest.approx(1 / 0.3, rel=1e-15)  # no whole rate near
    assert frame_rate(0.0, 1) == 24.0


def test_the_stage_rate_and_metadata_as_the_scene_says(tmp_path):
    """frame_dt 0.016667 (1/60 s in decimal) gives exactly 60 time codes per
    second, and the scene's name is stored as text, not a bytes repr."""
    import json
    scene = json.load(open(SCENE))
    scene["frame_dt"] = 0.016667
    scene["output"]["every"] = 1
    scene["name"] = "fig10"
    sp = tmp_path / "s.json"
    sp.write_text(json.dumps(scene))
    h5 = str(tmp_path / "r.h5")
    subprocess.run([TOOL, "run", str(sp), "--frames", "3", "--out", h5, "--quiet"], check=True)
    usd = str(tmp_path / "r.usda")
    r = export_py(h5, usd)
    assert r.returncode == 0, r.stderr
    stage = Usd.Stage.Open(usd)
    assert stage.GetTimeCodesPerSecond() == 60.0
    assert stage.GetFramesPerSecond() == 60.0
    prim = stage.GetPrimAtPath("/Run")
    assert prim.GetCustomDataByKey("modesplit:scene_name") == "fig10"
    assert isinstance(prim.GetCustomDataByKey("modesplit:source"), str)
    # the file itself, as a text layer, holds no bytes repr
    assert "b'" not in open(usd).read()


def test_every_prim_has_an_extent_at_every_frame(run, tmp_path):
    usd = str(tmp_path / "e.usdc")
    r = export_py(run, usd)
    assert r.returncode == 0, r.stderr
    stage = Usd.Stage.Open(usd)
    frames = [float(k) for k in range(int(stage.GetEndTimeCode()) + 1)]
    seen = 0
    for prim in stage.Traverse():
        seen += 1
        if prim.IsA(UsdGeom.Boundable):
            ext = UsdGeom.Boundable(prim).GetExtentAttr()
            assert ext.GetTimeSamples() == frames, prim.GetPath()
            lo, hi = np.asarray(ext.Get(frames[-1]))
            pts = np.asarray(UsdGeom.PointBased(prim).GetPointsAttr().Get(frames[-1]))
            # a mesh's box is its points'; points grow it by half their width
            pad = 0.0
            if prim.IsA(UsdGeom.Points):
                pad = 0.5 * float(UsdGeom.Points(prim).GetWidthsAttr().Get()[0])
            assert np.allclose(pts.min(0) - pad, lo, atol=1e-6), prim.GetPath()
            assert np.allclose(pts.max(0) + pad, hi, atol=1e-6), prim.GetPath()
        else:
            hint = UsdGeom.ModelAPI(prim).GetExtentsHintAttr()
            assert hint and hint.GetTimeSamples() == frames, prim.GetPath()
            lo, hi = np.asarray(hint.Get(frames[-1]))
            assert (lo <= hi).all()
    assert seen == 3  # /Run, /Run/Surface, /Run/Particles


def test_a_python_without_numpy_or_pxr_gets_the_tools_sentence(run, tmp_path):
    """`modesplit export` with a Python that lacks numpy, then one that lacks
    pxr (a module of that name that fails to import, first on the path):
    one sentence with the install line, exit status 1, no traceback."""
    for missing, word in (("numpy", "lacks numpy"), ("pxr", "lacks Pixar's USD library")):
        block = tmp_path / f"no_{missing}" / missing
        block.mkdir(parents=True)
        (block / "__init__.py").write_text(
            f"raise ModuleNotFoundError('No module named {missing}', name={missing!r})\n")
        env = dict(os.environ, PYTHONPATH=str(block.parent), MODESPLIT_PYTHON=sys.executable)
        r = subprocess.run([TOOL, "export", run, "--usd", str(tmp_path / "m.usdc")], env=env,
                           capture_output=True, text=True)
        assert r.returncode == 1, r.stderr
        assert "Traceback" not in r.stderr, r.stderr
        assert r.stderr.startswith("modesplit export: ") and word in r.stderr, r.stderr
        assert "pip install usd-core" in r.stderr and r.stderr.count("\n") == 1, r.stderr


def test_spray_and_foam_are_exported(tmp_path):
    """A run with spray: /Run/Spray holds each frame's droplets in flight
    (their count changes), the surface the foam as a vertex primvar."""
    h5 = str(tmp_path / "pour.h5")
    subprocess.run([TOOL, "run", os.path.join(ROOT, "data", "scenes", "pour.json"), "--frames",
                    "24", "--out", h5, "--quiet", "--set", "output.fields=[\"combined\"]"],
                   check=True)
    usd = str(tmp_path / "pour.usdc")
    r = export_py(h5, usd)
    assert r.returncode == 0, r.stderr
    stage = Usd.Stage.Open(usd)
    spray = UsdGeom.Points(stage.GetPrimAtPath("/Run/Spray"))
    assert spray
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Run/Surface"))
    foam = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("foam")
    counts = []
    with h5py.File(h5, "r") as f:
        for k in range(int(f.attrs["frames"])):
            n = int(f["spray_count"][k])
            p = np.asarray(spray.GetPointsAttr().Get(k)).reshape(-1, 3)
            assert p.shape == (n, 3)
            assert np.array_equal(p, f["spray"][k, :n])
            assert np.array_equal(np.asarray(foam.Get(k)), f["foam"][k].ravel())
            counts.append(n)
    assert max(counts) > 0 and len(set(counts)) > 1


def export_peak(h5, usd):
    """`modesplit export` (this Python) in a child: (exit status, its peak
    resident set in bytes, from wait4's rusage of that child alone)."""
    env = dict(os.environ, MODESPLIT_PYTHON=sys.executable)
    p = subprocess.Popen([TOOL, "export", h5, "--usd", usd], env=env,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, usage.ru_maxrss * 1024, err.decode()


def test_the_export_streams_frames_in_memory_that_does_not_grow_with_them(tmp_path):
    """40 and 240 frames of a 256 x 192 field (1.2 MB of points and normals
    a frame): a stage held whole until its save would hold 236 MB more for
    the longer run; the export saves the .usdc as it goes, so its peak
    grows by less than a quarter of that (it holds at most SAVE_BYTES of
    samples and one frame)."""
    import json
    scene = {"name": "stream", "duration": 100.0, "frame_dt": 0.02, "threads": 1,
             "domain": {"min": [0, 0, 0], "max": [1.2, 0.9, 0.4]},
             "volume": {"spacing": 0.06, "field": [16, 12],
                        "fill": [{"min": [0, 0, 0], "max": [0.6, 0.9, 0.18]}]},
             "surface": {"cells": [256, 192], "wave_speed": 0.3, "damping": 0.9},
             "output": {"fields": ["combined", "particles"], "every": 1}}
    sp = tmp_path / "s.json"
    sp.write_text(json.dumps(scene))
    peak = {}
    for frames in (40, 240):
        h5 = str(tmp_path / f"r{frames}.h5")
        subprocess.run([TOOL, "run", str(sp), "--frames", str(frames), "--out", h5, "--quiet"],
                       check=True)
        usd = str(tmp_path / f"r{frames}.usdc")
        code, peak[frames], err = export_peak(h5, usd)
        assert code == 0, err
        stage = Usd.Stage.Open(usd)
        pts = UsdGeom.Mesh(stage.GetPrimAtPath("/Run/Surface")).GetPointsAttr()
        assert len(pts.GetTimeSamples()) == frames
        with h5py.File(h5, "r") as f:
            # the last frame, saved last, bit for bit
            assert np.array_equal(np.asarray(pts.Get(frames - 1))[:, 2],
                                  f["fields/combined"][frames - 1].ravel())
        os.remove(usd)
        os.remove(h5)
    held = 200 * 256 * 192 * 24
    assert peak[240] - peak[40] < held / 4, (peak, held)
