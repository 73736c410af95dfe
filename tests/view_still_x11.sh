#!/bin/sh
# A pool at rest left open in `modesplit view` for minutes, under a real X
# server (tests/test_view.c runs this under xvfb-run from the repository's
# top directory): X screenshots (ImageMagick's import of the window below
# its overlay, whose numbers change every frame) at START s and after WAIT
# more seconds untouched, a drag across the water with xdotool, one
# screenshot 2 s after it, and two more SETTLE s and SETTLE + 10 s after
# it. Prints the mean colour differences (0-255): "still D" (START against
# START + WAIT), "dragged D" (the drag against the last still one) and
# "settled D" (the two after SETTLE: still again, if not as before); then
# presses Esc and exits with the viewer's status.
# Usage: view_still_x11.sh TOOL TMPDIR START WAIT SETTLE
set -eu
TOOL=$1
T=$2
START=$3
WAIT=$4
SETTLE=$5
"$TOOL" view tests/data/view_still_pool.json --size 300x300 > "$T/still.out" 2> "$T/still.err" &
pid=$!
win=""
i=0
while [ -z "$win" ]; do
    if ! kill -0 "$pid" 2> /dev/null || [ "$i" -ge 60 ]; then
        echo "no viewer window:"
        cat "$T/still.err"
        kill "$pid" 2> /dev/null || true
        exit 1
    fi
    sleep 0.5
    i=$((i + 1))
    win=$(xdotool search --onlyvisible --name 'modesplit' 2> /dev/null | head -n 1 || true)
done
eval "$(xdotool getwindowgeometry --shell "$win")" # X, Y, WIDTH, HEIGHT
shot() { import -window root -crop "${WIDTH}x$((HEIGHT - 110))+${X}+$((Y + 110))" +repage "$1"; }
diff_of() { compare -metric MAE "$1" "$2" null: 2>&1 | sed 's/ .*//' | awk '{print $1 / 257}'; }
sleep "$START"
shot "$T/a.png"
sleep "$WAIT"
shot "$T/b.png"
xdotool mousemove --window "$win" 60 170 mousedown 1
for x in 70 80 90 100 110 120 130 140 150 160 170 180 190 200 210 220 230 240; do
    xdotool mousemove --window "$win" "$x" 170
    sleep 0.1
done
for x in 230 220 210 200 190 180 170 160 150 140 130 120 110 100 90 80 70; do
    xdotool mousemove --window "$win" "$x" 200
    sleep 0.1
done
xdotool mouseup 1
sleep 2
shot "$T/c.png"
sleep "$SETTLE"
shot "$T/d.png"
sleep 10
shot "$T/e.png"
echo "still $(diff_of "$T/a.png" "$T/b.png")"
echo "dragged $(diff_of "$T/b.png" "$T/c.png")"
echo "settled $(diff_of "$T/d.png" "$T/e.png")"
xdotool mousemove --window "$win" 150 170 key Escape || echo "xdotool: Esc not sent"
rc=0
wait "$pid" || rc=$?
cat "$T/still.err"
echo "exit $rc"
exit "$rc"
