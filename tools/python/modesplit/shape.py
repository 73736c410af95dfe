"""Shape: a collision object from a shape plugin (sphere, box, glass, ...)."""
import ctypes
import json

from ._base import Handle, L, vec
from .errors import check


class Shape(Handle):
    """Shape("sphere", {"radius": 0.1}); params as a dict or a JSON text."""

    _kind = "Shape"

    def __init__(self, kind, params=None):
        if params is not None and not isinstance(params, str):
            params = json.dumps(params)
        p = ctypes.c_void_p()
        check(L().ms_shape_create(kind.encode(), params.encode() if params else None,
                                  ctypes.byref(p)))
        super().__init__(p.value, L().ms_shape_destroy)

    @property
    def kind(self):
        return L().ms_shape_kind(self._ptr).decode()

    def set_pose(self, pos, vel=(0, 0, 0)):
        check(L().ms_shape_set_pose(self._ptr, vec(pos, 3, "shape: pos"),
                                    vec(vel, 3, "shape: vel")))

    def distance(self, p):
        """(signed distance in m, outward unit normal) at world point p."""
        n = (ctypes.c_float * 3)()
        d = L().ms_shape_distance(self._ptr, vec(p, 3, "shape: p"), n)
        return d, tuple(n)

    def bounds(self):
        lo, hi = (ctypes.c_float * 3)(), (ctypes.c_float * 3)()
        L().ms_shape_bounds(self._ptr, lo, hi)
        return tuple(lo), tuple(hi)
