#!/bin/sh
# The shared library exports the public ms_* API and nothing else
# (-fvisibility=hidden, MS_API on public symbols only), and has a SONAME.
set -eu
lib="$1"
# __bss_start, _edata and _end are the linker's section bounds, not code:
# GNU ld puts them in the dynamic table of some builds (ThreadSanitizer's).
bad=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDRBW]$/ {print $3}' |
      grep -v -e '^ms_' -e '^__bss_start$' -e '^_edata$' -e '^_end$' || true)
if [ -n "$bad" ]; then
    echo "exports: $lib exports non-ms_ symbols:" >&2
    echo "$bad" >&2
    exit 1
fi
n=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDRBW]$/ && $3 ~ /^ms_/' | wc -l)
soname=$(readelf -d "$lib" | sed -n 's/.*SONAME.*\[\(.*\)\].*/\1/p')
if [ -z "$soname" ]; then
    echo "exports: $lib has no SONAME" >&2
    exit 1
fi
echo "exports: $n ms_* symbols, SONAME $soname"
