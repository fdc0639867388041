#!/usr/bin/env python3
"""3D Delaunay benchmark: cvmesh's engine (lib/delaunay3) side by side with
TetGen 1.5 (linked directly, tests/bench/bench_tetgen3.cxx) and scipy's qhull,
on the same points, in the same run, on one core.

Rows: uniform random points in the unit cube (1e5 and CVM_BENCH3_N, default
1e6), and an exact and a 1e-9-perturbed BCC lattice of CVM_BENCH3_BCC^3 cells
(default 40: about 1.3e5 points); then the large rows, one run each
(CVM_BENCH3_BIG=0 leaves them out): 1e7 uniform points and the exact and
perturbed 100^3 lattices (about 2e6 points).
Gmsh (the gmsh wheel from PyPI) runs HXT (Marot, Pellerin and Remacle) two ways,
with General.NumThreads 1 and 2:
- wall_g1/wall_g2: gmsh.algorithm.tetrahedralize, Gmsh's API call for the
  tetrahedralisation of a point set (it calls HXT's hxtDelaunaySteadyVertices,
  as Gmsh's log line "Tetrahedrizing N nodes" shows, then makes one Gmsh object
  per tetrahedron), up to CVM_BENCH3_GMSH_MAX points (default 2e6): wall
  seconds of the call in a child process, the conversion of its arguments
  included; gmsh1/gmsh2 = cvmesh's wall time over it. Its tetrahedra differ in
  number from the Delaunay tetrahedralisation's (it drops those on a bounding
  box it adds; a line says so).
- hxt1/hxt2: HXT's own timer of its Delaunay stage ("tEmptyMesh" in Gmsh's log
  at verbosity 99) when Gmsh meshes a box with Mesh.Algorithm3D = 10 and the
  points embedded in it (the 8 corners and 12 triangles of the box added): the
  bare insertion, without reading the points in or writing tetrahedra out,
  which is the strictest time to compare with; hx_r1/hx_r2 = cvmesh's build
  (cpu of "build", one core) over it. Up to CVM_BENCH3_HXT_MAX points (default
  1e6; setting the points up through the API takes about 25 s per 1e6).
CVM_BENCH_NO_GMSH=1 leaves it out.
Each timing is the median of CVM_BENCH3_REPS runs (default 3) of the build
and its output arrays; both wall and process CPU seconds are given, because on
a shared machine CPU time is the fairer of the two. ratio = cvmesh / TetGen
(< 1: cvmesh faster); build / b_ratio: cvmesh's build alone, without the
canonical sorted output (TetGen's time always includes its output arrays). qhull runs only up to CVM_BENCH3_QHULL_MAX points
(default 2e5; it took 93 s for 1e6 here). B/tet: cvmesh's peak heap through a
counting allocator (points, store, workspace and output); TetGen's growth of
the peak RSS during its run. Every cvmesh row passes cvm__tet3_check().
wall_2t / cpu_2t: cvmesh built with 2 threads (parallel insertion, the same
tetrahedra); speedup = wall_cvm / wall_2t (CVM_BENCH3_THREADS=0 leaves it out).
Weighted rows (regular tetrahedralisation; CVM_BENCH3_WEIGHTED=0 leaves them
out): 1e5 and CVM_BENCH3_N uniform points with weights of the order of the
squared spacing h^2 = n^(-2/3), h^2 (r - 0.3) / 10 with r uniform in [0, 1) and
one point in five ten times that (about 1.4 % of the points hidden, as in
tests/unit/delaunay3/test_par3.c), cvmesh on 1 and 2 threads (the same bytes);
no peer computes a weighted 3D triangulation here (CGAL is not installed), so
their columns are -.
"""
import json, os, subprocess, sys, tempfile, time
import numpy as np

BUILD = sys.argv[1]
N = int(float(os.environ.get("CVM_BENCH3_N", "1e6")))
BCC = int(os.environ.get("CVM_BENCH3_BCC", "40"))
REPS = int(os.environ.get("CVM_BENCH3_REPS", "3"))
QHULL_MAX = int(float(os.environ.get("CVM_BENCH3_QHULL_MAX", "2e5")))
BIG = os.environ.get("CVM_BENCH3_BIG", "1") != "0"
GMSH_MAX = int(float(os.environ.get("CVM_BENCH3_GMSH_MAX", "2e6")))
HXT_MAX = int(float(os.environ.get("CVM_BENCH3_HXT_MAX", "1e6")))
NO_GMSH = os.environ.get("CVM_BENCH_NO_GMSH", "0") == "1"
THREADS2 = os.environ.get("CVM_BENCH3_THREADS", "1") != "0"
WEIGHTED = os.environ.get("CVM_BENCH3_WEIGHTED", "1") != "0"
CVM = os.path.join(BUILD, "bench", "bench_delaunay3")
TETGEN = os.path.join(BUILD, "bench", "bench_tetgen3")


def bcc(k):
    r = np.arange(k, dtype=float)
    c = np.stack(np.meshgrid(r, r, r, indexing="ij"), -1).reshape(-1, 3) * 2.0
    rc = np.arange(k - 1, dtype=float)
    m = np.stack(np.meshgrid(rc, rc, rc, indexing="ij"), -1).reshape(-1, 3) * 2.0 + 1.0
    return np.concatenate([c, m])


def cases():
    rng = np.random.default_rng(12345)
    yield "uniform", rng.random((100000, 3)), REPS
    if N != 100000:
        yield "uniform", rng.random((N, 3)), REPS
    lat = bcc(BCC)
    yield "bcc_exact_%d^3" % BCC, lat, REPS
    yield "bcc_perturbed_1e-9", lat + 1e-9 * (rng.random(lat.shape) - 0.5), REPS
    if BIG:
        yield "uniform", rng.random((10000000, 3)), 1
        lat = bcc(100)
        yield "bcc_exact_100^3", lat, 1
        yield "bcc_perturbed_1e-9", lat + 1e-9 * (rng.random(lat.shape) - 0.5), 1


def weighted_cases():
    rng = np.random.default_rng(54321)
    for n in sorted({100000, N}):
        pts = rng.random((n, 3))
        r = rng.random(n)
        w = n ** (-2.0 / 3.0) * (r - 0.3) * np.where(np.arange(n) % 5 == 0, 1.0, 0.1)
        yield "weighted", pts, w, REPS


def run(binary, path, reps, *extra):
    r = subprocess.run([binary, path, str(reps)] + [str(x) for x in extra],
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("%s failed on %s: %s %s" % (binary, path, r.stdout, r.stderr))
    return json.loads(r.stdout)


def gmsh_time(pts, threads):
    """Wall seconds and tetrahedra of gmsh.algorithm.tetrahedralize, in a child
    process (Gmsh keeps its memory until finalize)."""
    code = ("import sys, time, numpy as np, gmsh\n"
            "p = np.fromfile(sys.argv[1]).reshape(-1, 3).ravel()\n"
            "gmsh.initialize(['-noenv'])\n"
            "gmsh.option.setNumber('General.Terminal', 0)\n"
            "gmsh.option.setNumber('General.NumThreads', %d)\n"
            "t0 = time.perf_counter()\n"
            "tets, _ = gmsh.algorithm.tetrahedralize(p)\n"
            "print(time.perf_counter() - t0, len(tets) // 4)\n"
            "gmsh.finalize()\n" % threads)
    r = subprocess.run([sys.executable, "-c", code, pts], capture_output=True, text=True)
    if r.returncode != 0:
        return None
    w, n = r.stdout.split()[-2:]
    return float(w), int(n)


def hxt_core_time(pts, threads):
    """HXT's own wall seconds for the Delaunay tetrahedralisation of the points
    embedded in a box (Gmsh's tEmptyMesh timer), in a child process."""
    code = ("import sys, numpy as np, gmsh\n"
            "p = np.fromfile(sys.argv[1]).reshape(-1, 3)\n"
            "gmsh.initialize(['-noenv'])\n"
            "gmsh.option.setNumber('General.Terminal', 1)\n"
            "gmsh.option.setNumber('General.Verbosity', 99)\n"
            "gmsh.option.setNumber('General.NumThreads', %d)\n"
            "gmsh.option.setNumber('Mesh.MaxNumThreads3D', %d)\n"
            "gmsh.option.setNumber('Mesh.Algorithm3D', 10)\n"
            "gmsh.option.setNumber('Mesh.Optimize', 0)\n"
            "lo = p.min(0); hi = p.max(0); e = 1e-3 * (hi - lo).max()\n"
            "big = 10 * (hi - lo).max()\n"
            "for k in ('Mesh.MeshSizeMin', 'Mesh.MeshSizeMax'): gmsh.option.setNumber(k, big)\n"
            "gmsh.option.setNumber('Mesh.MeshSizeFromPoints', 0)\n"
            "gmsh.option.setNumber('Mesh.MeshSizeExtendFromBoundary', 0)\n"
            "gmsh.model.add('b')\n"
            "b = gmsh.model.occ.addBox(*(lo - e), *(hi - lo + 2 * e))\n"
            "gmsh.model.occ.synchronize()\n"
            "tags = []\n"
            "for i in range(len(p)):\n"
            "    t = gmsh.model.addDiscreteEntity(0, 100 + i)\n"
            "    gmsh.model.mesh.addNodes(0, t, [], p[i].tolist())\n"
            "    tags.append(t)\n"
            "gmsh.model.mesh.embed(0, tags, 3, b)\n"
            "gmsh.model.mesh.generate(3)\n"
            "gmsh.finalize()\n" % (threads, threads))
    r = subprocess.run([sys.executable, "-c", code, pts], capture_output=True, text=True)
    for line in (r.stdout + r.stderr).splitlines():
        if "tEmptyMesh" in line:
            return float(line.split("=")[-1])
    return None


def have_gmsh():
    if NO_GMSH:
        return False
    r = subprocess.run([sys.executable, "-c", "import gmsh"], capture_output=True)
    return r.returncode == 0


def qhull_time(pts):
    from scipy.spatial import Delaunay
    best = []
    for _ in range(max(1, min(REPS, 3))):
        t0 = time.perf_counter()
        c0 = time.process_time()
        d = Delaunay(pts)
        best.append((time.process_time() - c0, time.perf_counter() - t0, len(d.simplices)))
    best.sort()
    return best[len(best) // 2]


def main():
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    have_tetgen = os.path.exists(TETGEN)
    use_gmsh = have_gmsh()
    tmp = tempfile.mkdtemp()
    print("# cvmesh 3D Delaunay benchmark: medians of %d runs, one core; ratio = cvmesh / TetGen"
          " (< 1: cvmesh faster)" % REPS)
    print("# cpu: %s" % next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                              if l.startswith("model name")), "?"))
    print("# load average at start: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))
    if not have_tetgen:
        print("# TetGen driver not built (no /usr/include/tetgen.h or no C++ compiler): its columns are -")
    if not use_gmsh:
        print("# gmsh not importable (or CVM_BENCH_NO_GMSH=1): its columns are -")
    print("%-20s %8s %4s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %9s %9s %7s %7s" % (
        "case", "n", "reps", "cpu_cvm", "cpu_tg", "ratio", "build", "b_ratio", "wall_cvm",
        "wall_tg", "wall_2t", "cpu_2t", "speedup", "wall_g1", "gmsh1", "wall_g2", "gmsh2",
        "hxt1", "hx_r1", "hxt2", "hx_r2", "cpu_qh", "tets_cvm", "tets_tg", "B/t_cvm", "B/t_tg"))
    for name, pts, reps in cases():
        pts = np.ascontiguousarray(pts, dtype=np.float64)
        path = os.path.join(tmp, "pts.bin")
        pts.tofile(path)
        c = run(CVM, path, reps)
        t = run(TETGEN, path, reps) if have_tetgen else None
        c2 = run(CVM, path, reps, 2) if THREADS2 else None
        if c2 and (c2["tets"] != c["tets"] or c2.get("digest") != c.get("digest")):
            raise SystemExit("2 threads made %d tetrahedra (digest %s), 1 thread %d (%s)"
                             % (c2["tets"], c2.get("digest"), c["tets"], c.get("digest")))
        g1 = gmsh_time(path, 1) if use_gmsh and len(pts) <= GMSH_MAX else None
        g2 = gmsh_time(path, 2) if use_gmsh and len(pts) <= GMSH_MAX else None
        h1 = hxt_core_time(path, 1) if use_gmsh and len(pts) <= HXT_MAX else None
        h2 = hxt_core_time(path, 2) if use_gmsh and len(pts) <= HXT_MAX else None
        q = qhull_time(pts) if len(pts) <= QHULL_MAX else None
        print_row(name, pts, reps, c, t, c2, g1, g2, h1, h2, q)
        if g1 and g1[1] != c["tets"]:
            print("#   gmsh made %d tetrahedra (cvmesh %d): Gmsh's result is not the same "
                  "tetrahedralisation" % (g1[1], c["tets"]))
    if not WEIGHTED:
        return
    for name, pts, w, reps in weighted_cases():
        path = os.path.join(tmp, "pts.bin")
        wpath = os.path.join(tmp, "w.bin")
        np.ascontiguousarray(pts, dtype=np.float64).tofile(path)
        np.ascontiguousarray(w, dtype=np.float64).tofile(wpath)
        c = run(CVM, path, reps, 1, wpath)
        c2 = run(CVM, path, reps, 2, wpath) if THREADS2 else None
        if c2 and (c2["tets"] != c["tets"] or c2.get("digest") != c.get("digest")):
            raise SystemExit("weighted: 2 threads made %d tetrahedra (digest %s), 1 thread %d (%s)"
                             % (c2["tets"], c2.get("digest"), c["tets"], c.get("digest")))
        print_row(name, pts, reps, c, None, c2, None, None, None, None, None)
        print("#   weighted %d: %d points hidden (empty power cell)" % (len(pts), c["redundant"]))


def print_row(name, pts, reps, c, t, c2, g1, g2, h1, h2, q):
    fmt = lambda x, f="%8.3f": (f % x) if x is not None else "%8s" % "-"
    print("%-20s %8d %4d %s %s %s %s %s %s %s %s %s %s %s %s %s %s %s %s %s %s %s %9d %9s %7.0f %7s" % (
        name, len(pts), reps, fmt(c["cpu"]), fmt(t and t["cpu"]),
        fmt(t and c["cpu"] / t["cpu"]), fmt(c["cpu_build"]),
        fmt(t and c["cpu_build"] / t["cpu"]), fmt(c["wall"]), fmt(t and t["wall"]),
        fmt(c2 and c2["wall"]), fmt(c2 and c2["cpu"]), fmt(c2 and c["wall"] / c2["wall"]),
        fmt(g1 and g1[0]), fmt(g1 and c["wall"] / g1[0]),
        fmt(g2 and g2[0]), fmt(g2 and c["wall"] / g2[0]),
        fmt(h1), fmt(h1 and c["cpu_build"] / h1), fmt(h2), fmt(h2 and c["cpu_build"] / h2),
        fmt(q and q[0]), c["tets"],
        t["tets"] if t else "-", c["peak_bytes"] / c["tets"],
        ("%7.0f" % (t["peak_bytes"] / t["tets"])) if t else "-"), flush=True)


if __name__ == "__main__":
    main()
