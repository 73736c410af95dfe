"""Handles that own (or borrow) a C object, desc helpers, views and inputs."""
import ctypes
import functools
import os
import queue
import signal
import threading
import weakref

import numpy as np

from ._lib import ABI, STRUCTS, check_int, ctype, int_range, lib
from .errors import Closed, InvalidArgument, check, last_error


def _finish(destroy, ptr, deps):
    destroy(ptr)
    for d in deps:          # objects the C one used (a scene, collider shapes)
        d._unhold()
    deps.clear()


class Handle:
    """A C handle. An owning handle is destroyed by close(), by `with`, or by
    the garbage collector (a finalizer); a borrowed one (sim.volume) lives as
    long as its owner. Any use after close raises modesplit.Closed before C
    is called.

    The C object stays alive while something still holds it: a numpy view
    of its memory, or another C object that uses it (a sim its scene, a
    volume its collider shapes). close() then only closes the Python side
    and the C object is freed when the last holder goes, so nothing ever
    reads freed memory."""

    _kind = "object"

    def __init__(self, ptr, destroy=None, owner=None):
        self._h = ptr
        self._raw = ptr   # kept after close, for releasing what C still holds
        self._owner = owner
        self._holds = 0   # live views and C objects using this one
        self._pviews = 0  # live particle views (positions, velocities)
        self._deps = []   # handles this one holds (released after destroy)
        self._finalizer = (weakref.finalize(self, _finish, destroy, ptr, self._deps)
                           if destroy is not None else None)
        self._lock = threading.RLock()  # one call at a time (serialised)
        self._cancel_lock = threading.Lock()  # cancel() against close()

    @classmethod
    def _borrow(cls, ptr, owner):
        """A wrapper of a C object that `owner` owns (sim.volume)."""
        h = cls.__new__(cls)
        Handle.__init__(h, ptr, None, owner)
        return h

    def _root(self):
        h = self
        while h._owner is not None:
            h = h._owner
        return h

    def _hold(self):
        self._holds += 1

    def _unhold(self):
        self._holds -= 1
        if self._holds == 0 and self._h is None:
            self._destroy_now()

    def _depend_on(self, other):
        """This object's C side uses `other` until it is destroyed."""
        other._hold()
        self._root()._deps.append(other)

    def _undepend(self, other):
        deps = self._root()._deps
        if other in deps:
            deps.remove(other)
            other._unhold()

    def _view_made(self, buf):
        root = self._root()
        root._hold()
        weakref.finalize(buf, root._unhold)

    def _particle_view_made(self, buf):
        root = self._root()
        root._pviews += 1
        weakref.finalize(buf, root._particle_view_gone)

    def _particle_view_gone(self):
        self._pviews -= 1

    def _no_particle_views(self, what):
        """Refuse a call that changes the particle count while views of the
        particles are alive (as a bytearray refuses to resize while a
        memoryview exports it): their shape would be stale and a grown
        count moves the memory they view."""
        n = self._root()._pviews
        if n:
            from .errors import ViewsAlive
            raise ViewsAlive("modesplit: %s would change the particle count while %d view%s of "
                             "the particles (positions, velocities, particle_views) %s alive; "
                             "a view has a "
                             "fixed shape and a grown count moves the memory it reads: del "
                             "the views (or keep .copy()s) first"
                             % (what, n, "" if n == 1 else "s", "is" if n == 1 else "are"))

    def _destroy_now(self):
        if self._finalizer is not None:
            self._finalizer()

    @property
    def _ptr(self):
        if self._h is None:
            raise Closed("modesplit: the %s is closed" % self._kind)
        if self._owner is not None and self._owner.closed:
            raise Closed("modesplit: the %s belongs to a %s that is closed"
                         % (self._kind, self._owner._kind))
        return self._h

    @property
    def closed(self):
        return self._h is None or (self._owner is not None and self._owner.closed)

    def _busy(self):
        """The handle's lock for one call, refused with StateError while
        another thread is in a call on the same handle (or on its owner or
        what it owns: they share the root's lock)."""
        lock = self._root()._lock
        if not lock.acquire(blocking=False):
            from .errors import StateError
            raise StateError("modesplit: the %s is in a call from another thread; a handle takes "
                             "one call at a time (use one handle per thread, or a lock of your "
                             "own around the calls)" % self._kind)
        return lock

    def close(self):
        """Close the object (idempotent): further use raises Closed; the C
        object is freed now, or when the last view or user of it goes. A
        close() from another thread while a call runs waits for that call."""
        root = self._root()
        with root._lock, root._cancel_lock:
            self._h = None
            if self._holds == 0:
                self._destroy_now()

    def _cancel(self, fn):
        """fn(ptr) (ms_*_cancel) from any thread, without the handle's lock
        (a step on another thread holds it): under the cancel lock, which
        close() takes too, so the pointer is never one close() freed."""
        root = self._root()
        with root._cancel_lock:
            if not self.closed:
                fn(self._h)

    def _no_copy(self, *args):
        raise TypeError("modesplit: a %s is a handle to C memory and cannot be copied or "
                        "pickled (a copy would share, then free, the same C object); copy its "
                        "state instead: Sim.snapshot() / Sim.restore(blob) between processes, "
                        "or .copy() of the arrays it returns" % type(self).__name__)

    __copy__ = __deepcopy__ = __reduce__ = __reduce_ex__ = __getstate__ = _no_copy

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return "<modesplit.%s %s>" % (type(self).__name__,
                                      "closed" if self.closed else hex(self._h))


class _Worker:
    """One thread that runs the main thread's long C calls (steps), so the
    main thread can wait for them where Python's SIGINT handler runs.
    ctypes releases the GIL around a C call, but the handler runs only on
    the main thread between bytecodes: with the step itself on the main
    thread, Ctrl-C waited for C to return (12.6 s for a 4096^2 surface
    step). One thread for the whole process: only the main thread gets
    signals, so only its calls come here."""

    def __init__(self):
        self.jobs = queue.SimpleQueue()
        threading.Thread(target=self._run, name="modesplit-step", daemon=True).start()

    def _run(self):
        while True:
            fn, args, box, done = self.jobs.get()
            try:
                box.append(fn(*args))
            except BaseException as e:  # handed to the waiting caller
                box.append(e)
            done.set()


_worker = None


def _forget_worker():
    global _worker
    _worker = None  # a forked child has the queue but not the thread


os.register_at_fork(after_in_child=_forget_worker)


def _status_call(fn, args):
    """fn(*args) and, when it failed, this thread's ms_last_error()."""
    st = fn(*args)
    return st, (last_error() if st else None)


def interruptible(fn, args, cancel):
    """check(fn(*args)) -- a C call that may run long (a step) -- such that Ctrl-C
    stops it: on the main thread with a Python SIGINT handler, the call
    runs on the worker thread while the main thread waits interruptibly;
    when the handler raises (KeyboardInterrupt), cancel() asks C to stop
    (ms_*_cancel: at its next sub-step), the wait goes on until C has
    returned -- so nothing is freed under it -- and the exception is
    raised. Elsewhere (another thread, SIGINT ignored or C's) fn runs here."""
    global _worker
    if (threading.current_thread() is not threading.main_thread()
            or not callable(signal.getsignal(signal.SIGINT))):
        check(fn(*args))
        return
    if _worker is None:
        _worker = _Worker()
    box, done = [], threading.Event()
    _worker.jobs.put((_status_call, (fn, args), box, done))
    try:
        done.wait()  # a lock wait: signal handlers run in it (POSIX)
    except BaseException:
        # C keeps a cancel that comes after its step ended for the next
        # step; asking only while it runs leaves a window of a few
        # instructions, not a whole step, for that
        if not done.is_set():
            cancel()
        while not done.is_set():
            try:
                done.wait()
            except BaseException:  # another Ctrl-C: C must return first
                cancel()
        raise
    r = box[0]
    if isinstance(r, BaseException):
        raise r
    check(*r)


def _serial(fn):
    @functools.wraps(fn)
    def call(self, *args, **kwargs):
        lock = self._busy()
        try:
            return fn(self, *args, **kwargs)
        finally:
            lock.release()
    return call


def serialised(cls):
    """Class decorator: every public method and property of cls runs under
    the handle's lock (Handle._busy). The rule, one for Surface, Volume and
    Sim: a call while another thread is in a call on the same handle raises
    StateError at once; close() waits for the running call; cancel() is
    the one call another thread makes during a step. A call that
    re-enters from the same thread (a method using a property) is fine."""
    for name, attr in list(vars(cls).items()):
        if name.startswith("_") or name in ("close", "cancel"):
            continue
        if isinstance(attr, property):
            setattr(cls, name, property(_serial(attr.fget) if attr.fget else None,
                                        _serial(attr.fset) if attr.fset else None,
                                        attr.fdel, attr.__doc__))
        elif callable(attr) and not isinstance(attr, (classmethod, staticmethod, type)):
            setattr(cls, name, _serial(attr))
    return cls


SIZE_FIELDS = ("size", "struct_size")


def new_struct(name):
    """A zeroed struct for C to fill (ms_stats, infos) or for a desc that has
    no *_desc_default(). If it carries a size field (the "descs only grow"
    promise), that is set to the size the package's listing
    gives, as a C caller's sizeof would; descs with a default come from C."""
    s = STRUCTS[name]()
    for f in SIZE_FIELDS:
        if f in dict(type(s)._fields_):
            setattr(s, f, ctypes.sizeof(s))
    return s


def filled(struct_name, fn, *args):
    """A dict of the struct C fills: fn(*args, &out) (infos, stats)."""
    out = new_struct(struct_name)
    fn(*args, ctypes.byref(out))
    return to_dict(out)


def _enum_of(type_name):
    return ABI["enums"].get(type_name.replace("const ", "").strip())


def set_fields(struct_name, s, values, what):
    """Set fields of a desc by name; arrays from sequences, enums from their
    names ("absorb" for MS_BOUNDARY_ABSORB) or values."""
    fields = {f["name"]: f for f in ABI["structs"][struct_name]["fields"]}
    for key, v in values.items():
        if key not in fields or key in SIZE_FIELDS:
            raise InvalidArgument("%s: %s has no field %r; its fields: %s"
                                  % (what, struct_name, key,
                                     ", ".join(k for k in fields if k not in SIZE_FIELDS)))
        t = fields[key]["type"]
        ct = ctype(t)
        enum = _enum_of(t)
        if enum is not None and isinstance(v, str):
            match = [val for n, val in enum.items() if n.lower().endswith("_" + v.lower())]
            if not match:
                raise InvalidArgument("%s: %s %r is not one of %s" % (
                    what, key, v, ", ".join(n for n in enum if not n.endswith("_"))))
            v = match[0]
        if hasattr(ct, "_length_"):
            seq = list(np.asarray(v, dtype=np.float64).ravel())
            if len(seq) != ct._length_:
                raise InvalidArgument("%s: %s needs %d values, got %d"
                                      % (what, key, ct._length_, len(seq)))
            v = ct(*seq)
        elif ct is ctypes.c_char_p and isinstance(v, str):
            v = v.encode()
        elif int_range(ct) is not None:
            v = check_int(v, ct, "%s: %s" % (what, key))
        elif ct in (ctypes.c_float, ctypes.c_double) and (
                isinstance(v, bool) or not isinstance(v, (int, float, np.number))):
            raise InvalidArgument("%s: %s = %r is not a number" % (what, key, v))
        try:
            setattr(s, key, v)
        except TypeError as e:
            raise InvalidArgument("%s: %s = %r: %s" % (what, key, v, e)) from None
    return s


def to_dict(s):
    out = {}
    for name, _ in type(s)._fields_:
        v = getattr(s, name)
        if isinstance(v, ctypes.Array):
            v = list(v)
        elif isinstance(v, bytes):
            v = v.decode()
        out[name] = v
    return out


def view(ptr, shape, dtype, owner, writeable=False, particles=False):
    """A numpy array over C memory (no copy), keeping `owner` alive;
    `particles`: it counts as a particle view of owner's (see
    Handle._no_particle_views) while it or any array made from it lives."""
    n = int(np.prod(shape))
    if not ptr or n == 0:  # zeros over an immutable buffer: read-only too
        return np.frombuffer(bytes(n * np.dtype(dtype).itemsize), dtype=dtype).reshape(shape)
    ct = np.ctypeslib.as_ctypes_type(np.dtype(dtype))
    buf = (ct * n).from_address(ptr)
    buf._modesplit_owner = owner
    owner._view_made(buf)
    if particles:
        owner._particle_view_made(buf)
    # A view that must not write is made over a read-only buffer, so that
    # a.flags.writeable = True fails (numpy refuses it for an array whose
    # base does not export write access); the memoryview keeps buf alive.
    src = buf if writeable else memoryview(buf).cast("B").toreadonly()
    a = np.frombuffer(src, dtype=dtype).reshape(shape)
    a.flags.writeable = writeable
    return a


def soa_view(n, ptrs, owner):
    """A read-only (n, 3) float32 view of three arrays x, y, z that lie in
    one block at equal distances (ms_sim_particles, ms_volume_particles
    promise it): strides (4, distance), no copy. It counts as a particle
    view of `owner` (see Handle._no_particle_views)."""
    if n == 0 or not ptrs[0]:
        return view(None, (0, 3), np.float32, owner)
    step = ptrs[1] - ptrs[0]
    if step <= 0 or ptrs[2] - ptrs[1] != step or step % 4:
        raise RuntimeError("modesplit: the library's particle arrays are not one block "
                           "(its header promises it): cannot view them as (n, 3)")
    flat = view(ptrs[0], (2 * step // 4 + n,), np.float32, owner, particles=True)
    return np.lib.stride_tricks.as_strided(flat, shape=(n, 3), strides=(4, step),
                                           writeable=False)


def as_input(x, shape, dtype, what):
    """An input array for C: an ndarray must already have the dtype and be
    C-contiguous (nothing is converted behind the caller's back); other
    array-likes (lists) are converted. Checked before C sees it."""
    dtype = np.dtype(dtype)
    if isinstance(x, np.ndarray):
        if x.dtype != dtype:
            raise InvalidArgument("%s: dtype %s, needs %s" % (what, x.dtype, dtype))
        if not x.flags.c_contiguous:
            raise InvalidArgument("%s: the array is not C-contiguous (np.ascontiguousarray "
                                  "makes a contiguous copy)" % what)
        a = x
    else:
        try:
            a = np.ascontiguousarray(x, dtype=dtype)
        except (TypeError, ValueError) as e:
            raise InvalidArgument("%s: not an array of %s: %s" % (what, dtype, e)) from None
    if tuple(a.shape) != tuple(shape):
        raise InvalidArgument("%s: shape %s, needs %s" % (what, tuple(a.shape), tuple(shape)))
    return a


def vec(x, n, what):
    """A small fixed vector (a point, a velocity): any n numbers."""
    try:
        a = np.asarray(x, dtype=np.float64).ravel()
    except (TypeError, ValueError) as e:
        raise InvalidArgument("%s: not %d numbers: %s" % (what, n, e)) from None
    if a.size != n:
        raise InvalidArgument("%s: %d values, needs %d" % (what, a.size, n))
    return (ctypes.c_float * n)(*a)


def cint():
    return ctypes.c_int()


L = lib
