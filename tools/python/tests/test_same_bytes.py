"""The same scene stepped from Python and by the C tool gives the same bytes
of the combined field, for 60 frames of fig3 and fig10, 1 and 2 threads."""
import subprocess

import numpy as np
import pytest

import modesplit as ms
from conftest import SCENES

FRAMES = 60


@pytest.mark.parametrize("scene", ["fig3", "fig10"])
@pytest.mark.parametrize("threads", [1, 2])
def test_python_steps_give_the_c_tools_bytes(scene, threads, tool, tmp_path):
    h5py = pytest.importorskip("h5py")
    out = tmp_path / ("%s_%d.h5" % (scene, threads))
    subprocess.run([str(tool), "run", str(SCENES / (scene + ".json")), "--frames", str(FRAMES),
                    "--threads", str(threads), "--out", str(out), "--quiet"], check=True)
    with h5py.File(out, "r") as f:
        ref = f["fields/combined"][...]
    assert ref.shape[0] == FRAMES and ref.dtype == np.float32
    with ms.Sim(ms.Scene.load(SCENES / (scene + ".json")), threads=threads) as sim:
        for i in range(FRAMES):
            sim.step()
            assert sim.height.tobytes() == ref[i].tobytes(), "frame %d differs" % i
    assert np.abs(ref[-1]).max() > 0
