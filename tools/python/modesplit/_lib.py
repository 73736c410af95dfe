"""Finding libmodesplit.so and binding its C ABI with ctypes.

Why ctypes (not cffi): it is in the standard library, so the package has no
extension module to compile against a Python version (the wheel's one
compiled part is the library itself), and every declaration the binding needs is
already machine-readable in the ABI listing (abi.json, made by
tools/abi/abi_listing.py from the headers and the compiler). The struct
layouts and the function signatures are BUILT from that listing, and each
struct's ctypes size and offsets are checked against the compiler's at
import, so the Python side cannot drift from the C side: after an ABI change
`make abi` regenerates the listing and the package follows with no hand edits.

Where the library is looked for, in order (the error lists every place):
  1. $MODESPLIT_LIB: the library file, or a directory holding it; the word
     `pkg-config` asks for the installed library (pkg-config's libdir of
     `modesplit`) and nothing else;
  2. the wheel's own copy (modesplit/_native/libmodesplit.so, with its
     plugins beside it: setup.py builds both with the Makefile);
  3. pkg-config's libdir of `modesplit` (an installed library);
  4. the build tree beside the package (tools/python/../../build/lib);
  5. the system loader (ld.so: LD_LIBRARY_PATH, ldconfig's cache).
"""
import ctypes
import operator
import ctypes.util
import json
import os
import re
import subprocess

LIB_NAME = "libmodesplit.so"

_HERE = os.path.dirname(os.path.abspath(__file__))


def load_listing():
    with open(os.path.join(_HERE, "abi.json")) as f:
        return json.load(f)


ABI = load_listing()


class LibraryNotFound(OSError):
    """libmodesplit.so could not be loaded from any of the places tried."""


def _pkg_config_libdir():
    try:
        r = subprocess.run(["pkg-config", "--variable=libdir", "modesplit"],
                           capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.SubprocessError) as e:
        return None, "pkg-config not usable (%s)" % e
    if r.returncode != 0 or not r.stdout.strip():
        return None, "pkg-config knows no `modesplit` package"
    return r.stdout.strip(), None


def candidates():
    """(description, path or None, why-not) for each place, in search order."""
    out = []
    env = os.environ.get("MODESPLIT_LIB")
    if env == "pkg-config":
        libdir, why = _pkg_config_libdir()
        return [("MODESPLIT_LIB=pkg-config",
                 os.path.join(libdir, LIB_NAME) if libdir else None, why)]
    if env:
        p = os.path.join(env, LIB_NAME) if os.path.isdir(env) else env
        out.append(("MODESPLIT_LIB", p, None))
    else:
        out.append(("MODESPLIT_LIB", None, "not set"))
    out.append(("the wheel's copy", os.path.join(_HERE, "_native", LIB_NAME), None))
    libdir, why = _pkg_config_libdir()
    out.append(("pkg-config libdir", os.path.join(libdir, LIB_NAME) if libdir else None, why))
    build = os.path.normpath(os.path.join(_HERE, "..", "..", "..", "build", "lib", LIB_NAME))
    out.append(("build tree", build, None))
    found = ctypes.util.find_library("modesplit")
    out.append(("system loader", found or LIB_NAME, None))
    return out


def load_library():
    tried = []
    for what, path, why in candidates():
        if path is None:
            tried.append("%s: %s" % (what, why))
            continue
        if what != "system loader" and not os.path.exists(path):
            tried.append("%s: %s does not exist" % (what, path))
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as e:
            tried.append("%s: %s: %s" % (what, path, e))
    raise LibraryNotFound("modesplit: cannot load %s; looked in:\n  %s\n(install the package "
                          "from a clone with `pip install ./tools/python`, which builds the "
                          "library "
                          "into it; or set MODESPLIT_LIB to the library or its directory)"
                          % (LIB_NAME, "\n  ".join(tried)))


# ---- C types from the listing's type strings --------------------------------

_SCALARS = {
    "int": ctypes.c_int, "signed int": ctypes.c_int, "unsigned int": ctypes.c_uint,
    "unsigned": ctypes.c_uint, "long": ctypes.c_long, "long int": ctypes.c_long,
    "unsigned long": ctypes.c_ulong, "float": ctypes.c_float, "double": ctypes.c_double,
    "size_t": ctypes.c_size_t, "char": ctypes.c_char, "unsigned char": ctypes.c_ubyte,
    "uint32_t": ctypes.c_uint32, "uint64_t": ctypes.c_uint64, "int32_t": ctypes.c_int32,
    "int64_t": ctypes.c_int64, "void": None,
}
# Public enums are 32-bit (ms_status, ms_boundary, ...): C int.
_ENUMS = {name for name in ABI["enums"] if not name.startswith("(")}

STRUCTS = {}  # C name -> ctypes.Structure subclass


class AbiMismatch(ImportError):
    """The ctypes layout built from abi.json differs from the listing's."""


def ctype(t, param=False):
    """The ctypes type of a C type string from the listing."""
    s = re.sub(r"\bconst\b", " ", t)
    s = re.sub(r"\s+", " ", s).strip()
    s = re.sub(r"\s*\*\s*", "*", s)
    if "(" in s:                      # a function pointer
        return ctypes.c_void_p
    m = re.fullmatch(r"(.*?)\[(\d*)\]", s)
    if m:
        if param:                     # an array parameter is a pointer
            return ctypes.c_void_p
        return ctype(m.group(1)) * int(m.group(2))
    if s.endswith("*"):
        return ctypes.c_char_p if s == "char*" else ctypes.c_void_p
    if s in _SCALARS:
        return _SCALARS[s]
    if s in _ENUMS:
        return ctypes.c_int
    if s in STRUCTS:
        return STRUCTS[s]
    raise AbiMismatch("modesplit: abi.json names a C type the binding cannot map: %r" % t)


def _build_structs():
    pending = dict(ABI["structs"])
    while pending:
        progress = False
        for name, st in list(pending.items()):
            try:
                fields = [(f["name"], ctype(f["type"])) for f in st["fields"]]
            except AbiMismatch:
                continue  # a field of a struct not built yet
            cls = type(name, (ctypes.Structure,), {"_fields_": fields, "__doc__":
                                                    "C struct %s (from abi.json)" % name})
            STRUCTS[name] = cls
            del pending[name]
            progress = True
        if not progress:
            raise AbiMismatch("modesplit: cannot build the structs %s" % sorted(pending))
    for name, st in ABI["structs"].items():
        cls = STRUCTS[name]
        if ctypes.sizeof(cls) != st["size"]:
            raise AbiMismatch("modesplit: ctypes sizeof(%s) = %d, the C compiler's is %d"
                              % (name, ctypes.sizeof(cls), st["size"]))
        for f in st["fields"]:
            off = getattr(cls, f["name"]).offset
            if off != f["offset"]:
                raise AbiMismatch("modesplit: ctypes offsetof(%s, %s) = %d, the C compiler's "
                                  "is %d" % (name, f["name"], off, f["offset"]))


_build_structs()


_INTS = (ctypes.c_int, ctypes.c_uint, ctypes.c_long, ctypes.c_ulong, ctypes.c_size_t,
         ctypes.c_uint32, ctypes.c_uint64, ctypes.c_int32, ctypes.c_int64, ctypes.c_ubyte)


def int_range(ct):
    """(lo, hi) of a ctypes integer type, None for other types. ctypes
    stores an out-of-range Python int modulo 2**bits without a word
    (nx = 2**32 + 64 became 64), so every int is checked against this
    before ctypes sees it."""
    if ct not in _INTS:
        return None
    bits = 8 * ctypes.sizeof(ct)
    signed = ct(-1).value < 0
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)


def check_int(v, ct, what):
    """v as a Python int within ct's range; InvalidArgument otherwise (a
    bool, a float or a str is not an int here)."""
    from .errors import InvalidArgument
    r = int_range(ct)
    if isinstance(v, bool) or isinstance(v, float):
        raise InvalidArgument("%s: %r is not an integer" % (what, v))
    try:
        i = operator.index(v)
    except TypeError:
        raise InvalidArgument("%s: %r is not an integer" % (what, v)) from None
    if not r[0] <= i <= r[1]:
        raise InvalidArgument("%s: %d is out of the range of a C %s (%d .. %d)"
                              % (what, i, ct.__name__[2:], r[0], r[1]))
    return i


def _checked(cfn, name, argtypes):
    """cfn with its integer arguments range-checked and a wrong argument
    type raised as modesplit.InvalidArgument instead of ctypes.ArgumentError."""
    ints = [(i, t) for i, t in enumerate(argtypes) if int_range(t) is not None]

    def call(*args):
        if ints:
            args = list(args)
            for i, t in ints:
                if i < len(args) and not isinstance(args[i], ctypes._SimpleCData):
                    args[i] = check_int(args[i], t, "%s argument %d" % (name, i + 1))
        try:
            return cfn(*args)
        except ctypes.ArgumentError as e:
            from .errors import InvalidArgument
            raise InvalidArgument("%s: %s" % (name, e)) from None
    call.__name__ = name
    call.raw = cfn
    call.argtypes, call.restype = cfn.argtypes, cfn.restype
    return call


def enum_values(enum_name):
    return ABI["enums"][enum_name]


class Lib:
    """The C functions, typed from the listing (lib.ms_sim_step(...))."""

    def __init__(self):
        self.dll, self.path = load_library()
        missing = []
        for name, fn in ABI["functions"].items():
            if not fn["exported"]:
                continue
            try:
                cfn = getattr(self.dll, name)
            except AttributeError:
                missing.append(name)
                continue
            cfn.restype = ctype(fn["returns"])
            cfn.argtypes = [ctype(p["type"], param=True) for p in fn["params"]]
            setattr(self, name, _checked(cfn, name, cfn.argtypes))
        if missing:
            raise LibraryNotFound("modesplit: %s lacks %d functions of the headers the package "
                                  "was built for (an older library?): %s"
                                  % (self.path, len(missing), ", ".join(missing[:8])))
        lib_version = self.ms_version().decode()
        m = ABI["macros"]
        want = "%d.%d." % (m["MS_VERSION_MAJOR"], m["MS_VERSION_MINOR"])
        if not lib_version.startswith(want):
            raise LibraryNotFound("modesplit: %s is version %s, the package's ABI listing is "
                                  "for %s*" % (self.path, lib_version, want))


_lib = None


def lib():
    """The loaded library (loaded on first use, so `import modesplit` works
    without it and the error comes with the first call that needs it)."""
    global _lib
    if _lib is None:
        _lib = Lib()
    return _lib
