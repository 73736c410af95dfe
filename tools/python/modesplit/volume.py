"""Volume: 3D SPH (paper eqs. 9-18), the low-frequency half."""
import ctypes

import numpy as np

from ._base import (Handle, L, as_input, filled, interruptible, serialised, set_fields, soa_view,
                    to_dict, vec, view)
from .errors import check


@serialised
class Volume(Handle):
    """SPH particles in a box.

        v = Volume(domain_min=(0, 0, 0), domain_max=(1, 1, 1), spacing=0.04)
        v.fill_box((0, 0, 0), (0.3, 1, 0.5))
        v.step(1 / 60)
        v.positions          # (n, 3) float32, a read-only view, order added

    Keywords are fields of ms_volume_desc (from ms_volume_desc_default()).

    `positions` / `velocities` are numpy views of C memory (no copy): the
    block ms_volume_particles gives, x | y | z at a fixed distance, viewed
    as (n, 3) with strides (4, 4 cap), in the order the particles were
    added. The first access makes the volume keep that block (one copy of
    the n particles at the end of each step, 24 bytes a particle). A view
    stays valid and CURRENT across step() and the other calls: read after a
    step it holds the new state. Its shape cannot follow a count change, so
    add_particles, fill_box and remove_box raise modesplit.ViewsAlive while
    a view of the particles (of this volume, or of the sim that owns it) is
    alive: del it or keep a .copy(). `particle_views()` gives the solver's
    own arrays (x, y, z), (vx, vy, vz) in its internal order, which changes
    at every step (valid until the next mutating call)."""

    _kind = "Volume"

    def __init__(self, **desc):
        d = volume_desc(desc)
        p = ctypes.c_void_p()
        check(L().ms_volume_create(ctypes.byref(d), ctypes.byref(p)))
        super().__init__(p.value, L().ms_volume_destroy)

    def fill_box(self, lo, hi):
        self._no_particle_views("volume: fill_box")
        check(L().ms_volume_fill_box(self._ptr, vec(lo, 3, "volume: lo"),
                                     vec(hi, 3, "volume: hi")))

    def settle(self, seconds):
        """Bring the fill to a packing at rest before the first step
        (ms_volume_settle: a seeded jitter, then seconds of damped
        sub-steps; the clock does not move)."""
        check(L().ms_volume_settle(self._ptr, seconds))

    def add_particles(self, pos, vel=None):
        """pos, vel: (n, 3) float32, C-contiguous (vel None = at rest)."""
        ptr = self._ptr
        self._no_particle_views("volume: add_particles")
        n = len(pos) if hasattr(pos, "__len__") else -1
        p = as_input(pos, (n, 3), np.float32, "volume: add_particles pos")
        v = None if vel is None else as_input(vel, (n, 3), np.float32,
                                              "volume: add_particles vel")
        check(L().ms_volume_add_particles(ptr, n, p.ctypes.data,
                                          None if v is None else v.ctypes.data))

    def cancel(self):
        """Ask a step running on another thread to stop at its next
        sub-step (the state valid at the time reached): that step raises
        modesplit.Canceled. Safe from any thread; asked between
        steps it stops the next one at once (as in C)."""
        self._cancel(L().ms_volume_cancel)

    def step(self, dt):
        """Advance dt seconds. Ctrl-C stops a long step at its next
        sub-step (KeyboardInterrupt; the state valid at the time reached,
        the volume usable)."""
        ptr = self._ptr
        interruptible(L().ms_volume_step, (ptr, dt), lambda: L().ms_volume_cancel(ptr))

    @property
    def count(self):
        return L().ms_volume_count(self._ptr)

    def __len__(self):
        return self.count

    def _particles(self):
        n = ctypes.c_int()
        pos, vel = (ctypes.c_void_p * 3)(), (ctypes.c_void_p * 3)()
        check(L().ms_volume_particles(self._ptr, ctypes.byref(n), pos, vel))
        return n.value, pos, vel

    @property
    def positions(self):
        """(n, 3) m, order added: a read-only view, current after each step
        (see the class doc)."""
        n, pos, _ = self._particles()
        return soa_view(n, pos, self)

    @property
    def velocities(self):
        """(n, 3) m/s, order added: a read-only view like `positions`."""
        n, _, vel = self._particles()
        return soa_view(n, vel, self)

    def particle_views(self):
        """((x, y, z), (vx, vy, vz)): read-only zero-copy views of the C
        arrays, internal order, valid until the next mutating call."""
        n = ctypes.c_int()
        pos, vel = (ctypes.c_void_p * 3)(), (ctypes.c_void_p * 3)()
        check(L().ms_volume_particle_views(self._ptr, ctypes.byref(n), pos, vel))
        # particle views: a call that changes the count (fill_box that
        # grows the arrays, add_particles, remove_box) is refused while
        # they live, as for positions/velocities
        return (tuple(view(p, (n.value,), np.float32, self, particles=True) for p in pos),
                tuple(view(p, (n.value,), np.float32, self, particles=True) for p in vel))

    def extract_height(self, nx, ny):
        """The liquid's height field (eqs. 16-18), (ny, nx), m (a new array)."""
        out = np.empty((ny, nx), np.float32) if nx > 0 and ny > 0 else np.empty(1, np.float32)
        check(L().ms_volume_extract_height(self._ptr, nx, ny, out.ctypes.data))
        return out

    @property
    def kinetic_energy(self):
        return L().ms_volume_kinetic_energy(self._ptr)

    def add_collider(self, shape):
        """The volume uses the shape until it is removed or the volume (or
        its sim) is freed; the shape's C object stays alive that long, even
        if the Shape is closed."""
        check(L().ms_volume_add_collider(self._ptr, shape._ptr))
        self._depend_on(shape)

    def remove_collider(self, shape):
        check(L().ms_volume_remove_collider(self._ptr, shape._raw))
        self._undepend(shape)

    def drag(self, centre, radius, velocity, strength):
        check(L().ms_volume_drag(self._ptr, vec(centre, 3, "volume: centre"), radius,
                                 vec(velocity, 3, "volume: velocity"), strength))

    def push(self, centre, radius, accel):
        """During the next step only: extra acceleration accel (m/s^2)
        within radius (m) of centre."""
        check(L().ms_volume_push(self._ptr, vec(centre, 3, "volume: centre"), radius,
                                 vec(accel, 3, "volume: accel")))

    def remove_box(self, lo, hi):
        """Remove the particles inside [lo, hi] (m); returns how many."""
        ptr = self._ptr
        self._no_particle_views("volume: remove_box")
        removed = ctypes.c_int()
        check(L().ms_volume_remove_box(ptr, vec(lo, 3, "volume: lo"), vec(hi, 3, "volume: hi"),
                                       ctypes.byref(removed)))
        return removed.value

    def set_viscosity(self, mu):
        check(L().ms_volume_set_viscosity(self._ptr, mu))

    def info(self):
        return filled("ms_volume_info", L().ms_volume_get_info, self._ptr)

    def desc(self):
        return to_dict(L().ms_volume_get_desc(self._ptr))


def volume_desc(values):
    return set_fields("ms_volume_desc", L().ms_volume_desc_default(), values, "volume")
