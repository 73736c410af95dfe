"""Sim: the mode-splitting coupler (eqs. 19-20, the two-core split)."""
import ctypes

import numpy as np

from ._base import (Handle, L, filled, interruptible, new_struct, serialised, set_fields, soa_view,
                    to_dict, vec, view)
from ._lib import ABI
from .errors import InvalidArgument, check
from .surface import Surface, surface_desc
from .volume import Volume, volume_desc

FIELDS = {n[len("MS_FIELD_"):].lower(): v for e in ABI["enums"].values()
          for n, v in e.items() if n.startswith("MS_FIELD_")}


def field_bits(fields):
    """MS_FIELD_* bits from names ("combined", "particles", ...) or an int."""
    if isinstance(fields, int):
        return fields
    if isinstance(fields, str):
        fields = [fields]
    bits = 0
    for f in fields:
        if f not in FIELDS:
            raise InvalidArgument("modesplit: no field %r; fields: %s" % (f, ", ".join(FIELDS)))
        bits |= FIELDS[f]
    return bits


@serialised
class Sim(Handle):
    """A mode-splitting simulation.

        sim = Sim(Scene.load("data/scenes/fig1.json"), threads=2)
        sim = Sim.from_desc(volume=dict(spacing=0.04), surface=dict(nx=256, ny=256,
                            dx=1 / 256), field=(32, 32), threads=2)
        sim.step(1 / 60)
        sim.height           # (ny, nx) combined field, a read-only view

    Views (height, surface_height, volume_field, positions, velocities) are
    numpy arrays over the C buffers: no copy, read-only. They are valid
    until the next step() (the sim publishes each frame into the other of
    two buffers): read the property again after each step. The fields are
    one frame old (the pipeline of the paper's Fig. 8), as in C."""

    _kind = "Sim"

    def __init__(self, scene, threads=1):
        p = ctypes.c_void_p()
        check(L().ms_sim_create_from_scene(scene._ptr, threads, ctypes.byref(p)))
        Handle.__init__(self, p.value, L().ms_sim_destroy)
        self._depend_on(scene)        # sim.h: the scene must outlive the sim
        self.scene = scene
        self._frame_dt = scene.frame_dt
        self._keep = ()

    @classmethod
    def from_desc(cls, volume=None, surface=None, field=(0, 0), threads=1, **desc):
        """volume / surface: None (absent), True (defaults) or a dict of desc
        fields; field = (X_SPH, Y_SPH); other keywords are ms_sim_desc
        fields (surface_substeps, couple_surface_from_volume, ...)."""
        vd = None if volume is None else volume_desc({} if volume is True else volume)
        sd = None if surface is None else surface_desc({} if surface is True else surface)
        d = L().ms_sim_desc_default()
        nx, ny = field
        set_fields("ms_sim_desc", d, dict(desc, field_nx=nx, field_ny=ny, threads=threads),
                   "sim")
        d.volume = None if vd is None else ctypes.addressof(vd)
        d.surface = None if sd is None else ctypes.addressof(sd)
        p = ctypes.c_void_p()
        check(L().ms_sim_create(ctypes.byref(d), ctypes.byref(p)))
        self = cls.__new__(cls)
        Handle.__init__(self, p.value, L().ms_sim_destroy)
        self.scene = None
        self._frame_dt = None
        self._keep = (vd, sd)
        return self

    def cancel(self):
        """Ask a step running on another thread to stop at the next sub-step:
        that step raises modesplit.Canceled, and the sim is then failed as
        in C (restore() of a snapshot() makes it step again). Safe from
        any thread; asked between steps it stops the next one at once."""
        self._cancel(L().ms_sim_cancel)

    def step(self, frame_dt=None):
        """Advance one frame (s; default the scene's frame_dt). Ctrl-C stops
        a long step at the next sub-step with KeyboardInterrupt
        (ms_sim_cancel); as in C the sim is then failed (further steps
        raise StateError) but open: its views, stats and a writer's frames
        stay valid, and restore() of a snapshot() makes it step again."""
        ptr = self._ptr
        if frame_dt is None:
            if self._frame_dt is None:
                raise InvalidArgument("sim: step needs frame_dt for a sim made from descs")
            frame_dt = self._frame_dt
        interruptible(L().ms_sim_step, (ptr, frame_dt), lambda: L().ms_sim_cancel(ptr))

    def snapshot(self):
        """The sim's whole state between two steps as bytes (ms_sim_snapshot):
        restore() it into a sim made the same way, in this process or another
        (the way to copy a sim; the handle itself cannot be copied or pickled)."""
        ptr = self._ptr
        n = ctypes.c_size_t()
        check(L().ms_sim_snapshot_size(ptr, ctypes.byref(n)))
        buf = ctypes.create_string_buffer(n.value)
        written = ctypes.c_size_t()
        check(L().ms_sim_snapshot(ptr, buf, n.value, ctypes.byref(written)))
        return buf.raw[:written.value]

    def restore(self, blob):
        """Load a snapshot() of a sim made the same way (refused, unchanged,
        for another scene, version or a corrupt blob)."""
        if not isinstance(blob, (bytes, bytearray, memoryview)):
            raise InvalidArgument("sim: restore needs the bytes of snapshot(), not %s"
                                  % type(blob).__name__)
        data = bytes(blob)
        check(L().ms_sim_restore(self._ptr, data, len(data)))

    def _field(self, fn):
        nx, ny = ctypes.c_int(), ctypes.c_int()
        p = fn(self._ptr, ctypes.byref(nx), ctypes.byref(ny))
        return view(p, (ny.value, nx.value), np.float32, self)

    @property
    def height(self):
        """The combined field (eq. 20), (ny, nx), m."""
        return self._field(L().ms_sim_height)

    @property
    def surface_height(self):
        """The wave field of the last frame; (0, 0) without a surface."""
        return self._field(L().ms_sim_surface_height)

    @property
    def volume_field(self):
        """The SPH height field of the last frame (X_SPH x Y_SPH)."""
        return self._field(L().ms_sim_volume_height)

    def _particles(self):
        n = ctypes.c_int()
        pos, vel = (ctypes.c_void_p * 3)(), (ctypes.c_void_p * 3)()
        check(L().ms_sim_particles(self._ptr, ctypes.byref(n), pos, vel))
        return n.value, pos, vel

    @property
    def positions(self):
        """Particles of the last frame, (n, 3) m, the order they were added."""
        n, pos, _ = self._particles()
        return soa_view(n, pos, self)

    @property
    def velocities(self):
        n, _, vel = self._particles()
        return soa_view(n, vel, self)

    @property
    def floaters(self):
        """Objects carried by the flow (scene effects.floaters): (n, 3) m,
        z on the combined surface; a view valid until the next step."""
        n = ctypes.c_int()
        p = L().ms_sim_floaters(self._ptr, ctypes.byref(n))
        return view(p, (n.value, 3), np.float32, self)

    @property
    def spray(self):
        """Spray droplets in flight (scene effects.spray): (n, 3) m, thrown
        by fast water at the surface, falling back ballistically; (0, 3)
        without spray. A view valid until the next step."""
        n = ctypes.c_int()
        p = L().ms_sim_spray(self._ptr, ctypes.byref(n))
        return view(p, (n.value, 3), np.float32, self)

    @property
    def foam(self):
        """The foam cover in [0, 1], (ny, nx) on foam_grid() (the wave
        grid); (0, 0) without spray. A view valid until the next step."""
        nx, ny = ctypes.c_int(), ctypes.c_int()
        p = L().ms_sim_foam(self._ptr, ctypes.byref(nx), ctypes.byref(ny))
        return view(p, (ny.value, nx.value), np.float32, self)

    def foam_grid(self):
        """Where the foam cover lies (StateError without spray)."""
        out = new_struct("ms_grid")
        check(L().ms_sim_foam_grid(self._ptr, ctypes.byref(out)))
        return to_dict(out)

    @property
    def volume(self):
        """The sim's Volume (borrowed: valid while the sim is), or None."""
        p = L().ms_sim_volume(self._ptr)
        return Volume._borrow(p, self) if p else None

    @property
    def surface(self):
        p = L().ms_sim_surface(self._ptr)
        return Surface._borrow(p, self) if p else None

    @property
    def time(self):
        return L().ms_sim_time(self._ptr)

    @property
    def frame(self):
        return L().ms_sim_frame(self._ptr)

    def stats(self):
        """ms_stats as a dict (stage ms, sub-steps, frames, bytes, ...)."""
        return filled("ms_stats", L().ms_sim_get_stats, self._ptr)

    def info(self):
        return filled("ms_sim_info", L().ms_sim_get_info, self._ptr)

    def grid(self, field="combined"):
        out = new_struct("ms_grid")
        check(L().ms_sim_field_grid(self._ptr, field_bits(field), ctypes.byref(out)))
        return to_dict(out)

    def drag(self, pos, vel, radius, depth, strength):
        """Pull the water within radius (m) of the point depth (m) below the
        surface at pos (x, y, m) towards vel (m/s) at strength (1/s), during
        the next frame (up to 8 a frame; StateError without a volume)."""
        check(L().ms_sim_drag(self._ptr, vec(pos, 2, "sim: pos"), vec(vel, 2, "sim: vel"),
                              radius, depth, strength))

    # ---- the scene's effects, driven by hand (sim.h) ----

    def set_rain(self, on):
        """Rain on (the scene's effects.rain, or a light shower) or off,
        from the next frame on; StateError without a surface."""
        check(L().ms_sim_set_rain(self._ptr, 1 if on else 0))

    def steer_boat(self, vel):
        """Move the scene's boat at vel (vx, vy, m/s) from where it is, its
        scripted path dropped; StateError without a boat."""
        check(L().ms_sim_steer_boat(self._ptr, vec(vel, 2, "sim: boat vel")))

    @property
    def boat(self):
        """Where the boat is now (x, y, m); StateError without a boat."""
        pos = (ctypes.c_float * 2)()
        check(L().ms_sim_boat(self._ptr, pos))
        return tuple(pos)

    def move_container(self, pos, vel=(0, 0, 0)):
        """Put the scene's container at pos (m) moving at vel (m/s) from the
        next frame on, replacing its path; StateError without one."""
        check(L().ms_sim_move_container(self._ptr, vec(pos, 3, "sim: pos"),
                                        vec(vel, 3, "sim: vel")))

    def turn_container(self, orientation, omega=(0, 0, 0)):
        """Orient the container: a quaternion (w, x, y, z), omega (rad/s)."""
        check(L().ms_sim_turn_container(self._ptr, vec(orientation, 4, "sim: orientation"),
                                        vec(omega, 3, "sim: omega")))

    @property
    def container_pose(self):
        """((x, y, z) m, (w, x, y, z)) of the container now."""
        pos, q = (ctypes.c_float * 3)(), (ctypes.c_float * 4)()
        check(L().ms_sim_container_pose(self._ptr, pos, q))
        return tuple(pos), tuple(q)

    def move_obstacle(self, i, pos, vel=(0, 0, 0)):
        """Put the scene's obstacle i (scene order) at pos moving at vel."""
        check(L().ms_sim_move_obstacle(self._ptr, i, vec(pos, 3, "sim: pos"),
                                       vec(vel, 3, "sim: vel")))

    def turn_obstacle(self, i, orientation, omega=(0, 0, 0)):
        check(L().ms_sim_turn_obstacle(self._ptr, i, vec(orientation, 4, "sim: orientation"),
                                       vec(omega, 3, "sim: omega")))

    def run(self, frames, frame_dt=None, writer=None):
        """step() `frames` times (each frame written to `writer` when
        given); Ctrl-C stops it within the running step (see step)."""
        for _ in range(frames):
            self.step(frame_dt)
            if writer is not None:
                writer.frame(self)
