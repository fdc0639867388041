#!/bin/sh
# bindings/fortran/check.sh - checks of the Fortran binding:
#  1. cvmesh_c_interfaces.inc is what gen_interfaces.py makes of include/cvmesh.h
#     (a header change without regenerating fails here);
#  2. the module compiles warning-free (-Werror) and its tests pass;
#  3. examples/fortran/channel_poisson.f90 and the Fortran blocks of
#     bindings/README.md and README.md compile, link against the static library and run;
#  4. `make install-c install-fortran` into $BUILD/fortran/stage, then the example
#     once more, built with nothing but `pkg-config --cflags --libs cvmesh-fortran`.
# Usage: sh bindings/fortran/check.sh [--build-only]
# Environment: CVM_BUILD or BUILD (build directory, default build, relative to the top), FC (gfortran),
#   FFLAGS, CVMESH_LIB (static library; default: built with make), LIBS.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${CVM_BUILD:-${BUILD:-build}}
case $build in /*) ;; *) build=$root/$build ;; esac
out=$build/fortran
# make is given the build directory as the top Makefile names it (relative to
# the top when inside it): its dependency files record object paths as given,
# so one build directory named two ways would not see header changes.
mkbuild=${build#"$root"/}
FC=${FC:-gfortran}
[ "$FC" = f77 ] && FC=gfortran   # make's default FC
FFLAGS=${FFLAGS:--O2 -g -std=f2008 -Wall -Wextra -pedantic -Werror -fimplicit-none}
LIBS=${LIBS:--llbfgs -lz -lm -fopenmp}
PYTHON=${PYTHON:-python3}

"$PYTHON" "$here/gen_interfaces.py" --check

lib=${CVMESH_LIB:-}
if [ -z "$lib" ]; then
    make -s -C "$root" BUILD="$mkbuild" "$mkbuild/lib/libcvmesh.a"
    lib=$build/lib/libcvmesh.a
fi

mkdir -p "$out"
$FC $FFLAGS -J"$out" -I"$here" -c "$here/cvmesh.f90" -o "$out/cvmesh.o"
rm -f "$out/libcvmesh_fortran.a"
ar rcs "$out/libcvmesh_fortran.a" "$out/cvmesh.o"

build_prog() {  # build_prog NAME SOURCE
    $FC $FFLAGS -I"$out" -c "$2" -o "$out/$1.o"
    $FC -o "$out/$1" "$out/$1.o" "$out/libcvmesh_fortran.a" "$lib" $LIBS
}

# The ```fortran block of the README, as written.
awk '/^```fortran$/ { on = 1; next } /^```/ { on = 0 } on' "$root/bindings/README.md" \
    > "$out/readme_snippet.f90"
awk '/^```fortran$/ { on = 1; next } /^```/ { on = 0 } on' "$root/README.md" \
    > "$out/readme_top_snippet.f90"

build_prog test_cvmesh "$here/test_cvmesh.f90"
build_prog channel_poisson "$root/examples/fortran/channel_poisson.f90"
build_prog readme_snippet "$out/readme_snippet.f90"
build_prog readme_top_snippet "$out/readme_top_snippet.f90"
[ "${1:-}" = --build-only ] && exit 0

echo "check-fortran: README snippets"
"$out/readme_snippet"
"$out/readme_top_snippet"
echo "check-fortran: examples/fortran/channel_poisson"
"$out/channel_poisson"
echo "check-fortran: module tests"
"$out/test_cvmesh"

echo "check-fortran: examples/fortran against an installed copy, through cvmesh-fortran.pc"
stage=$out/stage
rm -rf "$stage"
make -s -C "$root" BUILD="$mkbuild" FC="$FC" PREFIX="$stage" install-c install-fortran >/dev/null
flags=$(PKG_CONFIG_PATH=$stage/lib/pkgconfig pkg-config --cflags --libs cvmesh-fortran)
case $flags in *"$stage/include/cvmesh/"*) ;;
    *) echo "check-fortran: cvmesh-fortran.pc has no compiler-specific module directory: $flags"
       exit 1 ;;
esac
echo "$FC channel_poisson.f90 $flags"
(cd "$out" && $FC $FFLAGS "$root/examples/fortran/channel_poisson.f90" $flags \
    -Wl,-rpath,"$stage/lib" -o channel_poisson_installed)
(cd "$out" && ./channel_poisson_installed >/dev/null)
echo "check-fortran: installed example ok"
