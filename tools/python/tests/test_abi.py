"""The package's layouts and functions are the ABI listing's."""
import ctypes
import json

import modesplit
from modesplit import _lib
from conftest import ROOT


def test_package_listing_is_the_committed_listing():
    with open(ROOT / "tools" / "abi" / "abi.json") as f:
        assert json.load(f) == modesplit.ABI


def test_struct_layouts_match_the_listing():
    for name, st in modesplit.ABI["structs"].items():
        cls = _lib.STRUCTS[name]
        assert ctypes.sizeof(cls) == st["size"], name
        assert ctypes.alignment(cls) == st["align"], name
        assert [f[0] for f in cls._fields_] == [f["name"] for f in st["fields"]], name
        for f in st["fields"]:
            assert getattr(cls, f["name"]).offset == f["offset"], (name, f["name"])
            assert getattr(cls, f["name"]).size == f["size"], (name, f["name"])


def test_every_exported_function_is_bound_with_its_arity():
    L = modesplit.lib()
    for name, fn in modesplit.ABI["functions"].items():
        if fn["exported"]:
            assert len(getattr(L, name).argtypes) == len(fn["params"]), name


def test_desc_defaults_come_from_c():
    d = modesplit.lib().ms_surface_desc_default()
    assert (d.nx, d.ny, d.boundary) == (256, 256, 0)
    assert abs(d.dx - 0.01) < 1e-9


def test_library_not_found_lists_where_it_looked(tmp_path, monkeypatch):
    monkeypatch.setenv("MODESPLIT_LIB", str(tmp_path / "nowhere.so"))
    monkeypatch.setenv("PKG_CONFIG_PATH", str(tmp_path))
    monkeypatch.setenv("PKG_CONFIG_LIBDIR", str(tmp_path))
    monkeypatch.setattr(_lib, "_HERE", str(tmp_path / "a" / "b"))
    monkeypatch.setattr(_lib.ctypes.util, "find_library", lambda name: None)
    try:
        _lib.load_library()
    except _lib.LibraryNotFound as e:
        msg = str(e)
    else:
        raise AssertionError("a library loaded from nowhere")
    for place in ("MODESPLIT_LIB", "nowhere.so", "the wheel's copy", "pkg-config", "build tree",
                  "system loader"):
        assert place in msg, msg


def _listing(args):
    import subprocess
    import sys
    return subprocess.run([sys.executable, str(ROOT / "tools" / "abi" / "abi_listing.py")] + args,
                          capture_output=True, text=True)


def _copy_headers(tmp_path):
    import shutil

    import pytest
    pytest.importorskip("pycparser")
    inc = tmp_path / "include"
    shutil.copytree(ROOT / "include", inc)
    return inc


def test_check_abi_shows_a_grown_struct_as_a_diff(tmp_path):
    inc = _copy_headers(tmp_path)
    sim_h = inc / "modesplit" / "sim.h"
    last = "    int n_time;           /* wave steps in the last frame (eq. 19) */\n"
    text = sim_h.read_text()
    assert last in text
    sim_h.write_text(text.replace(last, last + "    double grown_ms;\n"))
    listing = str(ROOT / "tools" / "abi" / "abi.json")
    r = _listing(["--lib", modesplit.lib().path, "--include", str(inc), "--check", listing])
    assert r.returncode != 0
    assert '"name": "grown_ms"' in r.stderr and "make abi" in r.stderr
    r = _listing(["--lib", modesplit.lib().path, "--check", listing])
    assert r.returncode == 0, r.stderr


def test_check_abi_refuses_an_export_no_header_declares(tmp_path):
    inc = _copy_headers(tmp_path)
    core = inc / "modesplit" / "core.h"
    core.write_text(core.read_text().replace("MS_API const char *ms_version(void);", ""))
    r = _listing(["--lib", modesplit.lib().path, "--include", str(inc),
                  "--out", str(tmp_path / "a.json")])
    assert r.returncode != 0 and "ms_version" in r.stderr and "no public header" in r.stderr


def test_library_found_through_pkg_config(tmp_path, monkeypatch):
    import os
    import shutil
    if shutil.which("pkg-config") is None:
        import pytest
        pytest.skip("no pkg-config here")
    libdir = os.path.dirname(os.path.realpath(modesplit.lib().path))
    (tmp_path / "modesplit.pc").write_text(
        "libdir=%s\nName: modesplit\nDescription: test\nVersion: 0.1.0\n" % libdir)
    monkeypatch.delenv("MODESPLIT_LIB", raising=False)
    monkeypatch.setenv("PKG_CONFIG_PATH", str(tmp_path))
    monkeypatch.setattr(_lib, "_HERE", str(tmp_path / "a" / "b"))
    dll, path = _lib.load_library()
    assert path == os.path.join(libdir, "libmodesplit.so") and dll.ms_version


def _pc(tmp_path, libdir):
    (tmp_path / "modesplit.pc").write_text(
        "libdir=%s\nName: modesplit\nDescription: test\nVersion: 0.1.0\n" % libdir)


def test_the_wheels_own_copy_comes_after_MODESPLIT_LIB_before_pkg_config(tmp_path, monkeypatch):
    import os
    import shutil
    if shutil.which("pkg-config") is None:
        import pytest
        pytest.skip("no pkg-config here")
    real = os.path.realpath(modesplit.lib().path)
    pkg = tmp_path / "site" / "modesplit"
    (pkg / "_native").mkdir(parents=True)
    os.symlink(real, pkg / "_native" / "libmodesplit.so")
    installed = tmp_path / "installed"
    installed.mkdir()
    os.symlink(real, installed / "libmodesplit.so")
    _pc(tmp_path, installed)
    monkeypatch.setenv("PKG_CONFIG_PATH", str(tmp_path))
    monkeypatch.setattr(_lib, "_HERE", str(pkg))
    monkeypatch.delenv("MODESPLIT_LIB", raising=False)
    assert _lib.load_library()[1] == str(pkg / "_native" / "libmodesplit.so")
    # asked for: MODESPLIT_LIB=pkg-config takes the installed one
    monkeypatch.setenv("MODESPLIT_LIB", "pkg-config")
    assert _lib.load_library()[1] == str(installed / "libmodesplit.so")
    # and only that: without a modesplit.pc it says so, not the wheel's
    monkeypatch.setenv("PKG_CONFIG_PATH", str(tmp_path / "none"))
    monkeypatch.setenv("PKG_CONFIG_LIBDIR", str(tmp_path / "none"))
    try:
        _lib.load_library()
    except _lib.LibraryNotFound as e:
        assert "MODESPLIT_LIB=pkg-config" in str(e) and "_native" not in str(e)
    else:
        raise AssertionError("MODESPLIT_LIB=pkg-config loaded a library pkg-config does not know")
    # MODESPLIT_LIB as a path still wins over the wheel's copy
    monkeypatch.setenv("MODESPLIT_LIB", str(installed))
    assert _lib.load_library()[1] == str(installed / "libmodesplit.so")
