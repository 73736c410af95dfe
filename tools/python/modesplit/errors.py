"""modesplit.Error and one subclass per ms_status (core.h's MS_STATUS_MAP).

Every non-OK status a C call returns becomes the subclass of its status,
carrying ms_last_error()'s sentence (`message`), the status name
(`status_name`, "MS_ERR_UNSTABLE") and value (`status`). The values come
from the ABI listing, so a status added to the C map appears here as a
plain `Error` with its name until it gets a class of its own.
"""
from ._lib import enum_values


class Error(Exception):
    """A libmodesplit call failed."""

    status = None
    status_name = None

    def __init__(self, message, status=None, status_name=None):
        super().__init__(message if status_name is None else "%s (%s)" % (message, status_name))
        self.message = message
        if status is not None:
            self.status = status
        if status_name is not None:
            self.status_name = status_name


class InvalidArgument(Error, ValueError):
    """MS_ERR_INVALID_ARGUMENT: a value out of its range."""


class OutOfMemory(Error, MemoryError):
    """MS_ERR_OUT_OF_MEMORY."""


class Unstable(Error):
    """MS_ERR_UNSTABLE: parameters that cannot be made numerically stable."""


class IoError(Error, OSError):
    """MS_ERR_IO: a file could not be read or written."""


class ParseError(Error):
    """MS_ERR_PARSE: a scene or run file that is not well formed."""


class PluginError(Error):
    """MS_ERR_PLUGIN: a plugin could not be found, loaded or created."""


class Unsupported(Error):
    """MS_ERR_UNSUPPORTED: not supported by this build (e.g. no OSMesa)."""


class StateError(Error):
    """MS_ERR_STATE: the call is not allowed in the object's current state."""


class ViewsAlive(StateError, BufferError):
    """A call that would change a volume's particle count while numpy views
    of its particles are alive (raised before C is called, as a bytearray
    refuses to resize while a memoryview of it exists)."""


class Canceled(Error):
    """MS_ERR_CANCELED: a step stopped by cancel() (from another thread;
    Ctrl-C on the main thread raises KeyboardInterrupt instead)."""


class Closed(Error, ValueError):
    """The Python object's handle was closed (raised before C is called)."""


_BY_NAME = {
    "MS_ERR_INVALID_ARGUMENT": InvalidArgument,
    "MS_ERR_OUT_OF_MEMORY": OutOfMemory,
    "MS_ERR_UNSTABLE": Unstable,
    "MS_ERR_IO": IoError,
    "MS_ERR_PARSE": ParseError,
    "MS_ERR_PLUGIN": PluginError,
    "MS_ERR_UNSUPPORTED": Unsupported,
    "MS_ERR_STATE": StateError,
    "MS_ERR_CANCELED": Canceled,
}
STATUS = {name: value for name, value in enum_values("ms_status").items()
          if not name.endswith("_")}
_BY_VALUE = {value: name for name, value in STATUS.items()}
for _name, _cls in _BY_NAME.items():
    _cls.status = STATUS[_name]
    _cls.status_name = _name


def error_class(status):
    return _BY_NAME.get(_BY_VALUE.get(status), Error)


def last_error():
    """ms_last_error() of the calling thread (the sentence is thread-local)."""
    from ._lib import lib
    return lib().ms_last_error().decode()


def check(status, message=None):
    """Raise the Error subclass of a non-OK status with the library's sentence
    (`message`: the sentence when the call ran on another thread)."""
    if status == 0:
        return
    from ._lib import lib
    L = lib()
    name = L.ms_status_name(status).decode()
    message = message or L.ms_last_error().decode() or L.ms_status_text(status).decode()
    raise error_class(status)(message, status, name)
