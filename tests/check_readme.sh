#!/bin/sh
# The C example of README.md compiles (warnings as errors) against the
# library just built and runs to completion: the README stays true.
set -eu
build="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
awk '/^## Using the library from C/ {f = 1} f && /^```c/ {p = 1; next} p && /^```/ {exit} p' \
    README.md > "$tmp/example.c"
if [ ! -s "$tmp/example.c" ]; then
    echo "readme: no C example found under '## Using the library from C'" >&2
    exit 1
fi
${CC:-cc} -std=c11 -Wall -Wextra -Werror -Iinclude "$tmp/example.c" "$build/lib/libmodesplit.a" \
    $(pkg-config --libs jansson hdf5 libpng 2>/dev/null) -ldl -lpthread -lm -o "$tmp/example"
"$tmp/example" > "$tmp/out.txt"
echo "readme: the C example builds and runs ($(wc -l < "$tmp/out.txt") lines of output)"
