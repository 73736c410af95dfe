"""Renderer: OSMesa off-screen images of the combined field (paper 3.6)."""
import ctypes
import os

import numpy as np

from ._base import Handle, L, filled, new_struct, set_fields, view
from .errors import check


class Renderer(Handle):
    """Renderer(scene) draws as the scene's `render` section says;
    Renderer(width=320, height=240, ...) from ms_renderer_desc fields.
    Raises modesplit.Unsupported in a build without OSMesa.

        r.draw(sim); r.pixels        # (h, w, 4) uint8 view, top row first
        r.write_png("frame.png")

    `pixels` is a read-only view valid until the next draw."""

    _kind = "Renderer"

    def __init__(self, scene=None, **desc):
        p = ctypes.c_void_p()
        if scene is not None and not desc:
            # refuses a scene without a `render` section (it asks for no image)
            check(L().ms_renderer_create(scene._ptr, ctypes.byref(p)))
        else:
            if scene is not None:
                d = new_struct("ms_renderer_desc")
                check(L().ms_renderer_desc_from_scene(scene._ptr, ctypes.byref(d)))
            else:
                d = L().ms_renderer_desc_default()
            set_fields("ms_renderer_desc", d, desc, "render")
            check(L().ms_renderer_create_desc(ctypes.byref(d), ctypes.byref(p)))
        super().__init__(p.value, L().ms_renderer_destroy)
        if scene is not None:
            self._depend_on(scene)   # the desc's strings point into it

    def draw(self, sim):
        check(L().ms_renderer_draw(self._ptr, sim._ptr))

    @property
    def pixels(self):
        w, h = ctypes.c_int(), ctypes.c_int()
        p = L().ms_renderer_pixels(self._ptr, ctypes.byref(w), ctypes.byref(h))
        return view(p, (h.value, w.value, 4), np.uint8, self)

    @property
    def caustics(self):
        """The last draw's caustics light map, (n, n) over the pool, 1 =
        unfocused light; (0, 0) when it was not traced. A view."""
        n = ctypes.c_int()
        p = L().ms_renderer_caustics(self._ptr, ctypes.byref(n))
        return view(p, (n.value, n.value) if p else (0, 0), np.float32, self)

    def set_spray(self, xyz, radius):
        """Droplets drawn with the next draws: xyz (n, 3) m, radius m;
        an empty xyz removes them. draw(sim) sets a sim's own."""
        a = np.ascontiguousarray(xyz, dtype=np.float32).reshape(-1, 3)
        check(L().ms_renderer_set_spray(self._ptr, a.ctypes.data if len(a) else None, len(a),
                                        float(radius)))

    def set_foam(self, foam, grid=None):
        """Foam cover (ny, nx) in [0, 1] over grid (a dict as Sim.foam_grid
        gives), laid white over the water by the water shader; None
        removes it. draw(sim) sets a sim's own."""
        if foam is None:
            check(L().ms_renderer_set_foam(self._ptr, None, None))
            return
        a = np.ascontiguousarray(foam, dtype=np.float32)
        g = new_struct("ms_grid")
        set_fields("ms_grid", g, dict(grid or {}, nx=a.shape[1], ny=a.shape[0]), "render")
        check(L().ms_renderer_set_foam(self._ptr, a.ctypes.data, ctypes.byref(g)))

    def write_png(self, path):
        check(L().ms_renderer_write_png(self._ptr, os.fsencode(path)))

    def stats(self):
        return filled("ms_render_stats", L().ms_renderer_stats, self._ptr)
