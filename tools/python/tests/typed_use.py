"""The package as a typed program uses it: `mypy --strict` checks this file
against the stubs (.ci/run's python stage), test_typing.py runs it."""
import numpy as np
import numpy.typing as npt

import modesplit as ms


def main(scene_path: str) -> float:
    with ms.Sim(ms.Scene.load(scene_path)) as sim:
        blob: bytes = sim.snapshot()
        sim.run(2)
        h: npt.NDArray[np.float32] = sim.height
        stats: dict[str, object] = sim.stats()
        vol = sim.volume
        n = vol.count if vol is not None else 0
        sim.restore(blob)
        sim.step()
        t: float = sim.time
    s = ms.Surface(nx=8, ny=8, dx=0.01)
    s.add_drop(0.04, 0.04, 0.02, 0.01)
    s.step(1 / 60)
    try:
        s.set_height(np.zeros((3, 3), np.float32))
    except ms.InvalidArgument as e:
        assert e.status_name == "MS_ERR_INVALID_ARGUMENT"
    assert "frames" in stats and n >= 0 and h.ndim == 2
    return t + float(s.energy)
