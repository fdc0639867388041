#!/usr/bin/env python3
"""Dual (power diagram) optimisation benchmark: cvmesh's cvm_mesh_optimise_dual on the
example domains after Delaunay refinement and after frontal refinement, with both local
solvers (pattern search and Modified Cuckoo Search), side by side in the same run with
Triangle's raw mesh (PyPI `triangle`, switches pq30a<A>, A = sqrt(3)/4 h^2), that mesh after
20 iterations of Lloyd smoothing (written here: every vertex on no segment moves to the
centroid of its Voronoi cell, then Triangle re-triangulates, boundary fixed), and that
Triangle mesh optimised by cvmesh. One core.

Per row: triangles, % of triangles whose dual (power) vertex lies outside them, before and
after; after optimisation % non-compliant (outside and not merged; all / boundary
triangles) and % merged; smallest angle; smallest dual edge over its primal edge (interior
edges); the explicit time-step proxy min(primal, dual edge) and its ratio to Triangle's
raw mesh; time of refinement and of optimisation. The "cvm-front-bg" rows refine with the
uniform size capped by the boundary's own spacing graded at slope 0.3
(cvm_sizing_set_boundary_grading), which carries finely spaced walls into the interior.
cvmesh rows are measured by the C driver (bench_dual.c, public API; every mesh passes
cvm_mesh_check); Triangle and Lloyd rows by the numpy code below (zero weights: the dual
vertex is the circumcentre).

usage: bench_dual.py BUILD DOMAINS   (make bench calls it through run.sh)
"""
import os, subprocess, sys, tempfile, time
import numpy as np

from benchlib import build_driver, read_poly

BUILD, DOMAINS = sys.argv[1], sys.argv[2]
CASES = [("square", 0.02), ("channel", 0.02), ("annulus", 0.1), ("cylinder", 0.2),
         ("naca0012", 0.2)]
LARGE = [("square", 0.006)]   # about 1e5 triangles (Triangle's mesh)
# about 1e5 triangles from each cvmesh refiner: Delaunay refinement (circumradius <= h)
# needs a smaller h than the frontal refiner (edges about h) for the same count
LARGE_CVM = [("square", 1, 0.0037, "cvm-del"), ("square", 2, 0.0048, "cvm-front")]
DRIVER = os.path.join(BUILD, "bench", "bench_dual")
LLOYD_ITERS = 20
BOUNDARY_GRADING = 0.3  # cvm_sizing_set_boundary_grading slope of the "cvm-front-bg" rows


def write_poly(path, xy, segs, holes):
    with open(path, "w") as f:
        f.write("%d 2 0 0\n" % len(xy))
        for i, (x, y) in enumerate(xy):
            f.write("%d %.17g %.17g\n" % (i, x, y))
        f.write("%d 0\n" % len(segs))
        for i, (a, b) in enumerate(segs):
            f.write("%d %d %d\n" % (i, a, b))
        f.write("%d\n" % len(holes))
        for i, (x, y) in enumerate(holes):
            f.write("%d %.17g %.17g\n" % (i, x, y))


def circumcentres(p):
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    bx, by, cx, cy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1], c[:, 0] - a[:, 0], c[:, 1] - a[:, 1]
    d = 2 * (bx * cy - by * cx)
    bb, cc = bx * bx + by * by, cx * cx + cy * cy
    return np.stack([a[:, 0] + (cy * bb - by * cc) / d, a[:, 1] + (bx * cc - cx * bb) / d], 1)


def edges_of(tri):
    """Unique edges (sorted pairs), and per triangle-edge k (opposite corner k) its edge id."""
    e = np.concatenate([tri[:, [1, 2]], tri[:, [2, 0]], tri[:, [0, 1]]])
    e.sort(axis=1)
    uniq, inv, cnt = np.unique(e, axis=0, return_inverse=True, return_counts=True)
    return uniq, inv.reshape(3, -1).T, cnt


def measure(xy, tri):
    """Zero-weight dual measures of a mesh, in numpy (independent of cvmesh)."""
    p = xy[tri]
    ang = []
    obtuse = np.zeros(len(tri), bool)
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        dot = (u * v).sum(1)
        obtuse |= dot < 0
        ang.append(np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]), dot)))
    uniq, te, cnt = edges_of(tri)
    bnd_v = np.zeros(len(xy), bool)
    bnd_v[uniq[cnt == 1].ravel()] = True
    bnd_t = bnd_v[tri].any(1)
    C = circumcentres(p)
    # interior edges: the two triangles of each edge with count 2
    flat = te.T.ravel()                       # edge id of (k, t) for k-major order
    tids = np.tile(np.arange(len(tri)), 3)
    order = np.argsort(flat, kind="stable")
    fe, ft = flat[order], tids[order]
    two = np.nonzero(fe[1:] == fe[:-1])[0]
    e_int = fe[two]
    dual = np.linalg.norm(C[ft[two]] - C[ft[two + 1]], axis=1)
    prim = np.linalg.norm(xy[uniq[e_int, 0]] - xy[uniq[e_int, 1]], axis=1)
    return dict(nt=len(tri), out=100.0 * obtuse.mean(),
                outb=100.0 * obtuse[bnd_t].mean() if bnd_t.any() else 0.0,
                minang=float(np.min(ang)), ratio=float((dual / prim).min()),
                step=float(np.minimum(dual, prim).min()))


def run_triangle(xy, segs, holes, h):
    import triangle
    a = dict(vertices=xy, segments=segs)
    if len(holes):
        a["holes"] = holes
    t0 = time.perf_counter()
    t = triangle.triangulate(a, "pq30a%.12f" % (np.sqrt(3) / 4 * h * h))
    return time.perf_counter() - t0, t


def lloyd(t, holes, iters):
    """Lloyd smoothing: vertices on no segment move to the centroid of their Voronoi cell
    (pieces (v, M_va, C_t) and (v, C_t, M_vb) of each incident triangle t, signed), then
    Triangle re-triangulates the points with the segments (constrained Delaunay)."""
    import triangle
    xy, tri, segs = np.array(t["vertices"]), np.array(t["triangles"]), np.array(t["segments"])
    fixed = np.zeros(len(xy), bool)
    fixed[segs.ravel()] = True
    for _ in range(iters):
        p = xy[tri]
        C = circumcentres(p)
        A = np.zeros(len(xy))
        M = np.zeros((len(xy), 2))
        for k in range(3):
            v, a, b = tri[:, k], tri[:, (k + 1) % 3], tri[:, (k + 2) % 3]
            pv = xy[v]
            for q, s in ((xy[a], 1.0), (xy[b], -1.0)):
                mid = 0.5 * (pv + q)
                # triangle (pv, mid, C) for the edge to a, (pv, C, mid) for the edge to b
                cr = s * ((mid[:, 0] - pv[:, 0]) * (C[:, 1] - pv[:, 1]) -
                          (mid[:, 1] - pv[:, 1]) * (C[:, 0] - pv[:, 0])) / 2
                cen = (pv + mid + C) / 3
                np.add.at(A, v, cr)
                np.add.at(M, v, cen * cr[:, None])
        move = ~fixed & (A > 0)
        xy[move] = M[move] / A[move, None]
        a = dict(vertices=xy, segments=segs)
        if len(holes):
            a["holes"] = holes
        r = triangle.triangulate(a, "p")
        xy, tri = np.array(r["vertices"]), np.array(r["triangles"])
        if len(xy) != len(fixed):
            fixed = np.concatenate([fixed, np.ones(len(xy) - len(fixed), bool)])
        segs = np.array(r["segments"])
    return xy, tri


def driver(poly, h, algo, solver, grade=None):
    extra = ["grade=%g" % grade] if grade else []
    out = subprocess.run([DRIVER, poly, str(h), str(algo), str(solver)] + extra, capture_output=True,
                         text=True)
    if out.returncode:
        raise RuntimeError("bench_dual %s %s %s %s: %s" % (poly, h, algo, solver, out.stderr))
    return dict(kv.split("=", 1) for kv in out.stdout.split())


HEAD = ("%-9s %-18s %7s %7s %7s %7s %7s %7s %6s %6s %8s %8s %9s %9s %6s %7s %7s" %
        ("case", "mesh", "tris", "out%0", "out%", "nc%", "ncb%", "merged", "ang0", "ang",
         "dual0", "dual", "step0", "step", "xTri", "t_ref", "t_opt"))


def row(name, label, nt, out0, out, nc, ncb, mrg, ang0, ang, r0, r, s0, s, s_tri, t_ref, t_opt):
    def f(x, fmt):
        return fmt % x if x is not None else "-"
    print("%-9s %-18s %7d %7s %7s %7s %7s %7s %6s %6s %8s %8s %9s %9s %6s %7s %7s" %
          (name, label, nt, f(out0, "%.3f"), f(out, "%.3f"), f(nc, "%.3f"), f(ncb, "%.3f"),
           f(mrg, "%.3f"), f(ang0, "%.2f"), f(ang, "%.2f"), f(r0, "%.2g"), f(r, "%.3f"),
           f(s0, "%.3g"), f(s, "%.3g"), f(s / s_tri if s_tri else None, "%.3g"),
           f(t_ref, "%.3f"), f(t_opt, "%.3f")))


def cvm_rows(name, poly, h, algo, label, s_tri, grade=None):
    for solver, sl in ((1, "pattern"), (2, "cuckoo")):
        d = driver(poly, h, algo, solver, grade)
        g = lambda k: float(d[k])
        row(name, "%s+%s" % (label, sl), int(d["after_nt"]), g("before_out"), g("after_out"),
            g("after_nc"), g("after_ncb"), g("after_merged"), g("before_minang"),
            g("after_minang"), g("before_powerratio"), g("after_powerratio"), g("before_step"),
            g("after_step"), s_tri, g("t_refine"), g("t_opt"))


def main():
    build_driver(BUILD, "bench_dual")
    print("# bench_dual: cvm_mesh_optimise_dual (defaults: min angle 30, target angle 40, margin "
          "0.15, merge tol 0.1), one core")
    print("# out%0/out% dual vertex outside before/after; nc% / ncb% non-compliant after (all / "
          "boundary); dual0/dual smallest dual edge / primal edge; step = min(primal, dual);")
    print("# xTri = step / step of Triangle's raw mesh; Lloyd = %d iterations on Triangle's mesh"
          % LLOYD_ITERS)
    print(HEAD)
    try:
        import triangle  # noqa: F401
        have_triangle = True
    except ImportError:
        print("# Triangle (pip triangle) not installed: Triangle and Lloyd rows skipped")
        have_triangle = False
    with tempfile.TemporaryDirectory() as tmp:
        for (name, h), large in [(c, False) for c in CASES] + [(c, True) for c in LARGE]:
            poly = os.path.join(DOMAINS, name + ".poly")
            s_tri = None
            if have_triangle:
                xy, segs, holes = read_poly(poly)
                t_tri, t = run_triangle(xy, segs, holes, h)
                m = measure(np.array(t["vertices"]), np.array(t["triangles"]))
                s_tri = m["step"]
                row(name, "triangle", m["nt"], m["out"], None, None, None, None, m["minang"], None,
                    m["ratio"], None, m["step"], None, None, t_tri, None)
                if not large:
                    t0 = time.perf_counter()
                    lxy, ltri = lloyd(t, holes, LLOYD_ITERS)
                    tl = time.perf_counter() - t0
                    ml = measure(lxy, ltri)
                    row(name, "triangle+lloyd20", ml["nt"], m["out"], ml["out"], None, None, None,
                        m["minang"], ml["minang"], m["ratio"], ml["ratio"], m["step"], ml["step"],
                        s_tri, t_tri, tl)
                tp = os.path.join(tmp, name + "_tri.poly")
                write_poly(tp, np.array(t["vertices"]), np.array(t["segments"]), holes)
                for solver, sl in ((1, "pattern"),):
                    d = driver(tp, h, 0, solver)
                    g = lambda k: float(d[k])
                    row(name, "triangle+cvm-" + sl, int(d["after_nt"]), g("before_out"),
                        g("after_out"), g("after_nc"), g("after_ncb"), g("after_merged"),
                        g("before_minang"), g("after_minang"), g("before_powerratio"),
                        g("after_powerratio"), g("before_step"), g("after_step"), s_tri,
                        t_tri, g("t_opt"))
            for algo, label in ((1, "cvm-del"), (2, "cvm-front")):
                cvm_rows(name, poly, h, algo, label, s_tri)
            # the frontal mesh with the sizing graded from the boundary's own spacing
            cvm_rows(name, poly, h, 2, "cvm-front-bg", s_tri, BOUNDARY_GRADING)
            sys.stdout.flush()
        # about 1e5 triangles from cvmesh's own refiners (sizes differ: see LARGE_CVM)
        for name, algo, h, label in LARGE_CVM:
            cvm_rows(name + "-1e5", os.path.join(DOMAINS, name + ".poly"), h, algo, label, None)
        sys.stdout.flush()


if __name__ == "__main__":
    main()
