#!/usr/bin/env python3
"""Write the closed surfaces of the 3D examples as .off, .stl and TetGen .poly.

Usage: make_data3d.py [OUTDIR]   (default: the directory of this script)

Standard library only and deterministic: the same bytes on every run (the
wing's sections use math.cos/sqrt, so another C library may differ in the last
digit of a few coordinates). Orientation convention: every triangle's normal
(right-hand rule) points out of the domain -- outward on the outer boundary,
into the body of a hole -- so the signed volume of a surface is the volume of
its domain.

Surfaces:
  cube           unit cube [0,1]^3, each face an 8x8 grid of right triangles
  sphere_in_box  box [-2,2]^3 (8x8 grid faces) minus a ball of radius 0.5 at
                 the origin (icosphere of 5120 triangles; a hole)
  wing_slab      swept, tapered NACA 0012 wing (chord 1 at the root, 0.6 at the
                 tip, span 3 along z, 15 degree leading-edge sweep, sharp
                 trailing edge, 60 points per section, 20 stations, flat caps;
                 a hole) in the box [-4,6]x[-4,4]x[-4,7]
  tetra          regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)
  two_cubes      two unit cubes sharing the face x=1, which is an internal
                 facet (marker 2, oriented +x); regions 1 and 2. Its surface is
                 not a 2-manifold; only the .poly carries the regions.

Each surface is written as NAME.off, NAME.stl (ASCII, one solid per boundary
marker), NAME.poly (TetGen, 1-based, one triangle per facet with its marker,
hole points, region points with attribute and max volume -1); the cube and
tetra also as NAME_binary.stl, and tetra and two_cubes as NAME.smesh.
"""
import math
import os
import struct
import sys


class Surface:
    def __init__(self, name, title):
        self.name = name
        self.title = title
        self.points = []      # (x, y, z)
        self.index = {}       # (x, y, z) -> index: shared vertices
        self.tris = []        # (i, j, k)
        self.marks = []       # marker per triangle
        self.mark_names = {}  # marker -> solid name
        self.holes = []
        self.regions = []     # (x, y, z, attribute, max volume)

    def point(self, p):
        p = tuple(float(c) for c in p)
        if p not in self.index:
            self.index[p] = len(self.points)
            self.points.append(p)
        return self.index[p]

    def tri(self, a, b, c, mark):
        self.tris.append((self.point(a), self.point(b), self.point(c)))
        self.marks.append(mark)


def box(s, lo, hi, n, mark, skip=None):
    """The faces of box [lo,hi] (3 tuples), each an n x n grid of right
    triangles, oriented outward; skip (axis, side) leaves out one face."""
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3     # u x v = +axis
        for side in (0, 1):
            if skip == (axis, side):
                continue
            for i in range(n):
                for j in range(n):
                    def at(a, b):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = hi[axis] if side else lo[axis]
                        p[u] = lo[u] + (hi[u] - lo[u]) * a / n
                        p[v] = lo[v] + (hi[v] - lo[v]) * b / n
                        return p
                    q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
                    if not side:                  # normal -axis: reverse
                        q.reverse()
                    s.tri(q[0], q[1], q[2], mark)
                    s.tri(q[0], q[2], q[3], mark)


def icosphere(s, r, levels, mark, inward):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(p):
        n = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
        return (p[0] / n, p[1] / n, p[2] / n)
    v = [unit(p) for p in v]
    for _ in range(levels):
        mid = {}
        nf = []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                pa, pb = v[a], v[b]
                v.append(unit(((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2)))
                mid[key] = len(v) - 1
            return mid[key]
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    pts = [(r * p[0], r * p[1], r * p[2]) for p in v]
    for a, b, c in f:                             # the icosahedron's faces point outward
        if inward:
            a, b = b, a
        s.tri(pts[a], pts[b], pts[c], mark)


def naca0012(xc):
    """Half thickness of NACA 0012 at chord fraction xc, closed trailing edge."""
    return 0.6 * (0.2969 * math.sqrt(xc) - 0.1260 * xc - 0.3516 * xc ** 2
                  + 0.2843 * xc ** 3 - 0.1036 * xc ** 4)


def wing(s, mark):
    npts, nst, span = 60, 20, 3.0
    sweep = math.tan(math.radians(15.0))
    half = npts // 2
    sec = []                                      # chord fraction, thickness sign
    for k in range(npts):
        xc = 0.5 * (1.0 + math.cos(2.0 * math.pi * k / npts))
        if k == 0:
            xc, y = 1.0, 0.0
        elif k == half:
            xc, y = 0.0, 0.0
        else:
            y = naca0012(xc) if k < half else -naca0012(xc)
        sec.append((xc, y))
    rings = []
    for j in range(nst):
        z = span * j / (nst - 1)
        chord = 1.0 - 0.4 * j / (nst - 1)
        xle = z * sweep
        rings.append([(xle + chord * xc, chord * y, z) for xc, y in sec])
    # Section k runs upper surface (y > 0) from the trailing edge to the leading
    # edge, then the lower one: counter-clockwise seen from +z. The hole's
    # triangles point into the wing.
    for j in range(nst - 1):
        a, b = rings[j], rings[j + 1]
        for k in range(npts):
            k1 = (k + 1) % npts
            s.tri(a[k], b[k1], a[k1], mark)
            s.tri(a[k], b[k], b[k1], mark)
    # Caps: strips between point k (upper) and npts - k (lower) of equal chord fraction.
    for ring, root in ((rings[0], True), (rings[-1], False)):
        tris = [(0, 1, npts - 1), (half - 1, half, half + 1)]
        for k in range(1, half - 1):
            tris += [(k, k + 1, npts - k - 1), (k, npts - k - 1, npts - k)]
        for a, b, c in tris:                      # ccw seen from +z: normal +z
            if root:                              # root cap: into the wing is +z
                s.tri(ring[a], ring[b], ring[c], mark)
            else:
                s.tri(ring[a], ring[c], ring[b], mark)
    c = 1.0 - 0.4 * 0.5
    s.holes.append((1.5 * sweep + 0.3 * c, 0.0, 1.5))


def make_all():
    out = []
    s = Surface("cube", "unit cube [0,1]^3, each face an 8x8 grid of right triangles")
    box(s, (0, 0, 0), (1, 1, 1), 8, 1)
    s.mark_names = {1: "cube"}
    s.regions.append((0.5, 0.5, 0.5, 1, -1.0))
    out.append(s)

    s = Surface("sphere_in_box", "box [-2,2]^3 (faces 8x8 grid) minus the ball of radius 0.5 "
                "at the origin (icosphere, 5120 faces; a hole)")
    box(s, (-2, -2, -2), (2, 2, 2), 8, 1)
    icosphere(s, 0.5, 4, 2, inward=True)
    s.mark_names = {1: "box", 2: "sphere"}
    s.holes.append((0.0, 0.0, 0.0))
    s.regions.append((1.5, 1.5, 1.5, 1, -1.0))
    out.append(s)

    s = Surface("wing_slab", "swept tapered NACA 0012 wing (chord 1 to 0.6, span 3 along z, "
                "15 deg sweep, sharp TE; a hole) in the box [-4,6]x[-4,4]x[-4,7]")
    box(s, (-4, -4, -4), (6, 4, 7), 8, 1)
    wing(s, 2)
    s.mark_names = {1: "box", 2: "wing"}
    s.regions.append((5.0, 3.0, 6.0, 1, -1.0))
    out.append(s)

    s = Surface("tetra", "regular tetrahedron, vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)")
    p = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    for a, b, c in ((0, 1, 2), (0, 2, 3), (0, 3, 1), (1, 3, 2)):
        s.tri(p[a], p[b], p[c], 1)
    s.mark_names = {1: "tetra"}
    s.regions.append((0.0, 0.0, 0.0, 1, -1.0))
    out.append(s)

    s = Surface("two_cubes", "two unit cubes sharing the face x=1 (marker 2, internal facet, "
                "oriented +x); regions 1 and 2")
    box(s, (0, 0, 0), (1, 1, 1), 1, 1, skip=(0, 1))
    box(s, (1, 0, 0), (2, 1, 1), 1, 1, skip=(0, 0))
    q = [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)]
    s.tri(q[0], q[1], q[2], 2)
    s.tri(q[0], q[2], q[3], 2)
    s.mark_names = {1: "outer", 2: "interface"}
    s.regions += [(0.5, 0.5, 0.5, 1, -1.0), (1.5, 0.5, 0.5, 2, -1.0)]
    out.append(s)
    return out


def num(x):
    return repr(float(x))


def normal(s, t):
    a, b, c = (s.points[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    ln = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    return [x / ln for x in n]


def write_off(s, path):
    with open(path, "w", newline="\n") as f:
        f.write("OFF\n%d %d 0\n" % (len(s.points), len(s.tris)))
        for p in s.points:
            f.write("%s %s %s\n" % tuple(num(c) for c in p))
        for t in s.tris:
            f.write("3 %d %d %d\n" % t)


def write_stl(s, path):
    with open(path, "w", newline="\n") as f:
        for m in sorted(s.mark_names):
            f.write("solid %s\n" % s.mark_names[m])
            for t, tm in zip(s.tris, s.marks):
                if tm != m:
                    continue
                f.write("  facet normal %s %s %s\n    outer loop\n" % tuple(num(x) for x in normal(s, t)))
                for i in t:
                    f.write("      vertex %s %s %s\n" % tuple(num(c) for c in s.points[i]))
                f.write("    endloop\n  endfacet\n")
            f.write("endsolid %s\n" % s.mark_names[m])


def write_binary_stl(s, path):
    with open(path, "wb") as f:
        head = ("binary STL: " + s.name).encode("ascii")
        f.write(head + b" " * (80 - len(head)))
        f.write(struct.pack("<I", len(s.tris)))
        for t, m in zip(s.tris, s.marks):
            f.write(struct.pack("<3f", *normal(s, t)))
            for i in t:
                f.write(struct.pack("<3f", *s.points[i]))
            f.write(struct.pack("<H", m))


def header(s, f):
    f.write("# %s: %s\n" % (s.name, s.title))
    f.write("# markers: %s\n" % ", ".join("%d=%s" % (m, s.mark_names[m]) for m in sorted(s.mark_names)))
    f.write("# normals point out of the domain (into hole bodies); generated by make_data3d.py\n")
    f.write("# part 1: nodes\n%d 3 0 0\n" % len(s.points))
    for i, p in enumerate(s.points):
        f.write("%d %s %s %s\n" % ((i + 1,) + tuple(num(c) for c in p)))


def tail(s, f):
    f.write("# part 3: holes\n%d\n" % len(s.holes))
    for i, h in enumerate(s.holes):
        f.write("%d %s %s %s\n" % ((i + 1,) + tuple(num(c) for c in h)))
    f.write("# part 4: regions (x y z attribute maxvolume)\n%d\n" % len(s.regions))
    for i, r in enumerate(s.regions):
        f.write("%d %s %s %s %d %s\n" % (i + 1, num(r[0]), num(r[1]), num(r[2]), r[3], num(r[4])))


def write_poly(s, path):
    with open(path, "w", newline="\n") as f:
        header(s, f)
        f.write("# part 2: facets (one triangle each) with boundary markers\n%d 1\n" % len(s.tris))
        for t, m in zip(s.tris, s.marks):
            f.write("1 0 %d\n3 %d %d %d\n" % (m, t[0] + 1, t[1] + 1, t[2] + 1))
        tail(s, f)


def write_smesh(s, path):
    with open(path, "w", newline="\n") as f:
        header(s, f)
        f.write("# part 2: facets with boundary markers\n%d 1\n" % len(s.tris))
        for t, m in zip(s.tris, s.marks):
            f.write("3 %d %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1, m))
        tail(s, f)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(outdir, exist_ok=True)
    for s in make_all():
        base = os.path.join(outdir, s.name)
        write_off(s, base + ".off")
        write_stl(s, base + ".stl")
        write_poly(s, base + ".poly")
        if s.name in ("cube", "tetra"):
            write_binary_stl(s, base + "_binary.stl")
        if s.name in ("tetra", "two_cubes"):
            write_smesh(s, base + ".smesh")


if __name__ == "__main__":
    main()
