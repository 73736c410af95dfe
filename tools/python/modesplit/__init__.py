"""modesplit: Python over libmodesplit's C ABI (ctypes), with numpy views.

    import modesplit as ms
    with ms.Sim(ms.Scene.load("data/scenes/fig3.json")) as sim:
        for _ in range(60):
            sim.step()
        print(sim.height.shape, sim.stats()["total_ms"])

Every failing C call raises a modesplit.Error subclass (InvalidArgument,
Unstable, ParseError, ...) carrying ms_last_error()'s sentence and the status
name. The library is found from $MODESPLIT_LIB, the copy inside the installed
wheel, pkg-config, the build tree beside this package, or the system loader
(see modesplit._lib).
"""
from ._lib import ABI, LibraryNotFound, lib
from .errors import (Canceled, Closed, Error, InvalidArgument, IoError, OutOfMemory, ParseError,
                     PluginError, StateError, Unstable, Unsupported, ViewsAlive)
from .io import Reader, Writer
from .render import Renderer
from .scene import Scene
from .shape import Shape
from .sim import FIELDS, Sim
from .surface import Surface
from .volume import Volume

__all__ = ["ABI", "LibraryNotFound", "lib", "Canceled", "Closed", "Error", "InvalidArgument",
           "IoError",
           "OutOfMemory", "ParseError", "PluginError", "StateError", "Unstable", "Unsupported",
           "Reader", "Writer", "Renderer", "Scene", "Shape", "FIELDS", "Sim", "Surface",
           "Volume", "ViewsAlive", "plugins", "version"]
__version__ = "%d.%d.%d" % (ABI["macros"]["MS_VERSION_MAJOR"], ABI["macros"]["MS_VERSION_MINOR"],
                            ABI["macros"]["MS_VERSION_PATCH"])


def plugins():
    """The shape and shader plugins found (name, kind, version, description,
    path, abi), as `modesplit plugins` lists them."""
    import ctypes

    from ._base import new_struct, to_dict
    from .errors import check
    L = lib()
    out = []
    for i in range(L.ms_plugin_count()):
        d = new_struct("ms_plugin_description")
        check(L.ms_plugin_describe(i, ctypes.byref(d)))
        out.append(to_dict(d))
    return out


def version():
    """The loaded library's version string ("0.1.0")."""
    return lib().ms_version().decode()
