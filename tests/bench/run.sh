#!/bin/sh
# run.sh BUILD SHARED - build the benchmark drivers and run every benchmark
# beside its peer (Triangle and scipy from PyPI, in a venv under BUILD).
set -eu
BUILD=$1
SHARED=$2
CC=${CC:-cc}
mkdir -p "$BUILD/bench"
$CC -std=c99 -O2 -Iinclude -o "$BUILD/bench/bench_delaunay" tests/bench/bench_delaunay.c \
    "$BUILD/lib/libcvmesh.a" -lm -fopenmp
VENV="$BUILD/venv"
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/python" -c 'import numpy, scipy, triangle' 2>/dev/null ||
    "$VENV/bin/pip" install -q numpy scipy triangle
OMP_NUM_THREADS=1 "$VENV/bin/python" tests/bench/bench_delaunay.py "$BUILD" "$SHARED"
for extra in tests/bench/bench_refine.py; do
    if [ -f "$extra" ]; then
        OMP_NUM_THREADS=1 "$VENV/bin/python" "$extra" "$BUILD" "$SHARED"
    fi
done
