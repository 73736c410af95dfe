"""The wheel's build step: the C library and its plugins, built by the
repository's own Makefile, go inside the package (modesplit/_native/).

setuptools stays the backend (PEP 517, setuptools.build_meta, as before):
the package is pure Python over ctypes, so the only compiled part is the
library the Makefile already builds, and a build_py step that runs `make`
is all it takes; scikit-build-core or meson-python would bring a second
build system to describe what the Makefile describes. The wheel is tagged
py3-none-<platform> (linux_x86_64 here): ctypes needs no Python ABI, but
libmodesplit.so is machine code for this platform.

Layout inside the package, the library's own install layout, so that its
plugin search (lib/plugin/search.c: <dir of libmodesplit.so>/modesplit/
plugins, found with dladdr) finds the plugins with no variable:
    modesplit/_native/libmodesplit.so
    modesplit/_native/modesplit/plugins/shape_*.so, shader_*.so

The build needs the repository (tools/python/../../Makefile): the wheel is
built from a clone (`pip install ./tools/python`), not from an sdist.
MODESPLIT_JOBS sets make's -j (default: the CPUs this process may use)."""
import glob
import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.bdist_wheel import bdist_wheel
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
# Its own build directory (ignored by git as /build-*/): the objects are
# not shared with a sanitizer or debug build, and a second pip install
# from the same clone rebuilds only what changed.
BUILD = os.path.join(ROOT, "build-wheel")


def make_library():
    if not os.path.exists(os.path.join(ROOT, "Makefile")) or \
            not os.path.exists(os.path.join(ROOT, "include", "modesplit", "core.h")):
        raise SystemExit("modesplit: the wheel builds libmodesplit with the repository's Makefile, "
                         "and %s is not a libmodesplit clone; run `pip install ./tools/python` "
                         "from a clone" % ROOT)
    jobs = os.environ.get("MODESPLIT_JOBS") or str(len(os.sched_getaffinity(0)))
    cmd = ["make", "-C", ROOT, "-j" + jobs, "BUILD=" + BUILD, "lib", "plugins"]
    print("modesplit: building the library:", " ".join(cmd), flush=True)
    r = subprocess.run(cmd)
    if r.returncode != 0:
        raise SystemExit("modesplit: `%s` failed (exit %d); tools/deps.sh installs what the "
                         "library needs (HDF5, jansson, libpng; OSMesa/EGL optional)"
                         % (" ".join(cmd), r.returncode))


class BuildPyWithLibrary(build_py):
    def run(self):
        super().run()
        make_library()
        native = os.path.join(self.build_lib, "modesplit", "_native")
        plugins = os.path.join(native, "modesplit", "plugins")
        shutil.rmtree(native, ignore_errors=True)
        os.makedirs(plugins)
        # one real file (a wheel holds no symlinks): libmodesplit.so.X.Y.Z
        shutil.copyfile(os.path.realpath(os.path.join(BUILD, "lib", "libmodesplit.so")),
                        os.path.join(native, "libmodesplit.so"))
        for p in sorted(glob.glob(os.path.join(BUILD, "plugins", "*.so"))):
            shutil.copyfile(p, os.path.join(plugins, os.path.basename(p)))
        for f in glob.glob(os.path.join(native, "**", "*.so"), recursive=True):
            os.chmod(f, 0o755)


class PlatformWheel(bdist_wheel):
    def finalize_options(self):
        super().finalize_options()
        self.root_is_pure = False

    def get_tag(self):
        _, _, plat = super().get_tag()
        return "py3", "none", plat


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True


setup(cmdclass={"build_py": BuildPyWithLibrary, "bdist_wheel": PlatformWheel},
      distclass=BinaryDistribution)
