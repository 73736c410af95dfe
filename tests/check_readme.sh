#!/bin/sh
# The C examples users copy first compile (warnings as errors) against the
# library just built and run to completion: README.md's example under
# '## Using the library from C' and the one opening modesplit.h.
set -eu
build="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
awk '/^## Using the library from C/ {f = 1} f && /^```c/ {p = 1; next} p && /^```/ {exit} p' \
    README.md > "$tmp/readme.c"
# the header's example: the comment lines from its #include to main's end
sed -n '/^ \*     #include <modesplit\/modesplit.h>/,/^ \*     }$/p' include/modesplit/modesplit.h |
    sed -e 's/^ \*     //' -e 's/^ \*$//' > "$tmp/header.c"
for ex in readme header; do
    if [ ! -s "$tmp/$ex.c" ]; then
        echo "examples: the $ex example was not found" >&2
        exit 1
    fi
    ${CC:-cc} -std=c11 -Wall -Wextra -Werror -Iinclude "$tmp/$ex.c" "$build/lib/libmodesplit.a" \
        ${MS_LIBS:-$(pkg-config --libs jansson hdf5 libpng osmesa 2>/dev/null) -ldl -lpthread -lm} \
        -o "$tmp/$ex"
    if ! "$tmp/$ex" > "$tmp/$ex.out" 2> "$tmp/$ex.err"; then
        echo "examples: the $ex example failed:" >&2
        cat "$tmp/$ex.err" >&2
        exit 1
    fi
    echo "examples: the $ex example builds and runs ($(wc -l < "$tmp/$ex.out") lines of output)"
done
