#!/bin/sh
# Install the Debian 12 packages cvmesh's build and tests need, only those
# dpkg says are missing (the X11/GL libraries: the gmsh wheel of the test venv
# loads them). As root: non-interactive apt-get; otherwise print the line.
set -e
PKGS="build-essential pkg-config check libsubunit-dev liblbfgs-dev clang libomp-dev libclang-rt-14-dev gfortran swig python3-venv zlib1g-dev librsvg2-bin libtet1.5-dev\
      libglu1-mesa libgl1 libxcursor1 libxft2 libxinerama1 libxrender1"
missing=""
for p in $PKGS; do
    dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "deps: installing$missing"
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing >/dev/null
else
    echo "deps: missing packages; run as root:"
    echo "  sudo apt-get install -y --no-install-recommends$missing"
    exit 1
fi
