"""Scene: a scene file (JSON) turned into the descs of the parts it asks for."""
import ctypes
import os

from ._base import Handle, L
from .errors import check


class Scene(Handle):
    """Scene.load(path) or Scene.parse(text). A Sim made from a scene keeps
    it alive: closing the scene while a sim uses it only marks it closed;
    the C scene is freed when the last such sim closes."""

    _kind = "Scene"

    def __init__(self, ptr):
        super().__init__(ptr, L().ms_scene_destroy)
        self._users = 0
        self._closing = False

    @classmethod
    def load(cls, path):
        p = ctypes.c_void_p()
        check(L().ms_scene_load(os.fsencode(path), ctypes.byref(p)))
        return cls(p.value)

    @classmethod
    def parse(cls, text):
        if isinstance(text, str):
            text = text.encode()
        p = ctypes.c_void_p()
        check(L().ms_scene_parse(text, len(text), ctypes.byref(p)))
        return cls(p.value)

    def close(self):
        if self._users > 0:
            self._closing = True   # freed when the last sim using it closes
        else:
            self._closing = False
            super().close()

    @property
    def closed(self):
        return self._closing or super().closed

    @property
    def _ptr(self):
        if self._closing:
            from .errors import Closed
            raise Closed("modesplit: the Scene is closed")
        return super()._ptr

    def _acquire(self):
        self._users += 1
        return self._h

    def _release(self):
        self._users -= 1
        if self._users == 0 and self._closing:
            self.close()

    name = property(lambda self: L().ms_scene_name(self._ptr).decode())
    text = property(lambda self: L().ms_scene_text(self._ptr).decode())
    path = property(lambda self: L().ms_scene_path(self._ptr).decode())
    duration = property(lambda self: L().ms_scene_duration(self._ptr))
    frame_dt = property(lambda self: L().ms_scene_frame_dt(self._ptr))
    output_fields = property(lambda self: L().ms_scene_output_fields(self._ptr))
    has_render = property(lambda self: bool(L().ms_scene_has_render(self._ptr)))
