#!/bin/sh
# The wheel as a new user gets it: a fresh clone of this repository's
# HEAD (committed files only), a new venv, `pip install ./tools/python`
# (which builds libmodesplit and its plugins with the Makefile, inside the
# wheel), then from / with no MODESPLIT_* variable: import, a step, a shape
# plugin loaded from inside the package; and `pip wheel` gives a platform
# wheel (py3-none-<platform>) holding the library, the plugins and the stubs.
#
#   tools/python/check_wheel.sh [VENV [EXTRAS]]
# VENV (default: a temporary one, removed) is left with the package
# installed, with the extras EXTRAS (e.g. test) for a caller's pytest.
# MODESPLIT_JOBS is make's -j (default 2 here: a shared machine).
set -eu
repo=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
venv=${1:-$tmp/venv}
extras=${2:+[$2]}
unset MODESPLIT_LIB MODESPLIT_PLUGIN_PATH MODESPLIT_BUILD PYTHONPATH || true
export MODESPLIT_JOBS=${MODESPLIT_JOBS:-2}

git clone -q "$repo" "$tmp/clone"
python3 -m venv "$venv"
"$venv/bin/pip" install -q --upgrade pip
"$venv/bin/pip" install -q "$tmp/clone/tools/python$extras"

cd /
"$venv/bin/python" - "$venv" <<'PY'
import os, sys
import modesplit
venv = os.path.realpath(sys.argv[1])
path = os.path.realpath(modesplit.lib().path)
assert path.startswith(venv + os.sep) and "_native" in path, \
    "the library was loaded from %s, not from the installed wheel in %s" % (path, venv)
plugins = modesplit.plugins()
names = {p["name"] for p in plugins}
assert {"sphere", "box", "water"} <= names, names
for p in plugins:
    assert os.path.realpath(p["path"]).startswith(venv + os.sep), p["path"]
s = modesplit.Surface(nx=32, ny=32, dx=0.01)
s.add_drop(0.16, 0.16, 0.04, 0.01)
s.step(1 / 60)
assert abs(float(s.height.sum())) > 0
sphere = modesplit.Shape("sphere", {"radius": 0.1})
d, _ = sphere.distance((0.3, 0, 0))
assert abs(d - 0.2) < 1e-5, d
print("wheel: library %s, %d plugins from the package, version %s"
      % (path, len(plugins), modesplit.version()))
PY

"$venv/bin/pip" wheel -q --no-deps -w "$tmp/wheel" "$tmp/clone/tools/python"
whl=$(ls "$tmp/wheel"/modesplit-*.whl)
case "$(basename "$whl")" in
*-py3-none-linux_*.whl) ;;
*) echo "wheel: $(basename "$whl") is not a py3-none-<platform> wheel" >&2; exit 1 ;;
esac
"$venv/bin/python" -m zipfile -l "$whl" >"$tmp/listing"
for f in modesplit/_native/libmodesplit.so modesplit/_native/modesplit/plugins/shape_sphere.so \
    modesplit/py.typed modesplit/sim.pyi; do
    grep -q "^$f " "$tmp/listing" || { echo "wheel: no $f inside $whl" >&2; exit 1; }
done
echo "wheel: $(basename "$whl") holds the library, the plugins and the stubs"
