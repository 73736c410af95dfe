"""Open a modesplit run file the way a ParaView user does, and check it.

Run with pvpython (ParaView 5.11, Debian 12), under xvfb-run for the
screenshot:
    xvfb-run -a pvpython tests/paraview/open_run.py RUN.h5 SHOT.png

1. run.xmf with the reader ParaView picks for it (File > Open), and
   run.xdmf2 with the reader it picks for that (the legacy XDMF reader);
2. each: the time steps equal /time; at the first, a middle and the last
   step every field array (`combined`, `surface`, `volume`) has the range
   h5py reads for that frame; the particles are one point set of the
   file's count with `velocity` (3 components, the range of vx, vy, vz)
   and `id` (0 .. n-1); block names carry no frame number;
3. a screenshot of the combined field at the last step, which must not be
   blank (more than one colour, most pixels not the background);
4. the particles have one vertex cell each (cells == particles) with both
   readers, and a screenshot of them alone, drawn from the default reader's
   output, shows their colour.
Exit 0 when all holds, 1 with the reasons otherwise.

    ... open_run.py RUN.h5 SHOT.png --killed
for a run whose writer was killed: the file's frames are the committed ones
(the smallest of the root attribute `frames` and /time's length, as
ms_reader_frames and the USD export count them). The writer appends a frame
to the XDMF sidecars after it commits the frame (lib/io/writer.c, step 5)
and links a particle step one flush before it raises `frames` (step 4), so
a kill between those leaves the sidecars one frame behind, or one complete
H5Part step beyond `frames`; nothing else is allowed.
"""
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview import simple as pv

FIELDS = ("combined", "surface", "volume")
failures = []
KILLED = "--killed" in sys.argv[3:]


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def default_reader(path):
    """The reader File > Open picks: OpenDataFile asks the same reader factory."""
    reader = pv.OpenDataFile(path)
    check(reader is not None, f"ParaView has no reader for {path}")
    name = reader.GetXMLName() if reader is not None else "none"
    print(f"{os.path.basename(path)}: ParaView's default reader is {name}")
    return name, reader


def leaves(data, out, names):
    """Every leaf dataset of a composite, with the names of its blocks."""
    if data is None:
        return
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkMultiPieceDataSet"):
        for i in range(data.GetNumberOfBlocks() if data.IsA("vtkMultiBlockDataSet")
                       else data.GetNumberOfPieces()):
            if data.IsA("vtkMultiBlockDataSet"):
                md = data.GetMetaData(i) if data.HasMetaData(i) else None
                if md is not None and md.Has(data.NAME()):
                    names.append(md.Get(data.NAME()))
                leaves(data.GetBlock(i), out, names)
            else:
                leaves(data.GetPiece(i), out, names)
    else:
        out.append(data)


def arrays_of(reader, t):
    reader.UpdatePipeline(t)
    out, names = [], []
    leaves(servermanager.Fetch(reader), out, names)
    got = {}
    for ds in out:
        pd = ds.GetPointData()
        for i in range(pd.GetNumberOfArrays()):
            a = pd.GetArray(i)
            got.setdefault(pd.GetArrayName(i), []).append((ds, a))
    return got, names, out


def committed(h5):
    """The frames a reader may use: `frames` and /time's length, the smaller."""
    return min(int(h5.attrs["frames"]), len(h5["time"]))


def check_reader(label, reader, h5):
    times = np.asarray(h5["time"][:committed(h5)])
    steps = np.asarray(reader.TimestepValues if reader.TimestepValues else [], dtype=float)
    if len(times) == 1 and steps.size == 0:
        steps = times  # one frame: ParaView reports no time steps
    if KILLED and len(steps) == len(times) - 1 and len(times) > 1:
        print(f"{label}: the sidecar lists {len(steps)} of {len(times)} committed frames "
              f"(killed between the commit and the sidecar's append)")
        times = times[:len(steps)]
    check(len(steps) == len(times), f"{label}: {len(steps)} time steps, file has {len(times)}")
    if len(steps) == len(times):
        check(np.allclose(steps, times, rtol=0, atol=1e-9), f"{label}: time steps differ")
    present = [f for f in FIELDS if f"fields/{f}" in h5]
    frames = sorted({0, len(times) // 2, len(times) - 1}) if len(times) else []
    for k in frames:
        got, names, _ = arrays_of(reader, float(times[k]))
        for f in present:
            check(f in got, f"{label} frame {k}: no array {f} (arrays: {sorted(got)})")
            if f in got:
                ds, a = got[f][0]
                frame = h5[f"fields/{f}"][k]
                lo, hi = a.GetRange(0)
                check(a.GetNumberOfTuples() == frame.size,
                      f"{label} frame {k}: {f} has {a.GetNumberOfTuples()} values, not {frame.size}")
                check(np.isclose(lo, frame.min(), rtol=0, atol=0) and
                      np.isclose(hi, frame.max(), rtol=0, atol=0),
                      f"{label} frame {k}: {f} range [{lo}, {hi}], h5py [{frame.min()}, {frame.max()}]")
        step = f"Step#{k}"
        if step in h5:
            n = h5[step]["x"].shape[0]
            check("velocity" in got and "id" in got, f"{label} frame {k}: particles lack velocity/id")
            if "velocity" in got and "id" in got:
                ds, v = got["velocity"][0]
                _, ids = got["id"][0]
                check(ds.GetNumberOfPoints() == n,
                      f"{label} frame {k}: {ds.GetNumberOfPoints()} particles, file {n}")
                # one vertex cell per particle: a point set without cells is
                # read but not drawn
                check(ds.GetNumberOfCells() == n,
                      f"{label} frame {k}: {ds.GetNumberOfCells()} particle cells, "
                      f"file {n} particles")
                check(n == 0 or all(ds.GetCellType(i) in (1, 2) for i in (0, n // 2, n - 1)),
                      f"{label} frame {k}: particle cells are not vertices")
                check(v.GetNumberOfComponents() == 3, f"{label}: velocity is not a 3-vector")
                for c, comp in enumerate(("vx", "vy", "vz")):
                    lo, hi = v.GetRange(c)
                    ref = h5[step][comp][:]
                    check(lo == ref.min() and hi == ref.max(),
                          f"{label} frame {k}: velocity[{c}] range [{lo}, {hi}] != {comp}")
                check(ids.GetRange(0) == (0.0, float(n - 1)), f"{label} frame {k}: id range")
                idv = np.array([ids.GetTuple1(i) for i in range(ids.GetNumberOfTuples())])
                check(np.array_equal(idv, np.arange(n)), f"{label} frame {k}: ids are not 0..n-1")
                pts = np.array([ds.GetPoint(i) for i in range(min(n, 50))])
                ref = np.stack([h5[step][a][:50] for a in "xyz"], 1)
                check(np.array_equal(pts.astype(np.float32), ref),
                      f"{label} frame {k}: particle positions differ from x, y, z")
        for nm in names:
            check(f"[{k}]" not in nm and str(k) not in nm.split(), f"{label}: block name {nm!r} carries the frame")


def check_h5part(run, h5):
    """ParaView's H5Part reader still reads the particles (with the ids)."""
    if "Step#0" not in h5:
        return
    r = pv.H5PartReader(FileName=run)
    r.UpdatePipelineInformation()
    steps = list(r.TimestepValues) if r.TimestepValues else []
    n = committed(h5)
    # killed after the step's link was flushed and before `frames` was
    # raised: one more step, complete (its data was flushed before its link)
    extra = KILLED and len(steps) == n + 1 and f"Step#{n}" in h5
    check(len(steps) == n or (n == 1 and not steps) or extra,
          f"H5Part: {len(steps)} steps, file {n}")
    r.UpdatePipeline(steps[-1] if steps else 0.0)
    d = servermanager.Fetch(r)
    pd = d.GetPointData()
    names = {pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())}
    last = h5[f"Step#{len(steps) - 1 if steps else n - 1}"]
    check(d.GetNumberOfPoints() == last["x"].shape[0], "H5Part: particle count")
    check({"id", "vx", "vy", "vz"} <= names, f"H5Part: arrays {sorted(names)}")


def screenshot(reader, t, png):
    view = pv.CreateRenderView()
    view.ViewSize = [640, 480]
    view.ViewTime = t
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    # The wave grid and the SPH grid lie in the same plane: keep the grid
    # that has `combined` (a threshold over all values drops the others)
    # and lift it by its heights, as a user would look at it.
    only = pv.Threshold(Input=reader, Scalars=["POINTS", "combined"],
                        LowerThreshold=-1e30, UpperThreshold=1e30)
    lifted = pv.WarpByScalar(Input=only, Scalars=["POINTS", "combined"], ScaleFactor=1.0)
    pv.UpdatePipeline(time=t, proxy=lifted)
    disp = pv.Show(lifted, view)
    pv.ColorBy(disp, ("POINTS", "combined"))
    lut = pv.GetColorTransferFunction("combined")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    disp.RescaleTransferFunctionToDataRange(False, True)
    view.CameraPosition = [0.5, -1.2, 1.4]
    view.CameraFocalPoint = [0.5, 0.5, 0.2]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    pv.Render(view)
    pv.SaveScreenshot(png, view, ImageResolution=[640, 480])
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3]
    colours = len(np.unique(img, axis=0))
    background = np.mean(np.all(img == 255, axis=1))
    # coloured by the field: saturated pixels (grey/white have max - min ~ 0)
    spread = img.max(axis=1).astype(int) - img.min(axis=1).astype(int)
    coloured = np.mean(spread > 40)
    print(f"screenshot {png}: {colours} colours, {background:.0%} background, "
          f"{coloured:.0%} coloured")
    check(colours > 64 and background < 0.9 and coloured > 0.1,
          f"screenshot {png} is blank or not coloured by the field ({colours} colours, "
          f"{coloured:.0%} coloured)")


def particle_screenshot(reader, t, png):
    """The particles as the default reader gives them, drawn as a user
    draws them (Show, points): pure red on white, nothing else in the view.
    The Threshold on `id` keeps the cells of the particle grid only (a grid
    without cells keeps nothing, so an undrawable point set fails here)."""
    view = pv.CreateRenderView()
    view.ViewSize = [480, 360]
    view.ViewTime = t
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    only = pv.Threshold(Input=reader, Scalars=["POINTS", "id"],
                        LowerThreshold=-1, UpperThreshold=1e12)
    pv.UpdatePipeline(time=t, proxy=only)
    disp = pv.Show(only, view)
    pv.ColorBy(disp, None)
    disp.AmbientColor = [1, 0, 0]
    disp.DiffuseColor = [1, 0, 0]
    disp.Representation = "Points"
    disp.PointSize = 3
    disp.Ambient = 1.0
    disp.Diffuse = 0.0
    view.CameraPosition = [0.5, -1.2, 1.4]
    view.CameraFocalPoint = [0.5, 0.5, 0.2]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    pv.Render(view)
    pv.SaveScreenshot(png, view, ImageResolution=[480, 360])
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    red = np.mean((img[:, 0] > 150) & (img[:, 1] < 90) & (img[:, 2] < 90))
    print(f"particle screenshot {png}: {red:.1%} particle-red pixels")
    check(red > 0.002, f"particle screenshot {png}: the particles are not visible "
          f"({red:.2%} red pixels)")


def main():
    run, png = sys.argv[1], sys.argv[2]
    base = run[:-3] if run.endswith(".h5") else run
    with h5py.File(run, "r") as h5:
        check(int(h5.attrs["format_version"]) >= 2, "format_version < 2")
        name, r3 = default_reader(base + ".xmf")
        check(name.startswith("Xdmf3Reader"), f"default reader of .xmf is {name}")
        check_reader("run.xmf (" + name + ")", r3, h5)
        name2, r2 = default_reader(base + ".xdmf2")
        check(name2 == "XdmfReader" or "XDMF" in name2.upper(), f".xdmf2 opens with {name2}")
        check_reader("run.xdmf2 (" + name2 + ")", r2, h5)
        check_h5part(run, h5)
        times = h5["time"][:committed(h5)]
        if len(times) and "fields/combined" in h5:
            screenshot(r3, float(times[-1]), png)
        if len(times) and f"Step#{len(times) - 1}" in h5:
            particle_screenshot(r3, float(times[-1]),
                                png[:-4] + "_particles.png")
    if failures:
        print(f"{len(failures)} failures")
        sys.exit(1)
    print("paraview: all checks hold")


main()
