"""The examples and the README's Python snippet run (Agg backend)."""
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT

EXAMPLES = ROOT / "tools" / "python" / "examples"


def run(args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable] + args, cwd=cwd, env=env, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def assert_png(path):
    with open(path, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert os.path.getsize(path) > 10_000


@pytest.mark.no_asan
def test_pool_example(tmp_path):
    out = run([str(EXAMPLES / "pool.py"), "--out", str(tmp_path / "pool.png")], tmp_path)
    assert "120 frames, 2000 particles" in out
    assert_png(tmp_path / "pool.png")


@pytest.mark.no_asan
def test_sweep_example(tmp_path):
    sys.path.insert(0, str(EXAMPLES))
    try:
        import sweep
    finally:
        sys.path.remove(str(EXAMPLES))
    out = run([str(EXAMPLES / "sweep.py"), "--out", str(tmp_path / "sweep.png")], tmp_path)
    assert "9 cases on 2 processes" in out
    assert_png(tmp_path / "sweep.png")
    # the physics the sweep shows: arrival ~ 1/c, energy kept without damping
    a = {c: sweep.run_case(c, 1.0) for c in (0.25, 1.0)}
    assert abs(a[0.25]["arrival_s"] / a[1.0]["arrival_s"] - 4) < 0.2
    assert abs(a[1.0]["energy_left"] - 1) < 1e-3
    for c in (0.25, 1.0):
        assert abs(sweep.run_case(c, 0.7)["energy_left"] / 0.7 ** 2 - 1) < 0.02


@pytest.mark.no_asan
def test_readme_python_snippet(tmp_path):
    text = (ROOT / "README.md").read_text()
    section = text[text.index("\n## Python"):]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    assert len(code.strip().splitlines()) <= 20
    script = tmp_path / "snippet.py"
    script.write_text(code)
    out = run([str(script)], ROOT)
    assert np.isfinite(float(out.split()[-1]))
