"""The package's layouts and functions are the ABI listing's (issue 13)."""
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
    for place in ("MODESPLIT_LIB", "nowhere.so", "pkg-config", "build tree", "system loader"):
        assert place in msg, msg
