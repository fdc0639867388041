#!/usr/bin/env python3
"""Delaunay / CDT benchmark: cvmesh side by side with Triangle (PyPI `triangle`)
and scipy's qhull, on the same points, in the same run, on one core.

Prints one row per case: n, medians of 5 runs, time ratio cvmesh/Triangle and
cvmesh/qhull, triangles, and peak memory per triangle (cvmesh: its own heap
through a counting allocator; Triangle: growth of the peak RSS (VmHWM, reset
first) of a fresh subprocess, which also counts its output arrays).
"""
import json, os, resource, subprocess, sys, tempfile, time
import numpy as np

from benchlib import read_poly

BUILD, DOMAINS = sys.argv[1], sys.argv[2]
SIZE = int(os.environ.get("CVM_BENCH_N", "1000000"))
REPS = int(os.environ.get("CVM_BENCH_REPS", "5"))
BIN = os.path.join(BUILD, "bench", "bench_delaunay")


def cases(n):
    rng = np.random.default_rng(12345)
    yield "uniform", rng.random((n, 2))
    k = int(round(n ** 0.5))
    g = np.stack(np.meshgrid(np.arange(k, dtype=float), np.arange(k, dtype=float)), -1).reshape(-1, 2)
    yield "lattice_perturbed_1e-9", g + 1e-9 * (rng.random(g.shape) - 0.5)
    yield "lattice_exact", g


def median_time(fn, reps):
    ts = []
    out = None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t0)
    ts.sort()
    return ts[len(ts) // 2], out


def triangle_peak_per_tri(path, switches):
    code = r'''
import resource, sys, numpy as np, triangle
a = {}
%s
def hwm():
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1])
# ru_maxrss survives fork+exec on Linux, so reset the high-water mark instead
open("/proc/self/clear_refs", "w").write("5")
base = hwm()
t = triangle.triangulate(a, %r)
peak = hwm()
print((peak - base) * 1024.0 / max(1, len(t["triangles"])))
''' % (("a['vertices'] = np.fromfile(%r).reshape(-1, 2)" % path) if path.endswith(".bin")
       else ("import runpy\nexec(open(%r).read())" % (path + ".py")), switches)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    try:
        return float(r.stdout.strip())
    except ValueError:
        return float("nan")


def run_cvm(kind, path):
    r = subprocess.run([BIN, kind, path, str(REPS)], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("cvmesh bench failed on %s: %s %s" % (path, r.stdout, r.stderr))
    return json.loads(r.stdout)


def main():
    import triangle
    from scipy.spatial import Delaunay
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    tmp = tempfile.mkdtemp()
    print("# cvmesh Delaunay benchmark: medians of %d runs, one core; t_ratio < 1 means cvmesh is faster" % REPS)
    print("# cpu: %s" % next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?"))
    hdr = "%-24s %9s %9s %9s %9s %8s %8s %10s %9s %9s" % (
        "case", "n", "t_cvm", "t_tri", "t_qhull", "ratio_tri", "ratio_qh", "triangles", "B/tri_cvm", "B/tri_tri")
    print(hdr)
    for name, pts in cases(SIZE):
        path = os.path.join(tmp, name + ".bin")
        pts.astype("<f8").tofile(path)
        c = run_cvm("points", path)
        t_tri, tt = median_time(lambda: triangle.triangulate({"vertices": pts}, "Q"), REPS)
        t_qh, _ = median_time(lambda: Delaunay(pts), max(1, REPS // 2 + 1))
        mem_tri = triangle_peak_per_tri(path, "Q")
        print("%-24s %9d %9.3f %9.3f %9.3f %8.2f %8.2f %10d %9.1f %9.1f" % (
            name, len(pts), c["median_s"], t_tri, t_qh, c["median_s"] / t_tri, c["median_s"] / t_qh,
            c["triangles"], c["peak_bytes"] / max(1, c["triangles"]), mem_tri))
        sys.stdout.flush()
    for poly in sorted(os.listdir(DOMAINS)):
        if not poly.endswith(".poly"):
            continue
        path = os.path.join(DOMAINS, poly)
        c = run_cvm("poly", path)
        P, S, H = read_poly(path)
        a = {"vertices": P, "segments": S}
        if len(H):
            a["holes"] = H
        t_tri, tt = median_time(lambda: triangle.triangulate(a, "pQ"), REPS)
        print("%-24s %9d %9.5f %9.5f %9s %8.2f %8s %10d %9.1f %9s" % (
            "cdt_" + poly[:-5], len(P), c["median_s"], t_tri, "-", c["median_s"] / t_tri, "-",
            c["triangles"], c["peak_bytes"] / max(1, c["triangles"]), "-"))


if __name__ == "__main__":
    main()
