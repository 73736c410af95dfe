"""Writer and Reader: HDF5 run files (DESIGN 5)."""
import ctypes
import os

import numpy as np

from ._base import Handle, L, new_struct, to_dict
from .errors import check
from .sim import FIELDS, field_bits


class Writer(Handle):
    """Writer(path, sim, fields=("combined", "particles")): appends a frame
    per `frame()`; `fields=0` writes what the sim's scene asks for."""

    _kind = "Writer"

    def __init__(self, path, sim, fields=0):
        p = ctypes.c_void_p()
        check(L().ms_writer_open(os.fsencode(path), sim._ptr, field_bits(fields),
                                 ctypes.byref(p)))
        # ms_writer_close both closes and frees: the finalizer ignores its status
        super().__init__(p.value, L().ms_writer_close)
        self.sim = sim

    def frame(self, sim=None):
        check(L().ms_writer_frame(self._ptr, (sim or self.sim)._ptr))

    @property
    def frames(self):
        return L().ms_writer_frames(self._ptr)

    def close(self):
        """Close the file and its XDMF sidecar; raises the first error met."""
        if self._h is None:
            return
        ptr = self._h
        self._finalizer.detach()
        self._h = None
        check(L().ms_writer_close(ptr))


class Reader(Handle):
    """A run file's frames as arrays.

        with Reader("run.h5") as r:
            r.frames, r.fields            # 60, ["combined", "particles"]
            h = r.field("combined", 10)   # (ny, nx) float32 (a copy)
            all = r.read("combined")      # (frames, ny, nx)
            pos, vel = r.particles(10)    # (n, 3) each"""

    _kind = "Reader"

    def __init__(self, path):
        p = ctypes.c_void_p()
        check(L().ms_reader_open(os.fsencode(path), ctypes.byref(p)))
        super().__init__(p.value, L().ms_reader_close)

    @property
    def frames(self):
        return L().ms_reader_frames(self._ptr)

    @property
    def fields(self):
        bits = L().ms_reader_fields(self._ptr)
        return [name for name, b in FIELDS.items() if bits & b]

    scene = property(lambda self: L().ms_reader_scene(self._ptr).decode())
    frame_dt = property(lambda self: L().ms_reader_frame_dt(self._ptr))
    library_version = property(lambda self: L().ms_reader_library_version(self._ptr).decode())

    def time(self, frame):
        t = ctypes.c_double()
        check(L().ms_reader_time(self._ptr, frame, ctypes.byref(t)))
        return t.value

    def grid(self, field="combined"):
        g = new_struct("ms_grid")
        check(L().ms_reader_field_grid(self._ptr, field_bits(field), ctypes.byref(g)))
        return to_dict(g)

    def field(self, name, frame):
        g = self.grid(name)
        out = np.empty((g["ny"], g["nx"]), np.float32)
        check(L().ms_reader_read_field(self._ptr, field_bits(name), frame, out.ctypes.data,
                                       out.size))
        return out

    def read(self, name):
        """Every frame of a field, (frames, ny, nx)."""
        return np.stack([self.field(name, i) for i in range(self.frames)]) if self.frames \
            else np.empty((0, 0, 0), np.float32)

    @property
    def spray_budget(self):
        """Droplets a frame may hold (0: the file has no spray)."""
        return L().ms_reader_spray_budget(self._ptr)

    def spray(self, frame):
        """Frame's spray droplets, (n, 3) m."""
        out = np.empty((max(self.spray_budget, 1), 3), np.float32)
        n = ctypes.c_int()
        check(L().ms_reader_read_spray(self._ptr, frame, out.ctypes.data, len(out),
                                       ctypes.byref(n)))
        return out[:n.value].copy()

    def foam_grid(self):
        g = new_struct("ms_grid")
        check(L().ms_reader_foam_grid(self._ptr, ctypes.byref(g)))
        return to_dict(g)

    def foam(self, frame):
        """Frame's foam cover, (ny, nx) in [0, 1]."""
        g = self.foam_grid()
        out = np.empty((g["ny"], g["nx"]), np.float32)
        check(L().ms_reader_read_foam(self._ptr, frame, out.ctypes.data, out.size))
        return out

    def particles(self, frame):
        n = ctypes.c_int()
        check(L().ms_reader_particle_count(self._ptr, frame, ctypes.byref(n)))
        pos = np.empty((3, n.value), np.float32)
        vel = np.empty((3, n.value), np.float32)
        pp = (ctypes.c_void_p * 3)(*[pos[a].ctypes.data for a in range(3)])
        vp = (ctypes.c_void_p * 3)(*[vel[a].ctypes.data for a in range(3)])
        if n.value:
            check(L().ms_reader_read_particles(self._ptr, frame, n.value, pp, vp))
        return pos.T.copy(), vel.T.copy()
