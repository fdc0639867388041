"""No leaks across many create/destroy cycles, on success and error paths."""

import gc
import math
import os
import resource
import sys
import tracemalloc

import numpy as np

import cvmesh
from cvmesh import Mesh, capi

CYCLES = 10_000


def rss_bytes():
    """Current resident set size (Linux /proc), else the peak from getrusage."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except OSError:
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        return peak if sys.platform == "darwin" else peak * 1024


def one_cycle(pts, segs, bad):
    mesh = Mesh.from_pslg(pts, segs)
    mesh.triangulate()
    mesh.insert_points([[0.5, 0.5], [0.25, 0.5]])
    mesh.points, mesh.triangles, mesh.edges, mesh.neighbors
    try:
        mesh.set_points(bad)             # error path: exception with message
    except cvmesh.InputError:
        pass
    try:
        mesh.set_option("seed", -1)
    except cvmesh.OptionError:
        pass
    mesh.close()
    m = capi.cvm_mesh_create()           # the raw API too, with callbacks kept alive by it
    capi.cvm_mesh_set_points(m, pts)
    capi.cvm_mesh_set_progress(m, lambda s, f: False, 100)
    capi.cvm_mesh_free(m)
    if hasattr(capi, "cvm_sizing_create"):
        s = capi.cvm_sizing_create()
        capi.cvm_sizing_set_callback(s, lambda x, y: 1.0)
        try:
            capi.cvm_sizing_set_uniform(s, -1.0)
        except cvmesh.ArgumentError:
            pass
        capi.cvm_sizing_free(s)


def test_no_growth_over_create_destroy_cycles():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.3, 0.6]], dtype=float)
    segs = np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.int32)
    bad = pts.copy()
    bad[2, 0] = math.nan
    for _ in range(500):                 # warm up caches and allocator pools
        one_cycle(pts, segs, bad)
    gc.collect()
    tracemalloc.start()
    rss0 = rss_bytes()
    snap0 = tracemalloc.take_snapshot()
    for _ in range(CYCLES):
        one_cycle(pts, segs, bad)
    gc.collect()
    snap1 = tracemalloc.take_snapshot()
    rss1 = rss_bytes()
    tracemalloc.stop()
    py_growth = sum(s.size_diff for s in snap1.compare_to(snap0, "filename"))
    # A leak of one small object per cycle would be >= 10^4 * 32 bytes.
    assert py_growth < 64 * 1024, "Python heap grew by %d bytes" % py_growth
    # A leaked handle or numpy array per cycle would be several MB.
    assert rss1 - rss0 < 4 * 1024 * 1024, "RSS grew by %d bytes" % (rss1 - rss0)
