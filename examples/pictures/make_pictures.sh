#!/bin/sh
# make_pictures.sh [CVMESH] - redraw the README pictures: the NACA 0012 of
# examples/data meshed by each refiner with the automatic size, framed on the
# airfoil (needs rsvg-convert, Debian package librsvg2-bin).
set -eu
cd "$(dirname "$0")/../.."
cli=${1:-build/bin/cvmesh}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for a in delaunay frontal aflr; do
    "$cli" refine examples/data/naca0012.poly --algo $a --auto 4 --grading 3 \
        --svg "$tmp/$a.svg" --svg-window=-0.45,-0.6,1.55,0.6
    rsvg-convert "$tmp/$a.svg" -o examples/pictures/naca0012_$a.png
done
