#!/usr/bin/env python3
"""Independent checker of a 2D cvmesh output against its input.

    verify_mesh.py INPUT MESH_PREFIX [--weights] [--no-delaunay] [--min-angle D]
                   [--max-obtuse PCT] [--tol T]

INPUT is the Triangle .poly (or .node point set) that was meshed; MESH_PREFIX
names the mesh written as Triangle files (MESH_PREFIX.node and .ele, 0- or
1-based as the files say). Nothing of cvmesh is used: the files are parsed
here and every topological decision is exact (float filter, then rational
arithmetic with fractions.Fraction).

Structural checks (exit status 1 when one fails):
  - every triangle is counter-clockwise and has three distinct vertices;
  - the mesh is conforming: each edge lies in one or two triangles, with
    opposite orientations when in two;
  - every input segment is covered, end to end, by a chain of mesh edges whose
    inner vertices lie on the segment (a vertex where two segments cross is a
    rounded point: within TOL x segment length of the line);
  - every boundary edge of the mesh lies on an input segment (or, for a point
    set, on the convex hull);
  - the area equals the domain's (loops of segments, minus the faces that hold
    a hole point; the convex hull for a point set), to 1e-9 relative;
  - the Euler characteristic V - E + T equals that of the domain;
  - the constrained Delaunay property: no edge that is not on a segment has its
    opposite vertex strictly inside the other triangle's circumcircle; with
    --weights the first .node attribute is the power weight w (power distance
    |x - p|^2 - w) and the test is the power (regular) one.
Measured and printed (JSON, last line): angles, % in [55, 65], % obtuse,
% interior vertices of degree 6 and, with --weights, % of triangles whose
power vertex lies strictly outside them. --min-angle / --max-obtuse turn the
measures into checks.
"""

import argparse
import json
import math
import sys
from fractions import Fraction

import numpy as np

EPS = 2.0 ** -53


# ---------------------------------------------------------------- reading
def rows_of(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                rows.append(line)
    return rows


def read_input(path):
    """Points, segments (0-based pairs) and hole points of a .poly or .node."""
    rows = rows_of(path)
    n, dim = int(rows[0][0]), int(rows[0][1])
    if dim != 2:
        raise SystemExit("%s: dimension %d, expected 2" % (path, dim))
    ids = [int(r[0]) for r in rows[1:1 + n]]
    base = min(ids) if ids else 0
    pts = np.array([[float(r[1]), float(r[2])] for r in rows[1:1 + n]]).reshape(-1, 2)
    order = np.argsort(np.array(ids) - base, kind="stable") if ids else []
    pts = pts[order] if n else pts
    segs, holes = [], []
    if path.endswith(".poly") and len(rows) > 1 + n:
        k = 1 + n
        ns = int(rows[k][0])
        k += 1
        for r in rows[k:k + ns]:
            a, b = int(r[1]) - base, int(r[2]) - base
            if a != b:
                segs.append((a, b))
        k += ns
        if k < len(rows):
            nh = int(rows[k][0])
            holes = [(float(r[1]), float(r[2])) for r in rows[k + 1:k + 1 + nh]]
    return pts, segs, holes


def read_mesh(prefix):
    nrows = rows_of(prefix + ".node")
    n, _, nattr = int(nrows[0][0]), int(nrows[0][1]), int(nrows[0][2])
    ids = [int(r[0]) for r in nrows[1:1 + n]]
    base = min(ids) if ids else 0
    xy = np.array([[float(r[1]), float(r[2])] for r in nrows[1:1 + n]]).reshape(-1, 2)
    w = None
    if nattr > 0:
        w = np.array([float(r[3]) for r in nrows[1:1 + n]])
    if ids != list(range(base, base + n)):
        raise SystemExit("%s.node: point numbers are not consecutive" % prefix)
    erows = rows_of(prefix + ".ele")
    nt = int(erows[0][0])
    tri = np.array([[int(v) - base for v in r[1:4]] for r in erows[1:1 + nt]],
                   dtype=np.int64).reshape(-1, 3)
    return xy, w, tri


# ---------------------------------------------------------------- exact predicates
def fr(v):
    return Fraction(float(v))


def orient(a, b, c):
    """Sign of the orientation of a, b, c (points as float pairs)."""
    l = (a[0] - c[0]) * (b[1] - c[1])
    r = (a[1] - c[1]) * (b[0] - c[0])
    det = l - r
    bound = 4 * EPS * (abs(l) + abs(r))
    if abs(det) > bound:
        return 1 if det > 0 else -1
    ax, ay, bx, by, cx, cy = map(fr, (a[0], a[1], b[0], b[1], c[0], c[1]))
    d = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)
    return (d > 0) - (d < 0)


def lifted(a, b, c, d, wa=0.0, wb=0.0, wc=0.0, wd=0.0):
    """Sign of the in-circle (power) determinant: > 0 when d lies strictly inside
    the circle (power circle) through a, b, c given counter-clockwise."""
    def row(p, w):
        x, y = p[0] - d[0], p[1] - d[1]
        return x, y, x * x + y * y - (w - wd)
    rows = [row(a, wa), row(b, wb), row(c, wc)]
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = rows
    det = (az * (bx * cy - by * cx) - bz * (ax * cy - ay * cx) + cz * (ax * by - ay * bx))
    perm = (abs(az) * (abs(bx * cy) + abs(by * cx)) + abs(bz) * (abs(ax * cy) + abs(ay * cx))
            + abs(cz) * (abs(ax * by) + abs(ay * bx)))
    if perm == perm and abs(det) > 64 * EPS * perm and math.isfinite(det):
        return 1 if det > 0 else -1
    D = [fr(d[0]), fr(d[1])]
    R = []
    for p, w in ((a, wa), (b, wb), (c, wc)):
        x, y = fr(p[0]) - D[0], fr(p[1]) - D[1]
        R.append((x, y, x * x + y * y - (fr(w) - fr(wd))))
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = R
    det = (az * (bx * cy - by * cx) - bz * (ax * cy - ay * cx) + cz * (ax * by - ay * bx))
    return (det > 0) - (det < 0)


# ---------------------------------------------------------------- domain
def loops_of(nseg_pts, segs):
    """Closed loops (lists of point indices) when every segment end has degree 2."""
    adj = {}
    for a, b in segs:
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    if any(len(v) != 2 for v in adj.values()):
        return None
    seen, loops = set(), []
    for start in adj:
        if start in seen:
            continue
        loop, prev, cur = [start], None, start
        seen.add(start)
        while True:
            nxt = adj[cur][0] if adj[cur][0] != prev else adj[cur][1]
            if nxt == start:
                break
            if nxt in seen:
                return None
            loop.append(nxt)
            seen.add(nxt)
            prev, cur = cur, nxt
        loops.append(loop)
    return loops


def shoelace(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def inside(pt, poly):
    """Even-odd containment of a point in a polygon (float; holes and loops of the
    test domains are far from the points tested)."""
    x, y = pt
    c = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y):
            xi = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
            if xi > x:
                c = not c
    return c


def domain_measures(pts, segs, holes):
    """(area, Euler characteristic) of the domain, or None when the segments do
    not form nested closed loops (then the checks are skipped)."""
    if not segs:
        hull = convex_hull(pts)
        return abs(shoelace(pts[hull])), 1
    loops = loops_of(len(pts), segs)
    if loops is None:
        return None
    polys = [pts[l] for l in loops]
    areas = [abs(shoelace(p)) for p in polys]
    n = len(loops)
    contains = [[j != i and inside(polys[i][0], polys[j]) for j in range(n)] for i in range(n)]
    parent = []
    for i in range(n):
        cands = [j for j in range(n) if contains[i][j]]
        parent.append(min(cands, key=lambda j: areas[j]) if cands else -1)
    children = [[i for i in range(n) if parent[i] == j] for j in range(n)]

    def in_face(h, j):
        return inside(h, polys[j]) and not any(inside(h, polys[c]) for c in children[j])
    area, euler = 0.0, 0
    for j in range(n):
        if any(in_face(h, j) for h in holes):
            continue
        area += areas[j] - sum(areas[c] for c in children[j])
        euler += 1 - len(children[j])
    return area, euler


def convex_hull(p):
    idx = sorted(range(len(p)), key=lambda i: (p[i][0], p[i][1]))

    def half(order):
        h = []
        for i in order:
            while len(h) >= 2 and orient(p[h[-2]], p[h[-1]], p[i]) <= 0:
                h.pop()
            h.append(i)
        return h
    lower, upper = half(idx), half(idx[::-1])
    return lower[:-1] + upper[:-1]


# ---------------------------------------------------------------- checks
def on_segment(q, a, b, tol):
    """q lies on segment ab: exactly, or within tol x |ab| (rounded crossings)."""
    ab = b - a
    L2 = float(ab @ ab)
    t = float((q - a) @ ab) / L2
    if t < -tol or t > 1 + tol:
        return False
    if orient(a, b, q) == 0:
        return True
    d = abs(float(ab[0] * (q[1] - a[1]) - ab[1] * (q[0] - a[0]))) / math.sqrt(L2)
    return d <= tol * math.sqrt(L2)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input")
    ap.add_argument("prefix")
    ap.add_argument("--weights", action="store_true")
    ap.add_argument("--no-delaunay", action="store_true")
    ap.add_argument("--min-angle", type=float)
    ap.add_argument("--max-obtuse", type=float)
    ap.add_argument("--tol", type=float, default=1e-9)
    a = ap.parse_args(argv)

    pts, segs, holes = read_input(a.input)
    xy, w, tri = read_mesh(a.prefix)
    if a.weights and w is None:
        raise SystemExit("%s.node has no attribute to read as the weight" % a.prefix)
    wt = w if a.weights else np.zeros(len(xy))
    fails = []

    def fail(msg):
        if len(fails) < 20:
            fails.append(msg)

    # vertices of the input
    where = {(float(x), float(y)): i for i, (x, y) in enumerate(xy)}
    if len(where) != len(xy):
        fail("two mesh vertices share coordinates")
    used = np.unique(tri)
    # triangles: distinct, counter-clockwise
    for t, (i, j, k) in enumerate(tri):
        if len({i, j, k}) != 3 or orient(xy[i], xy[j], xy[k]) <= 0:
            fail("triangle %d (%d %d %d) is not counter-clockwise" % (t, i, j, k))
    # conformity
    half = {}
    for t, (i, j, k) in enumerate(tri):
        for u, v in ((i, j), (j, k), (k, i)):
            if (u, v) in half:
                fail("edge %d-%d in two triangles with one orientation" % (u, v))
            half[(u, v)] = t
    edges = {(min(u, v), max(u, v)) for (u, v) in half}
    # segments
    on_segs = {}                       # mesh vertex -> input segments it lies on
    for s, (p, q) in enumerate(segs):
        ka, kb = (float(pts[p][0]), float(pts[p][1])), (float(pts[q][0]), float(pts[q][1]))
        if ka not in where or kb not in where:
            fail("segment %d: an end point is not a mesh vertex" % s)
            continue
        A, B = where[ka], where[kb]
        a0, b0 = xy[A], xy[B]
        lo, hi = np.minimum(a0, b0), np.maximum(a0, b0)
        pad = a.tol * float(np.linalg.norm(b0 - a0)) + 1e-300
        near = np.nonzero(np.all((xy[used] >= lo - pad) & (xy[used] <= hi + pad), axis=1))[0]
        chain = [int(used[i]) for i in near if on_segment(xy[used[i]], a0, b0, a.tol)]
        ab = b0 - a0
        chain.sort(key=lambda v: float((xy[v] - a0) @ ab))
        for v in chain:
            on_segs.setdefault(v, set()).add(s)
        if not chain or chain[0] != A or chain[-1] != B:
            fail("segment %d (points %d-%d) is not joined end to end" % (s, p, q))
            continue
        for u, v in zip(chain, chain[1:]):
            if (min(u, v), max(u, v)) not in edges:
                fail("segment %d (points %d-%d): vertices %d and %d on it are not joined by an edge"
                     % (s, p, q, u, v))
                break

    def constrained(u, v):
        return bool(on_segs.get(u, set()) & on_segs.get(v, set()))
    # boundary (for a point set the area and Euler checks below pin it to the hull)
    for (u, v) in half:
        if (v, u) not in half and segs and not constrained(u, v):
            fail("boundary edge %d-%d lies on no input segment" % (u, v))
    # area and Euler characteristic
    P = xy[tri]
    areas = 0.5 * ((P[:, 1, 0] - P[:, 0, 0]) * (P[:, 2, 1] - P[:, 0, 1])
                   - (P[:, 1, 1] - P[:, 0, 1]) * (P[:, 2, 0] - P[:, 0, 0]))
    area = float(np.sum(areas))
    dom = domain_measures(pts, segs, holes)
    euler = len(used) - len(edges) + len(tri)
    if dom is not None:
        if abs(area - dom[0]) > 1e-9 * max(1.0, abs(dom[0])):
            fail("area %.17g, domain %.17g" % (area, dom[0]))
        if euler != dom[1]:
            fail("Euler characteristic %d, domain %d" % (euler, dom[1]))
    # (constrained) Delaunay or regular
    illegal = 0
    if not a.no_delaunay:
        for (u, v), t in half.items():
            if u > v or (v, u) not in half:
                continue
            if segs and constrained(u, v):
                continue
            c = [x for x in tri[t] if x != u and x != v][0]
            d = [x for x in tri[half[(v, u)]] if x != u and x != v][0]
            # (u, v, c) is counter-clockwise in triangle t
            if lifted(xy[u], xy[v], xy[c], xy[d], wt[u], wt[v], wt[c], wt[d]) > 0:
                illegal += 1
                fail("edge %d-%d fails the exact %s test" % (u, v, "power" if a.weights else "in-circle"))
    # quality
    ang = []
    for k in range(3):
        p0, p1, p2 = P[:, k], P[:, (k + 1) % 3], P[:, (k + 2) % 3]
        e1, e2 = p1 - p0, p2 - p0
        ang.append(np.degrees(np.arctan2(np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]),
                                         np.sum(e1 * e2, axis=1))))
    ang = np.stack(ang, axis=1)
    deg = np.zeros(len(xy), dtype=np.int64)
    for (u, v) in edges:
        deg[u] += 1
        deg[v] += 1
    bnd = {u for (u, v) in half if (v, u) not in half} | {v for (u, v) in half if (v, u) not in half}
    inner = [v for v in used if int(v) not in bnd]
    res = {
        "points": int(len(used)), "triangles": int(len(tri)), "edges": len(edges),
        "area": area, "domain_area": dom[0] if dom else None,
        "euler": euler, "domain_euler": dom[1] if dom else None,
        "illegal_edges": illegal,
        "min_angle": round(float(ang.min()), 4) if len(tri) else None,
        "max_angle": round(float(ang.max()), 4) if len(tri) else None,
        "pct_angles_55_65": round(100.0 * float(np.mean((ang >= 55) & (ang <= 65))), 2) if len(tri) else None,
        "pct_obtuse": round(100.0 * float(np.mean(ang.max(axis=1) > 90)), 2) if len(tri) else None,
        "pct_deg6_interior": round(100.0 * float(np.mean(deg[inner] == 6)), 2) if inner else None,
    }
    if a.weights:
        outside = sum(1 for t in tri if power_vertex_outside(xy, wt, t))
        res["pct_power_outside"] = round(100.0 * outside / max(1, len(tri)), 4)
    if a.min_angle is not None and len(tri) and res["min_angle"] < a.min_angle:
        fail("min angle %.4f < %.4f" % (res["min_angle"], a.min_angle))
    if a.max_obtuse is not None and len(tri) and res["pct_obtuse"] > a.max_obtuse:
        fail("%.2f%% obtuse > %.2f%%" % (res["pct_obtuse"], a.max_obtuse))
    res["ok"] = not fails
    res["failures"] = fails
    print(json.dumps(res))
    return 0 if not fails else 1


def power_vertex_outside(xy, w, t):
    """The power vertex of triangle t lies strictly outside it (exact)."""
    i, j, k = (int(v) for v in t)
    ax, ay = fr(xy[i][0]), fr(xy[i][1])
    bx, by = fr(xy[j][0]) - ax, fr(xy[j][1]) - ay
    cx, cy = fr(xy[k][0]) - ax, fr(xy[k][1]) - ay
    wa, wb, wc = fr(w[i]), fr(w[j]), fr(w[k])
    # centre x (relative to a) with |x - b|^2 - wb = |x|^2 - wa etc.:
    # 2 b.x = |b|^2 - wb + wa,  2 c.x = |c|^2 - wc + wa
    rb = bx * bx + by * by - wb + wa
    rc = cx * cx + cy * cy - wc + wa
    det = 2 * (bx * cy - by * cx)
    X = (rb * cy - rc * by) / det
    Y = (bx * rc - cx * rb) / det
    pts = [(Fraction(0), Fraction(0)), (bx, by), (cx, cy)]
    for m in range(3):
        (px, py), (qx, qy) = pts[m], pts[(m + 1) % 3]
        if (qx - px) * (Y - py) - (qy - py) * (X - px) < 0:
            return True
    return False


if __name__ == "__main__":
    sys.exit(main())
