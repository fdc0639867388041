#!/bin/sh
# bindings/python/check.sh - build the Python binding and run tests/python.
#  1. the venv $BUILD/venv with tests/requirements.txt, swig (and matplotlib) from PyPI;
#  2. a wheel built as users build it: `pip wheel` in an isolated build
#     environment whose SWIG is the swig wheel, compiler warnings as errors;
#     the wheel must contain the SWIG-generated cvmesh/capi.py; install, pytest;
#     (`pip wheel ./bindings/python` into a temporary directory, then kept in
#     $BUILD/python/dist); the wheel must carry LICENSE and py.typed;
#  2b. an sdist (python -m build --sdist, into a temporary directory) must carry
#     LICENSE, README.md and the C sources, and `pip wheel` of it must build;
#  3. when Debian's SWIG is there ($SYSTEM_SWIG, default /usr/bin/swig, 4.1):
#     rebuild with it, install, pytest again.
# Usage: sh bindings/python/check.sh [--build-only]   (--build-only: step 1-2, no tests)
# Environment: CVM_BUILD or BUILD (build directory, default build, relative to the top), PYTHON (python3),
#   SYSTEM_SWIG, PYTEST_ARGS.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${CVM_BUILD:-${BUILD:-build}}
case $build in /*) ;; *) build=$root/$build ;; esac
venv=$build/venv
dist=$build/python/dist
PYTHON=${PYTHON:-python3}
SYSTEM_SWIG=${SYSTEM_SWIG:-/usr/bin/swig}
pipq="-q --disable-pip-version-check"

if [ ! -x "$venv/bin/python" ]; then
    echo "check-python: creating $venv"
    "$PYTHON" -m venv "$venv"
fi
py=$venv/bin/python
"$py" -m pip install $pipq -r "$root/tests/requirements.txt" swig "setuptools>=77" build
# optional: the tests of Mesh.plot() skip without it
"$py" -m pip install $pipq matplotlib || echo "check-python: matplotlib not installed; its tests will skip"

# A fresh build tree per SWIG, so no object of an earlier build is reused.
build_wheel() {  # build_wheel TAG DIST [pip options]: build, check and install a wheel
    tag=$1
    out=$2
    shift 2
    rm -rf "$out" "$build/python/$tag"
    tmp=$(mktemp -d)
    (cd "$root" && CVMESH_WERROR=1 CVMESH_BUILD_DIR=$build/python/$tag \
        "$py" -m pip wheel $pipq --no-deps -w "$tmp" "$@" ./bindings/python)
    mkdir -p "$out"
    mv "$tmp"/cvmesh-*.whl "$out"/
    rm -rf "$tmp"
    whl=$(ls "$out"/cvmesh-*.whl)
    "$py" - "$whl" <<'PYEOF'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
need = ["cvmesh/__init__.py", "cvmesh/_errors.py", "cvmesh/capi.py", "cvmesh/py.typed"]
missing = [n for n in need if n not in names]
if not any(n.endswith(".dist-info/licenses/LICENSE") for n in names):
    missing.append("LICENSE")
if missing or not any(n.startswith("cvmesh/_capi") for n in names):
    sys.exit("check-python: wheel %s lacks %s" % (sys.argv[1], missing or "the extension"))
PYEOF
    "$py" -m pip install $pipq --force-reinstall --no-deps "$whl"
}

run_tests() {  # run_tests LABEL
    echo "check-python: tests/python ($1)"
    (cd "$root" && $limit "$venv/bin/pytest" -q -p no:cacheprovider ${PYTEST_ARGS:-} tests/python)
}
limit=""
command -v timeout >/dev/null 2>&1 && limit="timeout 1800"

echo "check-python: building with the swig wheel (isolated build)"
build_wheel swig-wheel "$dist"
[ "${1:-}" = --build-only ] && exit 0

echo "check-python: sdist carries LICENSE, README.md and the C sources; pip wheel builds it"
tmp=$(mktemp -d)
"$py" -m build -q --sdist --outdir "$tmp" "$here" >/dev/null
sdist=$(ls "$tmp"/cvmesh-*.tar.gz)
"$py" - "$sdist" <<'PYEOF'
import sys, tarfile
with tarfile.open(sys.argv[1]) as tar:
    members = {m.name.split("/", 1)[1]: m for m in tar.getmembers() if "/" in m.name}
    need = ["LICENSE", "README.md", "PKG-INFO", "setup.py", "cvmesh.i", "cvmesh_numpy.i",
            "cvmesh/py.typed", "csrc/include/cvmesh.h"]
    missing = [n for n in need if n not in members or not members[n].isfile()]
    if missing:
        sys.exit("check-python: sdist %s lacks %s (or has them as links)" % (sys.argv[1], missing))
    info = tar.extractfile(members["PKG-INFO"]).read().decode()
    lic = tar.extractfile(members["LICENSE"]).read().decode()
    if "License-File: LICENSE" not in info or "BSD 3-Clause" not in lic:
        sys.exit("check-python: sdist PKG-INFO does not name the BSD LICENSE file")
    if "Description-Content-Type: text/markdown" not in info:
        sys.exit("check-python: sdist PKG-INFO has no README description")
PYEOF
CVMESH_BUILD_DIR=$tmp/build "$py" -m pip wheel $pipq --no-deps -w "$tmp" "$sdist"
ls "$tmp"/cvmesh-*.whl >/dev/null
rm -rf "$tmp"
"$py" -c "import cvmesh; print('check-python: cvmesh', cvmesh.version(), 'from', cvmesh.__file__)"
run_tests "swig wheel $("$venv/bin/swig" -version | awk '/Version/ { print $3 }')"

if [ -x "$SYSTEM_SWIG" ]; then
    echo "check-python: building with $SYSTEM_SWIG"
    CVMESH_SWIG=$SYSTEM_SWIG build_wheel system-swig "$build/python/dist-system-swig" \
        --no-build-isolation
    run_tests "$SYSTEM_SWIG $("$SYSTEM_SWIG" -version | awk '/Version/ { print $3 }')"
    # leave the swig-wheel build installed, as users get it
    "$py" -m pip install $pipq --force-reinstall --no-deps "$dist"/cvmesh-*.whl
else
    echo "check-python: $SYSTEM_SWIG not found; skipped the build with the system SWIG"
fi
