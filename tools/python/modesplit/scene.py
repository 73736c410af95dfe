"""Scene: a scene file (JSON) turned into the descs of the parts it asks for."""
import ctypes
import os

from ._base import Handle, L
from .errors import check


class Scene(Handle):
    """Scene.load(path) or Scene.parse(text). A Sim made from a scene keeps
    it alive: closing the scene while a sim uses it closes the Python side;
    the C scene is freed when the last such sim is."""

    _kind = "Scene"

    def __init__(self, ptr):
        super().__init__(ptr, L().ms_scene_destroy)

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

    name = property(lambda self: L().ms_scene_name(self._ptr).decode())
    text = property(lambda self: L().ms_scene_text(self._ptr).decode())
    path = property(lambda self: L().ms_scene_path(self._ptr).decode())
    duration = property(lambda self: L().ms_scene_duration(self._ptr))
    frame_dt = property(lambda self: L().ms_scene_frame_dt(self._ptr))
    output_fields = property(lambda self: L().ms_scene_output_fields(self._ptr))
    has_render = property(lambda self: bool(L().ms_scene_has_render(self._ptr)))
