"""Surface: the 2D wave equation (paper eq. 2) on an ny x nx grid."""
import ctypes

import numpy as np

from ._base import (Handle, L, as_input, cint, filled, interruptible, new_struct, serialised,
                    set_fields, to_dict, view)
from .errors import check


@serialised
class Surface(Handle):
    """A wave-equation height field.

        s = Surface(nx=128, ny=128, dx=0.01, wave_speed=0.5, damping=0.99,
                    boundary="reflect")
        s.add_drop(0.64, 0.64, 0.05, 0.01)
        s.step(1 / 60)
        s.height            # (ny, nx) float32 view of the C field

    Any other field of ms_surface_desc (seed, max_substeps, ...) is a
    keyword too; the desc starts from ms_surface_desc_default().
    `height` is a read-only view of the C memory, valid until the next
    mutating call (step, add_drop, set_*); read it again after those."""

    _kind = "Surface"

    def __init__(self, nx=None, ny=None, dx=None, wave_speed=None, damping=None,
                 boundary=None, **desc):
        given = dict(nx=nx, ny=ny, dx=dx, wave_speed=wave_speed, damping=damping,
                     boundary=boundary)
        desc.update({k: v for k, v in given.items() if v is not None})
        d = surface_desc(desc)
        p = ctypes.c_void_p()
        check(L().ms_surface_create(ctypes.byref(d), ctypes.byref(p)))
        super().__init__(p.value, L().ms_surface_destroy)

    @property
    def shape(self):
        nx, ny = cint(), cint()
        L().ms_surface_height(self._ptr, ctypes.byref(nx), ctypes.byref(ny))
        return (ny.value, nx.value)

    @property
    def height(self):
        nx, ny = cint(), cint()
        p = L().ms_surface_height(self._ptr, ctypes.byref(nx), ctypes.byref(ny))
        return view(p, (ny.value, nx.value), np.float32, self)

    def cancel(self):
        """Ask a step running on another thread to stop before its next
        block of sub-steps (the field valid at the time reached): that
        step raises modesplit.Canceled. Safe from any thread; asked between
        steps it stops the next one at once (as in C)."""
        self._cancel(L().ms_surface_cancel)

    def step(self, dt):
        """Advance dt seconds. Ctrl-C stops a long step at its next block
        of sub-steps (KeyboardInterrupt; the field valid at the time
        reached, the surface usable)."""
        ptr = self._ptr
        interruptible(L().ms_surface_step, (ptr, dt), lambda: L().ms_surface_cancel(ptr))

    def add_drop(self, x, y, radius, amplitude):
        check(L().ms_surface_add_drop(self._ptr, x, y, radius, amplitude))

    def _map(self, fn, x, dtype, what):
        ptr = self._ptr
        if x is None:
            check(fn(ptr, None))
            return
        a = as_input(x, self.shape, dtype, what)
        check(fn(ptr, a.ctypes.data))

    def excite(self, dh, gain=1.0):
        """Add gain*dh ((ny, nx) float32, m) to the current field only: an
        impulse changing the surface velocity by gain*dh/dt (the coupler's
        excitation from the SPH height field, paper 3.5)."""
        ptr = self._ptr
        a = as_input(dh, self.shape, np.float32, "surface: excite")
        check(L().ms_surface_excite(ptr, a.ctypes.data, gain))

    def set_height(self, h):
        """Replace the field (shape (ny, nx), float32) and start it at rest."""
        self._map(L().ms_surface_set_height, h, np.float32, "surface: set_height")

    def set_speed_map(self, c):
        """Per-cell wave speed (m/s, (ny, nx) float32); None = uniform."""
        self._map(L().ms_surface_set_speed_map, c, np.float32, "surface: set_speed_map")

    def set_damping_map(self, d):
        """Per-cell damping factor ((ny, nx) float32); None = uniform."""
        self._map(L().ms_surface_set_damping_map, d, np.float32, "surface: set_damping_map")

    def set_current(self, ux, uy=None):
        """A horizontal current under the waves (m/s, (ny, nx) float32 each,
        or scalars for a uniform one): they are carried along it (a packet
        travels at c + U) and damped where it shears (desc
        turbulence_damping). ux None: no current."""
        ptr = self._ptr
        if ux is None:
            check(L().ms_surface_set_current(ptr, None, None))
            return
        comps = []
        for x, what in ((ux, "surface: set_current ux"), (uy, "surface: set_current uy")):
            if x is None or np.ndim(x) == 0:
                x = np.full(self.shape, 0.0 if x is None else float(x), np.float32)
            comps.append(as_input(x, self.shape, np.float32, what))
        check(L().ms_surface_set_current(ptr, comps[0].ctypes.data, comps[1].ctypes.data))

    def set_obstacle_mask(self, mask):
        """1 = solid cell ((ny, nx) uint8); None = no obstacles."""
        self._map(L().ms_surface_set_obstacle_mask, mask, np.uint8,
                  "surface: set_obstacle_mask")

    def set_rain(self, rate=0.0, radius=0.01, amplitude=-0.002):
        """Drops per m^2 per s (0 = off), radius and amplitude in m."""
        r = set_fields("ms_rain", new_struct("ms_rain"),
                       dict(rate=rate, radius=radius, amplitude=amplitude), "surface")
        check(L().ms_surface_set_rain(self._ptr, ctypes.byref(r)))

    def add_disturber(self, x, y, radius, depth, vx=0.0, vy=0.0):
        """A moving disturber (the paper's boat, Fig. 10b): returns its id."""
        d = set_fields("ms_disturber_desc", new_struct("ms_disturber_desc"),
                       dict(x=x, y=y, vx=vx, vy=vy, radius=radius, depth=depth), "surface")
        i = ctypes.c_int()
        check(L().ms_surface_add_disturber(self._ptr, ctypes.byref(d), ctypes.byref(i)))
        return i.value

    def move_disturber(self, id, x, y, vx=0.0, vy=0.0):
        check(L().ms_surface_move_disturber(self._ptr, id, x, y, vx, vy))

    def set_disturber_path(self, id, points, speed, loop=False):
        """points: (k, 2) float32 (x, y) in m, travelled at speed m/s."""
        ptr = self._ptr
        n = len(points) if hasattr(points, "__len__") else -1
        xy = as_input(points, (n, 2), np.float32, "surface: disturber path")
        check(L().ms_surface_set_disturber_path(ptr, id, n, xy.ctypes.data, speed, int(loop)))

    def disturber_position(self, id):
        x, y = ctypes.c_float(), ctypes.c_float()
        check(L().ms_surface_disturber_position(self._ptr, id, ctypes.byref(x), ctypes.byref(y)))
        return x.value, y.value

    def remove_disturber(self, id):
        check(L().ms_surface_remove_disturber(self._ptr, id))

    @property
    def energy(self):
        """Wave energy, m^4/s^2 (conserved without damping)."""
        return L().ms_surface_energy(self._ptr)

    def info(self):
        return filled("ms_surface_info", L().ms_surface_get_info, self._ptr)

    def desc(self):
        return to_dict(L().ms_surface_get_desc(self._ptr))


def surface_desc(values):
    return set_fields("ms_surface_desc", L().ms_surface_desc_default(), values, "surface")
