#!/bin/sh
# check_standalone.sh - the repository stands alone:
#  1. no Makefile, script, test or source names the development machines'
#     shared folder (the parent's "shared") or its old make variable;
#  2. a clone of HEAD in an empty temporary folder, with nothing beside it,
#     runs `make demo` and a quick part of the tests (unit and CLI tests).
# Usage: sh .ci/check_standalone.sh [--grep-only]
set -eu
cd "$(dirname "$0")/.."
self=.ci/check_standalone.sh
# The two names are assembled so that this script does not match itself.
up=".."; var="SHARED"
pattern="$up/shared|${var}_DIR"
hits=$(git ls-files | grep -v -e '\.md$' -e "^$self\$" | xargs grep -n -E "$pattern" -- 2>/dev/null || true)
if [ -n "$hits" ]; then
    echo "check-standalone: these lines reach outside the repository:"
    echo "$hits" | head -n 20
    exit 1
fi
echo "check-standalone: no file names a folder outside the repository"
[ "${1:-}" = --grep-only ] && exit 0

tmp=$(mktemp -d "${TMPDIR:-/tmp}/cvmesh_standalone.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
git clone -q . "$tmp/cvmesh"
echo "check-standalone: clone of $(git rev-parse --short HEAD) in $tmp/cvmesh (nothing beside it)"
# A clean environment for the clone's make: nothing of this make's command line
# or of the test environment leaks in.
(cd "$tmp/cvmesh" &&
 env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u MAKEOVERRIDES -u CVM_DATA_DIR -u CVM_TEST_DATA \
     -u BUILD -u PYTHONPATH make demo > "$tmp/demo.log" 2>&1) ||
    { tail -n 30 "$tmp/demo.log"; echo "check-standalone: make demo failed in the clone"; exit 1; }
for f in naca0012.vtu naca0012_frontal.svg naca0012_aflr.vtu; do
    [ -s "$tmp/cvmesh/build/demo/$f" ] || { echo "check-standalone: make demo wrote no build/demo/$f"; exit 1; }
done
echo "check-standalone: make demo ok"
(cd "$tmp/cvmesh" &&
 env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u MAKEOVERRIDES -u CVM_DATA_DIR -u CVM_TEST_DATA \
     -u BUILD -u PYTHONPATH make check-unit check-cli > "$tmp/check.log" 2>&1) ||
    { tail -n 40 "$tmp/check.log"; echo "check-standalone: unit or CLI tests failed in the clone"; exit 1; }
grep -h -E '^100%: Checks:|^[0-9]+ passed, [0-9]+ failed' "$tmp/check.log" | sed 's/^/check-standalone: clone: /'
