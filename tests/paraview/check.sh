#!/bin/sh
# ParaView opens every kind of run the tool writes: the demo
# scene, a run of 0 frames, of 1 frame, a run killed by SIGKILL, and runs
# that write only some fields; each with ParaView's default reader for
# run.xmf and the legacy reader for run.xdmf2 (tests/paraview/open_run.py),
# with no VTK/ParaView error printed, and a screenshot that is not blank.
#
#   tests/paraview/check.sh BUILD_DIR
# Exit 0 all good, 1 a failure; 77 when pvpython or Xvfb is missing,
# which is a failure when MS_TEST_NO_SKIP=1 (CI).
set -u
build=${1:-build}
tool=$build/bin/modesplit
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v pvpython >/dev/null 2>&1 || ! command -v Xvfb >/dev/null 2>&1; then
    echo "check-paraview: SKIPPED: pvpython or Xvfb is not installed (tools/deps.sh --ci installs them)"
    [ "${MS_TEST_NO_SKIP:-0}" = 1 ] && { echo "check-paraview: a skip fails in CI"; exit 1; }
    exit 77
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/ms-paraview.XXXXXX")
xpid=
trap '[ -n "$xpid" ] && kill $xpid 2>/dev/null; rm -rf "$tmp"' EXIT
fail=0

# One X server for every pvpython run, on a display number the server
# takes itself (-displayfd): `xvfb-run -a` guesses a free number from the
# lock files and loses the race to another X server starting at the same
# moment (CI runs the viewer's long check under Xvfb beside this stage).
# -noreset: pvpython probes OpenGL on a first connection and closes it; a
# server left with no client resets, and resets the next connection if it
# arrives meanwhile ("bad X server connection", an abort; every time on a
# loaded machine).
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xpid=$!
i=0
while [ ! -s "$tmp/display" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
if [ ! -s "$tmp/display" ]; then
    echo "check-paraview: Xvfb did not start in 30 s:"; cat "$tmp/xvfb.log"; exit 1
fi
DISPLAY=:$(cat "$tmp/display")
export DISPLAY

scene_with() { # $1 out.json, $2 fields (JSON list), $3 every
    python3 - "$1" "$2" "$3" <<'PY'
import json, sys
s = json.load(open("data/scenes/default.json"))
s["output"]["fields"] = json.loads(sys.argv[2])
s["output"]["every"] = int(sys.argv[3])
s["name"] = "paraview_check"
json.dump(s, open(sys.argv[1], "w"))
PY
}

open_run() { # $1 label, $2 run.h5, [$3 --killed]
    log=$tmp/$1.log
    (cd "$tmp" && timeout 600 pvpython "$here/open_run.py" "$2" "$tmp/$1.png" ${3:-}) >"$log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then
        echo "check-paraview: $1: FAILED"; grep -v '^ ' "$log" | tail -20; fail=1; return
    fi
    # a reader that prints an error has not opened the run cleanly
    if grep -E '^(ERROR|Warning|HDF5-DIAG)|Segmentation|Skipping unrecognized' "$log" >/dev/null; then
        echo "check-paraview: $1: ParaView printed errors:"; grep -E '^(ERROR|Warning|HDF5-DIAG)|Segmentation|Skipping' "$log" | head; fail=1; return
    fi
    echo "check-paraview: $1: ok ($(grep -c FAIL "$log") failures; $(grep screenshot "$log" || echo 'no field, no screenshot'))"
}

run() { # $1 label, rest: modesplit run arguments
    label=$1; shift
    if ! "$tool" run "$@" --quiet; then echo "check-paraview: $label: the run failed"; fail=1; return 1; fi
}

run demo data/scenes/default.json --frames 20 --out "$tmp/demo.h5" && open_run demo "$tmp/demo.h5"
run zero data/scenes/default.json --frames 0 --out "$tmp/zero.h5" && open_run zero_frames "$tmp/zero.h5"
run one data/scenes/default.json --frames 1 --out "$tmp/one.h5" && open_run one_frame "$tmp/one.h5"
scene_with "$tmp/combined.json" '["combined"]' 1
run combined "$tmp/combined.json" --frames 6 --out "$tmp/combined.h5" && open_run combined_only "$tmp/combined.h5"
scene_with "$tmp/particles.json" '["volume", "particles"]' 1
run particles "$tmp/particles.json" --frames 6 --out "$tmp/particles.h5" && open_run volume_and_particles "$tmp/particles.h5"

# killed: SIGKILL once a few frames are on disk
"$tool" run data/scenes/default.json --frames 100000 --out "$tmp/killed.h5" --quiet &
pid=$!
i=0
while [ $i -lt 600 ]; do
    sleep 0.1; i=$((i + 1))
    # the writer holds the file's lock (one writer per run file), which
    # HDF5's own locking would refuse this read; it reads one attribute
    n=$(HDF5_USE_FILE_LOCKING=FALSE python3 -c "import h5py,sys; print(h5py.File(sys.argv[1],'r').attrs['frames'])" "$tmp/killed.h5" 2>/dev/null || echo 0)
    [ "$n" -ge 5 ] 2>/dev/null && break
done
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
# The writer's journal helper (lib/io/h5_atomic.c) finishes a flush it has
# received after the writer died, then exits: open the file once no process
# holds it, as a user would (reading it while it is written is not HDF5's
# contract without SWMR).
i=0
while [ $i -lt 100 ] && python3 - "$tmp/killed.h5" <<'PY'
import os, sys
target = os.path.realpath(sys.argv[1])
for pid in filter(str.isdigit, os.listdir("/proc")):
    try:
        if any(os.path.realpath(f"/proc/{pid}/fd/{fd}") == target for fd in os.listdir(f"/proc/{pid}/fd")):
            sys.exit(0)
    except OSError:
        pass
sys.exit(1)
PY
do sleep 0.1; i=$((i + 1)); done
[ $i -lt 100 ] || { echo "check-paraview: killed: a process still holds killed.h5 after 10 s"; fail=1; }
open_run killed "$tmp/killed.h5" --killed

if [ $fail -ne 0 ]; then echo "check-paraview: FAILED"; exit 1; fi
echo "check-paraview: every run opens in ParaView (default and legacy readers)"
