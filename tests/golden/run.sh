#!/bin/sh
# run.sh CLI [--update] - golden checksums: the md5 of every mesh the CLI
# writes for the example domains (triangulate; refine with each algorithm at
# its defaults and at --min-angle 34; optimise with both solvers), in .vtu,
# .msh and .node. A change that alters a mesh must say so by updating
# tests/golden/sums.md5 (--update) in the same commit.
# Prints "N passed, M failed" last; exits 1 when a sum differs.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cli=$1
case $cli in /*) ;; *) cli=$(pwd)/$cli ;; esac
sums=$here/sums.md5
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cvmesh_golden.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
out=$tmp/out
mkdir "$out"

run() {  # run NAME ARGS...: write NAME.{vtu,msh,node} with the CLI
    name=$1
    shift
    for ext in vtu msh node; do
        "$cli" "$@" -o "$out/$name.$ext" > /dev/null ||
            { echo "golden: cvmesh $* -o $name.$ext failed"; exit 1; }
    done
}

# domain and a uniform size that gives it a few hundred to a few thousand triangles
for d in square:0.05 channel:0.1 annulus:0.3 cylinder:0.8 naca0012:0.8; do
    h=${d#*:}
    d=${d%:*}
    in=$root/examples/data/$d.poly
    run "$d.triangulate" triangulate "$in"
    for a in delaunay frontal aflr; do
        run "$d.refine_$a" refine "$in" --algo $a --size "$h"
        run "$d.refine_${a}_34" refine "$in" --algo $a --size "$h" --min-angle 34 --max-steiner 200000
    done
    for solver in 1 2; do
        run "$d.optimise_$solver" optimise "$in" --size "$h" --solver $solver --max-sweeps 5
    done
done

(cd "$out" && md5sum $(ls | LC_ALL=C sort)) > "$tmp/new.md5"
if [ "${2:-}" = --update ]; then
    cp "$tmp/new.md5" "$sums"
    echo "golden: wrote $(wc -l < "$sums") sums to $sums"
    exit 0
fi
passed=0
failed=0
while read -r sum file; do
    want=$(awk -v f="$file" '$2 == f { print $1 }' "$sums")
    if [ "$want" = "$sum" ]; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "golden: $file differs (${want:-no committed sum})"
    fi
done < "$tmp/new.md5"
extra=$(awk 'NR == FNR { seen[$2] = 1; next } !($2 in seen) { print $2 }' "$tmp/new.md5" "$sums")
for f in $extra; do
    failed=$((failed + 1))
    echo "golden: $f has a committed sum but was not written"
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
