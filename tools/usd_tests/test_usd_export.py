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
        assert stage.GetTimeCodesPerSecond() == pytest.approx(fps, rel=1e-12)
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
