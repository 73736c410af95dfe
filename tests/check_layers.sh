#!/bin/sh
# Dependencies point down (DESIGN.md, section 1): core includes no part's
# header, public or internal; volume and surface never include each other.
# Fails naming each include that points the wrong way.
set -eu
cd "$(dirname "$0")/.."
bad=0
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# core: its own headers, modesplit/core.h and system headers only
for f in lib/core/*.c lib/core/*.h; do
    grep -n '#include "' "$f" | grep -v '"core/\|"modesplit/core.h"' |
        sed "s|^|layers: $f:|; s|\$|  (core includes no part)|" || true
done > "$out"
for pair in "volume surface" "surface volume"; do
    set -- $pair
    grep -n "#include \"$2/\|#include \"modesplit/$2.h\"" lib/$1/*.c lib/$1/*.h 2>/dev/null |
        sed "s|^|layers: |; s|\$|  ($1 and $2 never include each other)|" || true
done >> "$out"
if [ -s "$out" ]; then
    cat "$out"
    bad=1
fi
[ $bad = 0 ] && echo "layers: core includes no part; volume and surface not each other"
exit $bad
