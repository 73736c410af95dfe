#!/bin/sh
# make format-check: the C lines changed since a base commit are
# laid out as .clang-format says (STYLE.md's habits). Only changed lines:
# the tree as a whole predates .clang-format, and reformatting it at once
# would make every branch in flight conflict; files touched later get
# formatted line by line as they change. The base: FORMAT_BASE if set,
# else where HEAD left main (with the uncommitted changes), else (a clean
# main, as in CI) the first parent of HEAD, so a merge commit is checked
# for all it brings in.
# Needs git-clang-format (Debian's clang-format, tools/deps.sh --ci); not
# part of `make check` (a CI-only tool), run by .ci/run.
set -eu
cd "$(dirname "$0")/.."
if ! command -v git-clang-format > /dev/null; then
    echo "format-check: git-clang-format not found (apt-get install clang-format; tools/deps.sh --ci)" >&2
    exit 1
fi
base="${FORMAT_BASE:-}"
if [ -z "$base" ]; then
    base="$(git merge-base HEAD main 2> /dev/null || true)"
fi
if [ -z "$base" ] || { [ "$(git rev-parse "$base")" = "$(git rev-parse HEAD)" ] &&
    git diff --quiet HEAD; }; then
    base="$(git rev-parse --verify -q HEAD^)" || {
        echo "format-check: HEAD has no parent here (a shallow clone?); set FORMAT_BASE" >&2
        exit 1
    }
fi
out="$(git clang-format --diff --extensions c,h "$base" -- include lib plugins tools tests 2>&1)" || {
    echo "$out" >&2
    echo "format-check: git clang-format failed" >&2
    exit 1
}
case "$out" in
    "" | "no modified files to format" | *"did not modify any files"*)
        echo "format-check: the C lines changed since $(git rev-parse --short "$base") follow .clang-format"
        ;;
    *)
        echo "$out"
        echo "format-check: the lines above, changed since $(git rev-parse --short "$base"), differ from .clang-format;" \
            "\`git clang-format $(git rev-parse --short "$base")\` lays them out" >&2
        exit 1
        ;;
esac
