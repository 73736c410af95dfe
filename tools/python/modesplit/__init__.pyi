from typing import Any

from ._lib import ABI as ABI, LibraryNotFound as LibraryNotFound, lib as lib
from .errors import (Canceled as Canceled, Closed as Closed, Error as Error,
                     InvalidArgument as InvalidArgument, IoError as IoError,
                     OutOfMemory as OutOfMemory, ParseError as ParseError,
                     PluginError as PluginError, StateError as StateError, Unstable as Unstable,
                     Unsupported as Unsupported, ViewsAlive as ViewsAlive)
from .io import Reader as Reader, Writer as Writer
from .render import Renderer as Renderer
from .scene import Scene as Scene
from .shape import Shape as Shape
from .sim import FIELDS as FIELDS, Sim as Sim
from .surface import Surface as Surface
from .volume import Volume as Volume

__version__: str
__all__ = ["ABI", "LibraryNotFound", "lib", "Canceled", "Closed", "Error", "InvalidArgument",
           "IoError", "OutOfMemory", "ParseError", "PluginError", "StateError", "Unstable",
           "Unsupported", "Reader", "Writer", "Renderer", "Scene", "Shape", "FIELDS", "Sim",
           "Surface", "Volume", "ViewsAlive", "plugins", "version"]

def plugins() -> list[dict[str, Any]]: ...
def version() -> str: ...
