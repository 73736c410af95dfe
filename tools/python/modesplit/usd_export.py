"""Export a modesplit run file (HDF5) to USD for Blender, Houdini and Omniverse.

    python3 -m modesplit.usd_export RUN.h5 --usd OUT.usdc [--field combined]
    modesplit export RUN.h5 --usd OUT.usdc          (the C tool runs this)

Written with Pixar's own library (usd-core from PyPI, `pxr`), h5py and numpy
only; it imports nothing else from modesplit, so it works on any run file
without the C library.

The stage (metres, z up, one time code per written frame, time codes per
second = frames per second of the file = 1 / (frame_dt * output_every),
exactly n when that is n within 1e-4; each prim has its extent per frame,
/Run its children's union as the model's extentsHint; text attributes as
text):
  /Run                 Xform
  /Run/Surface         Mesh: the height field (combined, or --field) as a
                       grid of (nx x ny) points at the cell centres, z = the
                       height; points and vertex normals time-sampled, quads
                       and the UVs (primvars:st, u = x, v = y over the
                       domain, 0..1) static. A frame whose heights are not
                       finite keeps its NaNs out: they are written as 0 and
                       counted on stderr.
  /Run/Particles       Points: positions, velocities (m/s) and ids
                       time-sampled, one constant width (the mean particle
                       spacing of frame 0, or 1 cm).
Exit status: 0 written; 1 a read or write failure; 2 bad arguments or not a
modesplit run file (the message names the file and what is missing).
"""
import argparse
import os
import sys

# Run by its path (as `modesplit export` does), Python puts this file's own
# folder first on sys.path, where the package's modules (io.py, errors.py,
# ...) would shadow top-level modules of the same name: take it off.
if __name__ == "__main__" and sys.path and \
        os.path.abspath(sys.path[0]) == os.path.dirname(os.path.abspath(__file__)):
    del sys.path[0]

FIELDS = ("combined", "surface", "volume")
INSTALL = "pip install usd-core h5py numpy"


def fail(code, msg):
    print(f"modesplit export: {msg}", file=sys.stderr)
    sys.exit(code)


def _needed():
    """numpy and h5py, or the tool's sentence instead of a traceback (a
    function: a module-level `except ... as e` leaves a name that Python
    deletes, and stubtest then finds in the module's types but not at run
    time)."""
    try:
        import h5py
        import numpy
    except ImportError as missing:
        fail(1, f"this Python ({sys.executable}) lacks {missing.name or 'numpy or h5py'}, "
                f"which the export needs: {INSTALL} (or set MODESPLIT_PYTHON to a Python "
                f"that has them)")
    return h5py, numpy


h5py, np = _needed()


def text(v):
    """An HDF5 string attribute as text: h5py gives variable-length strings
    as str and fixed-length ones as bytes (the C writer's are fixed), and
    str(bytes) would store the repr "b'fig10'"."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray) and v.shape == ():
        return text(v.item())
    return str(v)


def frame_rate(frame_dt, every):
    """Time codes per second: 1 / (frame_dt * every), and exactly n when that
    is within 1e-4 (relative) of a whole number n: a scene's frame_dt is
    written in decimal (0.016667 for 1/60 s, 1.7e-5 off), so the rate a
    player expects is 60, not 59.9988. A rate no whole number is near (say
    frame_dt 0.3) is kept as it is."""
    if not frame_dt > 0:
        return 24.0
    fps = 1.0 / (frame_dt * every)
    n = round(fps)
    if n >= 1 and abs(fps - n) <= 1e-4 * n:
        return float(n)
    return fps


def grid_of(ds):
    """(nx, ny, dx, dy, x0, y0) of a /fields/<name> dataset."""
    _, ny, nx = ds.shape
    dx, dy = (float(v) for v in ds.attrs["dx"])
    x0, y0 = (float(v) for v in ds.attrs["origin"])
    return nx, ny, dx, dy, x0, y0


def frames_in(f):
    """Complete frames: the smallest of `frames` and every dataset's length
    (what ms_reader_frames reports)."""
    n = int(f.attrs.get("frames", len(f["time"])))
    n = min(n, len(f["time"]))
    for name in FIELDS:
        if f"fields/{name}" in f:
            n = min(n, f[f"fields/{name}"].shape[0])
    return n


def quad_topology(nx, ny):
    """Counter-clockwise quads (seen from +z) of an nx x ny point grid."""
    x, y = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1))
    i = (y * nx + x).ravel()
    idx = np.stack([i, i + 1, i + 1 + nx, i + nx], axis=1).ravel()
    return np.full((nx - 1) * (ny - 1), 4, dtype=np.int32), idx.astype(np.int32)


def vertex_normals(h, dx, dy):
    """Normals of z = h(x, y) from central differences (one-sided at the edges)."""
    gy, gx = np.gradient(h.astype(np.float64), dy, dx)
    n = np.stack([-gx, -gy, np.ones_like(gx)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return n.reshape(-1, 3).astype(np.float32)


# Unsaved time samples before the layer is saved (crate files only): a
# .usdc layer saved again writes only what changed and keeps what it wrote
# on disk, not in memory, so the export holds about this much plus one
# frame, whatever the number of frames. A .usda text layer is written whole
# at its one save (the C tool refuses one that would not fit in memory).
SAVE_BYTES = 64 << 20


def export(run, usd_path, field=None):
    try:
        from pxr import Gf, Sdf, Usd, UsdGeom, Vt
    except ImportError:
        fail(1, f"this Python ({sys.executable}) lacks Pixar's USD library (pxr), which the "
                f"export needs: {INSTALL} (or set MODESPLIT_PYTHON to a Python that has it)")

    try:
        f = h5py.File(run, "r")
    except OSError as e:
        fail(1, f"cannot open {run}: {e}")
    with f:
        if text(f.attrs.get("format", "")) != "modesplit":
            fail(2, f"{run} is not a modesplit run file (no root attribute format = \"modesplit\")")
        frames = frames_in(f)
        frame_dt = float(f.attrs.get("frame_dt", 0.0))
        every = int(f.attrs.get("output_every", 1))
        fps = frame_rate(frame_dt, every)
        present = [n for n in FIELDS if f"fields/{n}" in f]
        if field is None:
            field = present[0] if present else None
        elif field not in present:
            fail(2, f"{run} has no field {field} (it has: {', '.join(present) or 'none'})")

        # .usd is written as crate too (not as USD_DEFAULT_FILE_FORMAT says):
        # only crate layers can be saved as they grow
        text_layer = usd_path.endswith(".usda")
        layer = Sdf.Layer.CreateNew(usd_path, {} if text_layer else {"format": "usdc"})
        stage = Usd.Stage.Open(layer) if layer else None
        if stage is None:
            fail(1, f"cannot create {usd_path}")
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        stage.SetTimeCodesPerSecond(fps)
        stage.SetFramesPerSecond(fps)
        stage.SetStartTimeCode(0)
        stage.SetEndTimeCode(max(frames - 1, 0))
        root = UsdGeom.Xform.Define(stage, "/Run")
        stage.SetDefaultPrim(root.GetPrim())
        root.GetPrim().SetCustomDataByKey("modesplit:scene_name",
                                          text(f.attrs.get("scene_name", "")))
        root.GetPrim().SetCustomDataByKey("modesplit:source", run)

        def box(lo, hi):
            return Vt.Vec3fArray([Gf.Vec3f(*map(float, lo)), Gf.Vec3f(*map(float, hi))])

        mesh_attrs = None
        if field is not None:
            ds = f[f"fields/{field}"]
            nx, ny, dx, dy, x0, y0 = grid_of(ds)
            mesh = UsdGeom.Mesh.Define(stage, "/Run/Surface")
            mesh.GetPrim().SetCustomDataByKey("modesplit:field", field)
            counts, idx = quad_topology(nx, ny)
            mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(counts))
            mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(idx))
            del counts, idx
            mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
            mesh.CreateOrientationAttr(UsdGeom.Tokens.rightHanded)
            xs = x0 + (np.arange(nx) + 0.5) * dx
            ys = y0 + (np.arange(ny) + 0.5) * dy
            gx, gy = np.meshgrid(xs, ys)
            st = np.stack([(gx - x0) / (nx * dx), (gy - y0) / (ny * dy)], -1).reshape(-1, 2)
            pv = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(
                "st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex)
            pv.Set(Vt.Vec2fArray.FromNumpy(st.astype(np.float32)))
            del st
            mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
            mesh_attrs = (mesh.CreatePointsAttr(), mesh.CreateNormalsAttr(),
                          mesh.CreateExtentAttr())
            # the points' x and y, the same every frame (float32, as written)
            xy = np.stack([gx.ravel(), gy.ravel()], -1).astype(np.float32)
            del gx, gy
            # the foam, a vertex primvar when it lies on the mesh's grid
            foam = f.get("foam")
            if foam is not None and foam.shape[1:] != (ny, nx):
                foam = None  # on another grid: not a primvar of this mesh
            foam_pv = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(
                "foam", Sdf.ValueTypeNames.FloatArray, UsdGeom.Tokens.vertex) \
                if foam is not None else None

        step_attrs = None
        if "Step#0" in f:
            points = UsdGeom.Points.Define(stage, "/Run/Particles")
            step_attrs = (points.CreatePointsAttr(), points.CreateVelocitiesAttr(),
                          points.CreateIdsAttr(), points.CreateExtentAttr())
            spacing = 0.01
            try:
                scene = __import__("json").loads(text(f.attrs["scene"]))
                spacing = float(scene["volume"]["spacing"])
            except Exception:
                pass
            points.CreateWidthsAttr(Vt.FloatArray([spacing]))
            points.SetWidthsInterpolation(UsdGeom.Tokens.constant)

        spray_attrs = None
        if "spray" in f and "spray_count" in f:
            spray = UsdGeom.Points.Define(stage, "/Run/Spray")
            spray_attrs = (spray.CreatePointsAttr(), spray.CreateExtentAttr())
            width = 0.01
            try:
                scene = __import__("json").loads(text(f.attrs["scene"]))
                width = 0.3 * float(scene["volume"]["spacing"])
            except Exception:
                pass
            spray.CreateWidthsAttr(Vt.FloatArray([width]))
            spray.SetWidthsInterpolation(UsdGeom.Tokens.constant)
            spray_ds, spray_n = f["spray"], f["spray_count"]
            spray_frames = min(len(spray_ds), len(spray_n))

        # /Run is an Xform, which has no extent of its own: its children's
        # union per frame goes into the model's extentsHint, so every prim
        # states its bounds.
        model = UsdGeom.ModelAPI.Apply(root.GetPrim())
        # Frame by frame: each frame's samples are read, set and let go;
        # the layer is saved whenever SAVE_BYTES of them wait.
        bad = pending = 0
        for k in range(frames):
            lo = hi = None
            if mesh_attrs is not None:
                h = np.asarray(ds[k], dtype=np.float32)
                finite = np.isfinite(h)
                if not finite.all():
                    bad += 1
                    h = np.where(finite, h, 0.0).astype(np.float32)
                del finite
                p = np.empty((nx * ny, 3), np.float32)
                p[:, :2] = xy
                p[:, 2] = h.ravel()
                mesh_attrs[0].Set(Vt.Vec3fArray.FromNumpy(p), k)
                mesh_attrs[1].Set(Vt.Vec3fArray.FromNumpy(vertex_normals(h, dx, dy)), k)
                lo, hi = p.min(0), p.max(0)
                mesh_attrs[2].Set(box(lo, hi), k)
                pending += 24 * nx * ny
                del h, p
                if foam_pv is not None and k < len(foam):
                    c = np.nan_to_num(np.asarray(foam[k], dtype=np.float32), nan=0.0)
                    foam_pv.Set(Vt.FloatArray.FromNumpy(c.ravel()), k)
                    pending += 4 * nx * ny
                    del c
            step = f.get(f"Step#{k}") if step_attrs is not None else None
            if step is not None:
                p = np.stack([step[a][:] for a in "xyz"], 1).astype(np.float32)
                v = np.stack([step[a][:] for a in ("vx", "vy", "vz")], 1).astype(np.float32)
                ids = step["id"][:] if "id" in step else np.arange(len(p))
                step_attrs[0].Set(Vt.Vec3fArray.FromNumpy(p), k)
                step_attrs[1].Set(Vt.Vec3fArray.FromNumpy(v), k)
                step_attrs[2].Set(Vt.Int64Array.FromNumpy(ids.astype(np.int64)), k)
                # the points' box grown by half the width (UsdGeom.Points' rule)
                if len(p):
                    plo, phi = p.min(0) - 0.5 * spacing, p.max(0) + 0.5 * spacing
                else:
                    plo = phi = np.zeros(3, np.float32)
                step_attrs[3].Set(box(plo, phi), k)
                lo = plo if lo is None else np.minimum(lo, plo)
                hi = phi if hi is None else np.maximum(hi, phi)
                pending += 32 * len(p)
                del p, v, ids
            if spray_attrs is not None and k < spray_frames:
                n = max(0, min(int(spray_n[k]), spray_ds.shape[1]))
                p = np.asarray(spray_ds[k, :n], dtype=np.float32).reshape(-1, 3)
                spray_attrs[0].Set(Vt.Vec3fArray.FromNumpy(p), k)
                if n:
                    slo, shi = p.min(0) - 0.5 * width, p.max(0) + 0.5 * width
                    lo = slo if lo is None else np.minimum(lo, slo)
                    hi = shi if hi is None else np.maximum(hi, shi)
                else:
                    slo = shi = np.zeros(3, np.float32)
                spray_attrs[1].Set(box(slo, shi), k)
                pending += 12 * n
                del p
            if lo is not None:
                model.SetExtentsHint(box(lo, hi), k)
            if not text_layer and pending >= SAVE_BYTES:
                layer.Save()
                pending = 0
        if bad:
            print(f"modesplit export: {bad} frames of {field} had non-finite heights, "
                  "written as 0", file=sys.stderr)
        if not layer.Save():
            fail(1, f"cannot write {usd_path}")
    return frames


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="python3 -m modesplit.usd_export",
        description="Write a modesplit run file as USD: the height field as a time-sampled "
                    "mesh, the particles as time-sampled points.")
    ap.add_argument("run", help="the run file (RUN.h5)")
    ap.add_argument("--usd", required=True, help="the USD file to write (.usdc, .usda or .usd)")
    ap.add_argument("--field", choices=FIELDS,
                    help="the height field of the mesh (default: combined, else the first present)")
    a = ap.parse_args(argv)
    if not a.usd.endswith((".usd", ".usda", ".usdc")):
        fail(2, f"--usd {a.usd}: the name must end in .usdc, .usda or .usd")
    n = export(a.run, a.usd, a.field)
    print(f"modesplit export: wrote {a.usd} ({n} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
