#!/bin/sh
# run.sh BUILD DOMAINS - build the benchmark drivers and run every benchmark on
# the example domains (DOMAINS/*.poly) beside its peer (Triangle, scipy and Gmsh
# from PyPI, in the venv under BUILD; TetGen 1.5 from Debian for the 3D engine).
set -eu
BUILD=$1
DOMAINS=$2
CC=${CC:-cc}
# The libraries the static library needs (the Makefile passes its own list:
# TetGen and the C++ runtime in a TETGEN=1 build).
LIBS=${BENCH_LIBS:--llbfgs -lz -lm -fopenmp}
export BENCH_LIBS="$LIBS"
mkdir -p "$BUILD/bench"
$CC -std=c99 -O2 -Iinclude -o "$BUILD/bench/bench_delaunay" tests/bench/bench_delaunay.c \
    "$BUILD/lib/libcvmesh.a" $LIBS
# The 3D engine has no public handle yet: its driver includes lib/ and links the static library.
$CC -std=c99 -O2 -Iinclude -Ilib -D_POSIX_C_SOURCE=200809L -o "$BUILD/bench/bench_delaunay3" \
    tests/bench/bench_delaunay3.c "$BUILD/lib/libcvmesh.a" $LIBS
# TetGen (AGPL, Debian libtet1.5-dev) is linked only into this test-only C++ driver.
CXX=${CXX:-c++}
if [ -f /usr/include/tetgen.h ] && command -v "$CXX" >/dev/null 2>&1; then
    "$CXX" -O2 -o "$BUILD/bench/bench_tetgen3" tests/bench/bench_tetgen3.cxx -ltet
    "$CXX" -O2 -o "$BUILD/bench/bench_tetgen_quality" tests/bench/bench_tetgen_quality.cxx -ltet
else
    echo "# run.sh: no tetgen.h or C++ compiler: bench_delaunay3.py runs without TetGen"
fi
VENV="$BUILD/venv"
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install -q --disable-pip-version-check -r tests/bench/requirements.txt
# The gmsh wheel loads X11/GL libraries even when run headless; on bare Debian
# install them (root only), else say what is missing and let bench_refine.py
# skip the gmsh rows.
GMSH_DEBS="libglu1-mesa libgl1 libxcursor1 libxft2 libxinerama1 libxrender1"
if command -v dpkg-query >/dev/null 2>&1; then
    missing=
    for p in $GMSH_DEBS; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' ||
            missing="$missing $p"
    done
    if [ -n "$missing" ]; then
        line="DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends$missing"
        if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
            echo "# run.sh: installing for gmsh: $line"
            sh -c "$line" >/dev/null || echo "# run.sh: apt-get failed; gmsh rows may be skipped"
        else
            echo "# run.sh: gmsh needs (as root): $line"
            echo "# run.sh: gmsh rows skipped"
            export CVM_BENCH_NO_GMSH=1
        fi
    fi
fi
OMP_NUM_THREADS=1 "$VENV/bin/python" tests/bench/bench_delaunay.py "$BUILD" "$DOMAINS"
for extra in tests/bench/bench_refine.py tests/bench/bench_dual.py tests/bench/bench_delaunay3.py tests/bench/bench_matching.py tests/bench/bench_generate3.py tests/bench/bench_quad.py; do
    if [ -f "$extra" ]; then
        OMP_NUM_THREADS=1 "$VENV/bin/python" "$extra" "$BUILD" "$DOMAINS"
    fi
done
