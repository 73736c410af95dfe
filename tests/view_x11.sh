#!/bin/sh
# Real X events for `modesplit view` (tests/test_view.c runs this under
# xvfb-run, from the repository's top directory): start the viewer on a
# still pool of waves, take two X screenshots (ImageMagick's import of the
# root window) 1 s apart without touching it, then press, drag and release
# the left button across the water with xdotool and take a third; print
# the mean colour difference (0-255) of the water part of the window
# (below the overlay's text), "still D" and "dragged D"; then press Esc and
# exit with the viewer's status. The session's input log and run file
# (live.log, live.h5) stay in TMPDIR for the replay check. Usage: view_x11.sh TOOL TMPDIR
set -eu
TOOL=$1
T=$2
"$TOOL" view tests/data/view_waves.json --size 300x300 --record-input "$T/live.log" \
    --out "$T/live.h5" > "$T/x11.out" 2> "$T/x11.err" &
pid=$!
win=""
i=0
while [ -z "$win" ]; do
    if ! kill -0 "$pid" 2> /dev/null || [ "$i" -ge 60 ]; then
        echo "no viewer window:"
        cat "$T/x11.err"
        kill "$pid" 2> /dev/null || true
        exit 1
    fi
    sleep 0.5
    i=$((i + 1))
    win=$(xdotool search --onlyvisible --name 'modesplit' 2> /dev/null | head -n 1 || true)
done
eval "$(xdotool getwindowgeometry --shell "$win")" # X, Y, WIDTH, HEIGHT
sleep 3
# the window below its overlay (whose numbers change every frame)
shot() { import -window root -crop "${WIDTH}x$((HEIGHT - 110))+${X}+$((Y + 110))" +repage "$1"; }
diff_of() { compare -metric MAE "$1" "$2" null: 2>&1 | sed 's/ .*//' | awk '{print $1 / 257}'; }
shot "$T/a.png"
sleep 1
shot "$T/b.png"
xdotool mousemove --window "$win" 90 170 mousedown 1
for x in 100 110 120 130 140 150 160 170 180 190 200 210; do
    xdotool mousemove --window "$win" "$x" 170
    sleep 0.2
done
xdotool mouseup 1
# a frame under a loaded llvmpipe can take half a second: let the drag's
# frames reach the window before the screenshot
sleep 2
shot "$T/c.png"
echo "still $(diff_of "$T/a.png" "$T/b.png")"
echo "dragged $(diff_of "$T/b.png" "$T/c.png")"
# Esc through XTEST to the window under the pointer (no window manager:
# focus follows the pointer), not XSendEvent to $win: under load the id
# found by the search was once gone by now (BadWindow), which aborted this
# script before it could print the viewer's own stderr below
xdotool mousemove --window "$win" 150 170 key Escape || echo "xdotool: Esc not sent"
rc=0
wait "$pid" || rc=$?
cat "$T/x11.err"
echo "exit $rc"
exit "$rc"
