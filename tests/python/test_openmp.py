"""The extension is built with OpenMP like the C library (Makefile OPENMP=1):
threads > 1 then really runs in parallel instead of being accepted silently."""

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest

import cvmesh
from cvmesh import capi

ROOT = Path(__file__).resolve().parents[2]
OMP_RUNTIMES = ("libgomp", "libomp", "libiomp")


def _linked_omp(path):
    """The OpenMP runtime ldd lists for the shared object at path, or None."""
    out = subprocess.run(["ldd", str(path)], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        name = line.strip().split(" ", 1)[0]
        if name.startswith(OMP_RUNTIMES):
            return name
    return None


def _c_library_has_openmp():
    """Whether the C library of this build links an OpenMP runtime: the
    libcvmesh.so of $CVM_BUILD (or $BUILD) when built, else whether the C
    compiler links an OpenMP program (what `make` with OPENMP=1 does)."""
    for var in ("CVM_BUILD", "BUILD"):
        if os.environ.get(var):
            lib = Path(os.environ[var])
            lib = (lib if lib.is_absolute() else ROOT / lib) / "lib" / "libcvmesh.so"
            if lib.exists():
                return _linked_omp(lib) is not None
    cc = shutil.which(os.environ.get("CC", "cc")) or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler to compare with")
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "p.c"
        src.write_text("#include <omp.h>\nint main(void) { return omp_get_max_threads() < 1; }\n")
        r = subprocess.run([cc, "-fopenmp", str(src), "-o", str(Path(tmp) / "p")],
                           capture_output=True)
        return r.returncode == 0


@pytest.mark.skipif(shutil.which("ldd") is None, reason="needs ldd")
def test_extension_links_the_openmp_runtime_when_the_c_library_does():
    ext = Path(capi._capi.__file__) if hasattr(capi, "_capi") else None
    if ext is None:
        import cvmesh._capi as ext_mod
        ext = Path(ext_mod.__file__)
    expect = _c_library_has_openmp()
    got = _linked_omp(ext)
    assert (got is not None) == expect, "extension %s links %s; the C library %s OpenMP" % (
        ext, got or "no OpenMP runtime", "has" if expect else "has no")


def test_threads_give_the_same_mesh_as_one_thread():
    # determinism across thread counts (STYLE.md section 7), now that the
    # threads are real
    pts = np.random.default_rng(7).random((400, 2))
    meshes = []
    for threads in (1, 2):
        mesh = cvmesh.Mesh.from_points(pts, seed=3, threads=threads)
        mesh.refine(min_angle=25, max_area=0.001)
        mesh.optimise_dual(dual_max_sweeps=3)
        meshes.append((mesh.points, mesh.triangles, mesh.weights))
    for a, b in zip(*meshes):
        assert np.array_equal(a, b)
