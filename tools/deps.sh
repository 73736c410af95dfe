#!/bin/sh
# Installs the Debian packages libmodesplit needs when they are missing.
# As root it runs apt-get; otherwise it prints the one command to run.
#   tools/deps.sh          check, install what the product uses (root)
#   tools/deps.sh --ci     the same, plus the real clients the CI-only
#                          checks drive (ParaView's pvpython, h5py, valgrind,
#                          clang, clang-format)
#   tools/deps.sh --aarch64  the same, plus the aarch64 cross check's tools
#                          (`make check-aarch64`; --ci includes them)
#   tools/deps.sh --list   print the package list (with --ci: both lists)
set -eu

# build: compiler, make, pkg-config; libraries: JSON (jansson), HDF5, PNG,
# OSMesa (off-screen GL); tests: Check, h5dump (hdf5-tools).
PACKAGES="build-essential pkg-config libjansson-dev libhdf5-dev hdf5-tools libpng-dev \
libosmesa6-dev check libsubunit-dev"
# the ABI listing (`make check-abi`) parses the headers with pycparser
PACKAGES="$PACKAGES python3-pycparser"
# the renderer's EGL context backend: surfaceless Mesa
PACKAGES="$PACKAGES libegl-dev libegl-mesa0"
# what the product itself uses, so `make demo` and `make check` give all of
# it: the viewer (`modesplit view`, SDL2), the accuracy study's plots
# (gnuplot), `modesplit render --video` (ffmpeg)
PACKAGES="$PACKAGES libsdl2-dev gnuplot-nox ffmpeg"
# what `make check`'s suites drive, so that it runs every case instead of
# skipping some: tests/test_view.c runs the viewer under xvfb-run (xvfb, and
# xauth, which xvfb-run needs and --no-install-recommends leaves out), with
# real X events (xdotool) and screenshots compared by ImageMagick (import,
# compare; tests/view_x11.sh)
PACKAGES="$PACKAGES xvfb xauth xdotool imagemagick"
# the clients users run against the library's output, driven only by CI's
# own stages (`make check-paraview`, `make check-python`): installed by
# `tools/deps.sh --ci` (.ci/run), left to the user otherwise
CI_PACKAGES="x11-apps paraview python3-paraview python3-h5py python3-venv"
# valgrind and clang with its runtimes (libFuzzer, ASan: libclang-rt-14-dev,
# which --no-install-recommends leaves out) run only in CI (.ci/valgrind,
# .ci/fuzz): `make check` of a user without them must not fail for their
# absence.
CI_PACKAGES="$CI_PACKAGES valgrind clang libclang-rt-14-dev"
# `make format-check` (CI only: .clang-format)
CI_PACKAGES="$CI_PACKAGES clang-format"

# `make check-aarch64` (CI): Debian's cross gcc and C library for aarch64,
# and qemu-user to run what it builds. The arm64 libraries the suites link
# (jansson, Check, libpng) are unpacked by the Makefile into
# build-aarch64/sysroot/ with apt-get download, which needs the arm64
# package lists: the arm64 architecture is added to dpkg for that (no arm64
# package is installed, so nothing of the amd64 system changes).
AARCH64_PACKAGES="gcc-aarch64-linux-gnu libc6-dev-arm64-cross qemu-user"
AARCH64=0

if [ "${1:-}" = "--ci" ]; then
    PACKAGES="$PACKAGES $CI_PACKAGES"
    AARCH64=1
    shift
fi
if [ "${1:-}" = "--aarch64" ]; then
    AARCH64=1
    shift
fi
if [ $AARCH64 -eq 1 ]; then
    PACKAGES="$PACKAGES $AARCH64_PACKAGES"
fi

if [ "${1:-}" = "--list" ]; then
    echo $PACKAGES
    exit 0
fi

missing=""
for p in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done

# the arm64 package lists (--aarch64), read by apt-get download
need_arm64=0
if [ $AARCH64 -eq 1 ] && ! dpkg --print-foreign-architectures | grep -qx arm64; then
    need_arm64=1
fi

if [ -z "$missing" ] && [ $need_arm64 -eq 0 ]; then
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    [ -z "$missing" ] || echo "deps: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    if [ $need_arm64 -eq 1 ]; then
        echo "deps: adding the arm64 architecture (its package lists, for make check-aarch64)"
        dpkg --add-architecture arm64
    fi
    # wait for another apt (a second session, unattended upgrades) instead
    # of failing on its lock
    apt-get -o DPkg::Lock::Timeout=600 update -qq
    # shellcheck disable=SC2086
    [ -z "$missing" ] || apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends $missing
else
    [ $need_arm64 -eq 0 ] || echo "deps: run:  sudo dpkg --add-architecture arm64 && sudo apt-get update" >&2
    [ -z "$missing" ] || {
        echo "deps: missing Debian packages:$missing" >&2
        echo "deps: run:  sudo apt-get install -y$missing" >&2
    }
    exit 1
fi
