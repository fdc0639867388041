#!/usr/bin/env python3
"""Refinement benchmark: cvmesh (Delaunay refinement, frontal-Delaunay and AFLR) side by
side with Triangle (PyPI `triangle`, switches pq30a<A>) on the example domains (examples/data)
at a uniform size h, in the same run, on one core.

Triangle gets the area bound A = sqrt(3)/4 h^2 (an equilateral triangle of edge
h). Gmsh (PyPI `gmsh`, geo kernel, the .poly loops as curve loops, holes as
inner loops) gets Mesh.MeshSizeMin = Max = h, no size from points, curvature or
boundary, one thread, Mesh.Algorithm 5 (gmsh-del, Delaunay) and 6 (gmsh-front,
Frontal-Delaunay); only gmsh.model.mesh.generate(2) is timed. Every mesh is
measured here by the same numpy code: vertices, triangles, time (median of REPS
runs, 11 unless CVM_BENCH_REPS says otherwise: a run of the annulus takes about
10 ms, and medians of 5 moved by up to 8% between bench runs, of triangulate + refine, each cvmesh process after one untimed warm-up run, as
Triangle and Gmsh run warm in this Python process; Triangle: triangulate(); Gmsh:
generate(2)), min
angle, % of angles in [55, 65] degrees, % obtuse triangles (an angle > 90), % of
interior vertices (on no boundary edge) of degree 6, and mean edge / h.
After each case a "tri-mv" row runs Triangle again with its area bound scaled so
that its vertex count matches cvm-front's (Triangle's area bound gives edges of
about 0.82 h). The "annulus-g" case uses the graded size h(r) = 0.4 + (r - 1)/2.5
of the thesis: cvmesh through a sizing callback, Gmsh through its size callback,
Triangle through repeated refinement (-r) with per-triangle area bounds from the
size at each centroid until none is exceeded (all passes timed); edge/h is then
the mean of edge length / h(midpoint). Its "-rs" rows run cvmesh with
CVM_OPT_KEEP_SEGMENT_VERTICES = 0: the input circles (spacing 0.1 and 0.2) are
re-discretised with the size before refining.
A "same bound" line per uniform case compares vertex counts at one size bound, the
one Delaunay refinement reads its size as (every circumradius <= h): the frontal and
AFLR refiners read h as an edge length, so they are run at the largest h_f whose mesh
still meets that bound (bisection).
A last row times Delaunay refinement of the square to about 1e6 triangles
against Triangle at a matched triangle count (the speed target of issue 4).

usage: bench_refine.py BUILD DOMAINS   (make bench calls it through run.sh)
"""
import os, subprocess, sys, tempfile, time
import numpy as np

from benchlib import build_driver, read_poly

BUILD, DOMAINS = sys.argv[1], sys.argv[2]
REPS = int(os.environ.get("CVM_BENCH_REPS", "11"))
METHODS = [int(x) for x in os.environ.get("CVM_BENCH_SMOOTH_METHODS", "").split(",") if x]
CASES = [("square", 0.02), ("channel", 0.02), ("annulus", 0.1), ("cylinder", 0.2),
         ("naca0012", 0.2), ("annulus-g", -1.0)]


def size_at(h, xy):
    """Target size at points xy (n, 2): uniform h, or the graded annulus (h < 0)."""
    if h > 0:
        return np.full(len(xy), h)
    return 0.4 + (np.hypot(xy[:, 0], xy[:, 1]) - 1) / 2.5
DRIVER = os.path.join(BUILD, "bench", "bench_refine")


def quality(xy, tri, h):
    p = xy[tri]                                   # (nt, 3, 2)
    e = np.roll(p, -1, axis=1) - p                # edge k from corner k to k+1
    ang = []
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        w = p[:, (k + 2) % 3] - p[:, k]
        cross = np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        ang.append(np.degrees(np.arctan2(cross, (u * w).sum(1))))
    ang = np.stack(ang, 1)
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), 1)
    uniq, cnt = np.unique(edges, axis=0, return_counts=True)
    boundary = np.unique(uniq[cnt == 1])
    deg = np.bincount(uniq.ravel(), minlength=len(xy))
    used = np.zeros(len(xy), bool)
    used[tri.ravel()] = True
    interior = used.copy()
    interior[boundary] = False
    lens = np.linalg.norm(xy[uniq[:, 0]] - xy[uniq[:, 1]], axis=1)
    lens = lens / size_at(h, 0.5 * (xy[uniq[:, 0]] + xy[uniq[:, 1]]))  # edge / local size
    return dict(nv=int(used.sum()), nt=len(tri), minang=float(ang.min()),
                reg=100.0 * float(((ang >= 55) & (ang <= 65)).mean()),
                obt=100.0 * float((ang.max(1) > 90).mean()),
                deg6=100.0 * float((deg[interior] == 6).mean()) if interior.any() else 0.0,
                edge=float(lens.mean()))


def run_cvmesh(poly, h, algo, tmp, smooth_method=None, resample=False, reps=None):
    env = dict(os.environ)
    env.pop("CVM_BENCH_SMOOTH_METHOD", None)
    env.pop("CVM_BENCH_RESAMPLE", None)
    if smooth_method is not None:
        env["CVM_BENCH_SMOOTH_METHOD"] = str(smooth_method)
    if resample:
        env["CVM_BENCH_RESAMPLE"] = "1"
    out = subprocess.run([DRIVER, poly, str(h), str(algo), str(reps or REPS), os.path.join(tmp, "m")],
                         capture_output=True, text=True, env=env)
    if out.returncode:
        raise SystemExit("bench_refine: cvmesh failed on %s: %s" % (poly, out.stderr))
    t = float(out.stdout.split()[0])
    xy = np.fromfile(os.path.join(tmp, "m.xy")).reshape(-1, 2)
    tri = np.fromfile(os.path.join(tmp, "m.tri"), dtype=np.int32).reshape(-1, 3)
    return t, xy, tri


def run_triangle(poly, h, area_scale=1.0, reps=None):
    """Triangle pq30a<A>, A = area_scale x sqrt(3)/4 h^2; for the graded annulus
    (h < 0), pq30 at the largest size then -rpq30a with per-triangle bounds from
    the size at each centroid until none is exceeded (at most 12 passes)."""
    import triangle
    xy, segs, holes = read_poly(poly)
    a = dict(vertices=xy, segments=segs)
    if len(holes):
        a["holes"] = holes
    ts, t = [], None
    for _ in range(reps or REPS):
        t0 = time.perf_counter()
        if h > 0:
            t = triangle.triangulate(a, "pq30a%.12f" % (area_scale * np.sqrt(3) / 4 * h * h))
        else:
            t = triangle.triangulate(a, "pq30a%.12f" % (np.sqrt(3) / 4 * 1.6 ** 2))
            for _ in range(12):
                p = t["vertices"][t["triangles"]]
                u, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
                area = 0.5 * np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
                bound = np.sqrt(3) / 4 * size_at(h, p.mean(axis=1)) ** 2
                if (area <= bound).all():
                    break
                t = triangle.triangulate(dict(t, triangle_max_area=bound), "rpq30a")
        ts.append(time.perf_counter() - t0)
    ts.sort()
    return ts[len(ts) // 2], t["vertices"], t["triangles"]


def poly_loops(segs):
    """The closed loops of a .poly whose vertices all lie on two segments: each a
    list of (segment index, forward?) in walking order."""
    at = {}
    for k, (a, b) in enumerate(segs):
        at.setdefault(int(a), []).append(k)
        at.setdefault(int(b), []).append(k)
    if any(len(v) != 2 for v in at.values()):
        raise ValueError("segments do not form simple closed loops")
    seen, loops = set(), []
    for k0 in range(len(segs)):
        if k0 in seen:
            continue
        loop, k, v = [], k0, int(segs[k0][0])
        while k not in seen:
            seen.add(k)
            fwd = int(segs[k][0]) == v
            loop.append((k, fwd))
            v = int(segs[k][1]) if fwd else int(segs[k][0])
            k = at[v][0] if at[v][1] == k else at[v][1]
        loops.append(loop)
    return loops


def run_gmsh(poly, h, algo):
    """Gmsh (PyPI gmsh, geo kernel) at uniform size h; Mesh.Algorithm algo
    (5 Delaunay, 6 Frontal-Delaunay). Times gmsh.model.mesh.generate(2) only."""
    import gmsh
    xy, segs, holes = read_poly(poly)
    loops = poly_loops(segs)

    def area(loop):
        v = np.array([segs[k][0] if f else segs[k][1] for k, f in loop])
        x, y = xy[v, 0], xy[v, 1]
        return abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))) / 2
    loops.sort(key=area, reverse=True)            # outer boundary first, holes after
    if len(loops) - 1 != len(holes):
        raise ValueError("%d inner loops but %d holes" % (len(loops) - 1, len(holes)))
    gmsh.initialize(readConfigFiles=False)
    try:
        hmin, hmax = (h, h) if h > 0 else (0.4, 1.6)
        for opt, val in (("General.Terminal", 0), ("General.NumThreads", 1),
                         ("Mesh.Algorithm", algo), ("Mesh.MeshSizeMin", hmin),
                         ("Mesh.MeshSizeMax", hmax), ("Mesh.MeshSizeFromPoints", 0),
                         ("Mesh.MeshSizeFromCurvature", 0),
                         ("Mesh.MeshSizeExtendFromBoundary", 0)):
            gmsh.option.setNumber(opt, val)
        gmsh.model.add("bench")
        geo = gmsh.model.geo
        if h < 0:
            gmsh.model.mesh.setSizeCallback(
                lambda dim, tag, x, y, z, lc: 0.4 + (np.hypot(x, y) - 1) / 2.5)
        pt = [geo.addPoint(x, y, 0, abs(h)) for x, y in xy]
        ln = [geo.addLine(pt[a], pt[b]) for a, b in segs]
        cl = [geo.addCurveLoop([ln[k] if f else -ln[k] for k, f in loop]) for loop in loops]
        geo.addPlaneSurface(cl)
        geo.synchronize()
        ts = []
        for _ in range(REPS):
            gmsh.model.mesh.clear()
            t0 = time.perf_counter()
            gmsh.model.mesh.generate(2)
            ts.append(time.perf_counter() - t0)
        ts.sort()
        tags, coord, _ = gmsh.model.mesh.getNodes()
        _, enodes = gmsh.model.mesh.getElementsByType(2)
    finally:
        gmsh.finalize()
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    tri = index[np.asarray(enodes, dtype=np.int64)].reshape(-1, 3)
    return ts[len(ts) // 2], np.asarray(coord).reshape(-1, 3)[:, :2], tri


def run_1e6(domains, tmp):
    """The speed target of issue 4: Delaunay refinement of the unit square to
    about 1e6 triangles against Triangle at a matched triangle count (cvmesh
    h = 0.00115: circumradius <= h; Triangle pq30a with h = 0.0019), runs
    interleaved (cvmesh, Triangle, cvmesh, ...) so load on a shared machine
    hits both alike; medians of REPS."""
    import triangle
    poly = os.path.join(domains, "square.poly")
    xy, segs, _ = read_poly(poly)
    a = dict(vertices=xy, segments=segs)
    sw = "pq30a%.12f" % (np.sqrt(3) / 4 * 0.0019 ** 2)
    tc, tt = [], []
    for _ in range(REPS):
        out = subprocess.run([DRIVER, poly, "0.00115", "1", "1", os.path.join(tmp, "m")],
                             capture_output=True, text=True)
        if out.returncode:
            raise SystemExit("bench_refine: cvmesh failed on the 1e6 square: %s" % out.stderr)
        tc.append(float(out.stdout.split()[0]))
        t0 = time.perf_counter()
        t = triangle.triangulate(a, sw)
        tt.append(time.perf_counter() - t0)
    ntc = len(np.fromfile(os.path.join(tmp, "m.tri"), dtype=np.int32)) // 3
    tc.sort()
    tt.sort()
    c, r = tc[len(tc) // 2], tt[len(tt) // 2]
    print("# 1e6 square, Delaunay refinement, %d interleaved runs: cvm-del %d triangles %.3f s "
          "(%.3f us/tri), triangle %d triangles %.3f s (%.3f us/tri); time ratio cvm/triangle %.2f"
          % (REPS, ntc, c, 1e6 * c / ntc, len(t["triangles"]), r, 1e6 * r / len(t["triangles"]), c / r))


def max_circumradius(xy, tri):
    p = xy[tri]
    a = np.linalg.norm(p[:, 1] - p[:, 2], axis=1)
    b = np.linalg.norm(p[:, 0] - p[:, 2], axis=1)
    c = np.linalg.norm(p[:, 0] - p[:, 1], axis=1)
    u, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    area = 0.5 * np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
    return float((a * b * c / (4 * area)).max())


def same_bound(name, poly, h, nv_del, tmp):
    """Vertices each refiner needs to meet one size bound, the one Delaunay
    refinement reads its size as (every circumradius <= h): cvm-del at h, and
    frontal / AFLR at the largest size h_f in [h, 1.6 h] (bisection, 7 steps)
    whose mesh still has every circumradius <= h (at the same h they make edges
    of about h, circumradius about 0.58 h, so they over-resolve that bound)."""
    out = "# same bound %-9s h %-5g circumradius <= h: cvm-del %d vertices" % (name, h, nv_del)
    for algo, label in ((2, "cvm-front"), (3, "cvm-aflr")):
        lo, hi, best = h, 1.6 * h, None
        for _ in range(7):
            mid = 0.5 * (lo + hi)
            _, xy, tri = run_cvmesh(poly, mid, algo, tmp, reps=1)
            if max_circumradius(xy, tri) <= h:
                lo, best = mid, len(xy)
            else:
                hi = mid
        if best is None:
            _, xy, _ = run_cvmesh(poly, h, algo, tmp, reps=1)
            best = len(xy)
        out += "; %s %d (h_f %.3g h, %.2fx)" % (label, best, lo / h, best / nv_del)
    print(out)


def main():
    build_driver(BUILD, "bench_refine")
    print("# bench_refine: uniform size h; time = median of %d runs (triangulate + refine), one core; "
          "Triangle and the cvmesh refiners interleaved run by run" % REPS)
    print("%-9s %-5s %-9s %7s %7s %9s %8s %7s %6s %6s %6s %6s" %
          ("case", "h", "mesher", "verts", "tris", "time_s", "us/tri", "minang", "%55-65", "%obt",
           "%deg6", "edge/h"))
    gmsh_ok = not os.environ.get("CVM_BENCH_NO_GMSH")
    if gmsh_ok:
        try:
            import gmsh  # noqa: F401  (loads libgmsh: may fail on missing X11/GL libs)
        except (ImportError, OSError) as e:
            print("# Gmsh (pip gmsh) not usable (%s): skipped" % str(e).splitlines()[0])
            gmsh_ok = False
    else:
        print("# Gmsh skipped (its system libraries are missing; see run.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        for name, h in CASES:
            poly = os.path.join(DOMAINS, name.split("-")[0] + ".poly")
            rows = []
            # Triangle and the three cvmesh refiners run interleaved, one run each
            # per round, so that drift of the machine's speed hits all alike;
            # each time is the median over the rounds (the meshes are identical)
            runs = {}
            have_triangle = True
            for _ in range(REPS):
                if have_triangle:
                    try:
                        runs.setdefault("triangle", []).append(run_triangle(poly, h, reps=1))
                    except ImportError:
                        print("# Triangle (pip triangle) not installed: skipped")
                        have_triangle = False
                for algo, label in ((1, "cvm-del"), (2, "cvm-front"), (3, "cvm-aflr")):
                    runs.setdefault(label, []).append(run_cvmesh(poly, h, algo, tmp, reps=1))
            for label in ("triangle", "cvm-del", "cvm-front", "cvm-aflr"):
                if label in runs:
                    ts = sorted(r[0] for r in runs[label])
                    rows.append((label, ts[len(ts) // 2]) + tuple(runs[label][-1][1:]))
            if h < 0:
                # the thesis case: input polylines at 0.1/0.2 spacing against sizes
                # 0.4-1.6; -rs rows re-discretise them (CVM_OPT_KEEP_SEGMENT_VERTICES = 0)
                for algo, label in ((1, "cvm-del-rs"), (2, "cvm-front-rs"), (3, "cvm-aflr-rs")):
                    rows.append((label,) + run_cvmesh(poly, h, algo, tmp, resample=True))
            if rows[0][0] == "triangle" and h > 0:
                # Triangle again at cvm-front's vertex count (vertices ~ 1 / area bound)
                nv_tri = len(np.unique(np.asarray(rows[0][3]).ravel()))
                nv_front = len(np.unique(np.asarray(rows[2][3]).ravel()))
                rows.append(("tri-mv",) + run_triangle(poly, h, nv_tri / nv_front))
            # CVM_BENCH_SMOOTH_METHODS=1,2: extra frontal/AFLR rows (label -mN) with
            # CVM_OPT_SMOOTH_METHOD = N, in the same run (the 1e6 row is then skipped)
            for meth in METHODS:
                for algo, label in ((2, "cvm-front"), (3, "cvm-aflr")):
                    rows.append(("%s-m%d" % (label, meth),) + run_cvmesh(poly, h, algo, tmp, meth))
            if gmsh_ok:
                for algo, label in ((5, "gmsh-del"), (6, "gmsh-front")):
                    rows.append((label,) + run_gmsh(poly, h, algo))
            for label, t, xy, tri in rows:
                q = quality(np.asarray(xy), np.asarray(tri), h)
                print("%-9s %-5s %-12s %7d %7d %9.4f %8.3f %7.2f %6.2f %6.1f %6.1f %6.3f" %
                      (name, "%g" % h if h > 0 else "graded", label, q["nv"], q["nt"], t, 1e6 * t / q["nt"], q["minang"], q["reg"],
                       q["obt"], q["deg6"], q["edge"]))
            if h > 0:
                same_bound(name, poly, h, len(runs["cvm-del"][-1][1]), tmp)
            sys.stdout.flush()
        try:
            if not METHODS:
                run_1e6(DOMAINS, tmp)
        except ImportError:
            print("# Triangle (pip triangle) not installed: 1e6 square row skipped")


if __name__ == "__main__":
    main()
