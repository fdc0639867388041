"""Assemble the co-volume (finite-volume) Laplacian on a tetrahedral mesh's Voronoi dual.

Usage: python covolume_laplacian3d.py [--cvmesh CLI] [--tetgen] [--sizes H1,H2,H3]
                                      [--surface FILE.off] [--check]

This is what a co-volume or node-centred finite-volume user checks first. For
every mesh edge ij the coupling coefficient is c_ij = |dual face of ij| / |ij|,
the dual face being the polygon of circumcentres of the tetrahedra around the
edge (its area signed: a piece whose circumcentre lies beyond the edge's
neighbours counts negative). The scheme is monotone, with a discrete maximum
principle, only if every c_ij is positive.

The script meshes the domain (a sphere of radius 0.5 in the box [-2,2]^3 by
default, the sphere a hole) at three sizes with `cvmesh mesh3`, and with TetGen
(the `tetgen` package from PyPI, `-pq1.414a<V>`) when --tetgen is given and the
package is importable; for each mesh it prints how many coefficients are
negative, then solves -lap(u) = f with u = sin(x) cos(y) exp(z/2) on the
boundary (Dirichlet) and prints the largest nodal error and the observed order.

The script asserts two facts of any circumcentric dual before it reports: the
control volumes add up to the mesh's volume, and every interior dual cell is
closed (sum_j c_ij (x_j - x_i) = 0). (The P1 finite-element coefficients, the
cotangent formula, differ from these in 3D and may be negative even on a
Delaunay mesh; this is the co-volume scheme.) --check turns the
co-volume user's expectations into an exit status: every cvmesh coefficient
positive and an observed order of at least 1.8 between the two finer sizes.
"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np


def read_off(path):
    """Vertices (n,3) and triangles (m,3) of an OFF file."""
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            words.extend(line)
    if words[0] != "OFF":
        raise ValueError("%s: not an OFF file" % path)
    nv, nf = int(words[1]), int(words[2])
    at = 4
    v = np.array(words[at:at + 3 * nv], float).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + k]])
        at += 1 + k
    return v, np.array(faces, np.int64)


def sphere_in_box(level, n, radius=0.5, half=1.0):
    """Surface of the box [-half, half]^3 (n x n squares a face, each split in two) minus a ball
    (an icosphere subdivided level times, radius radius): vertices, triangles with their normals
    pointing out of the domain (into the ball on the sphere), and the ball's triangles."""
    phi = (1 + 5 ** 0.5) / 2
    v = [(-1, phi, 0), (1, phi, 0), (-1, -phi, 0), (1, -phi, 0), (0, -1, phi), (0, 1, phi),
         (0, -1, -phi), (0, 1, -phi), (phi, 0, -1), (phi, 0, 1), (-phi, 0, -1), (-phi, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    v = [np.array(x, float) / np.linalg.norm(x) for x in v]
    for _ in range(level):
        mid, g = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                x = v[a] + v[b]
                v.append(x / np.linalg.norm(x))
                mid[key] = len(v) - 1
            return mid[key]
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            g += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = g
    sphere_v = radius * np.array(v)
    sphere_f = np.array([(a, c, b) for a, b, c in f])  # reversed: normals into the ball
    pts, tris = [tuple(x) for x in sphere_v], [tuple(t) for t in sphere_f]
    index = {}

    def vid(x):
        key = tuple(round(c * n / (2 * half)) for c in x)
        if key not in index:
            index[key] = len(pts)
            pts.append(tuple(x))
        return index[key]
    g = np.linspace(-half, half, n + 1)
    for axis in range(3):
        for side in (-half, half):
            u, w = [k for k in range(3) if k != axis]
            for i in range(n):
                for j in range(n):
                    q = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        x = [0.0, 0.0, 0.0]
                        x[axis], x[u], x[w] = side, g[i + di], g[j + dj]
                        q.append(vid(x))
                    a, b, c, d = q
                    # outward normal: (u, w, axis) right-handed when side > 0
                    flip = (side > 0) != ((u, w, axis) in ((0, 1, 2), (1, 2, 0), (2, 0, 1)))
                    for t in ((a, b, c), (a, c, d)):
                        tris.append((t[0], t[2], t[1]) if flip else t)
    return np.array(pts), np.array(tris, np.int64), sphere_v, sphere_f


def write_surface(base, p, tris):
    """OFF (for TetGen) and TetGen .poly with the hole point at the origin (for cvmesh)."""
    with open(base + ".off", "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(p), len(tris)))
        f.writelines("%.17g %.17g %.17g\n" % tuple(x) for x in p)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in tris)
    with open(base + ".poly", "w") as f:
        f.write("%d 3 0 0\n" % len(p))
        f.writelines("%d %.17g %.17g %.17g\n" % ((i,) + tuple(x)) for i, x in enumerate(p))
        f.write("%d 1\n" % len(tris))
        f.writelines("1 0 1\n3 %d %d %d\n" % tuple(t) for t in tris)
        f.write("1\n0 0 0 0\n0\n")
    return base + ".off", base + ".poly"


def outside_ball_polyhedron(x, sphere_v, sphere_f):
    """Points outside the convex polyhedron of the ball (its triangles point into it)."""
    a = sphere_v[sphere_f[:, 0]]
    nrm = -np.cross(sphere_v[sphere_f[:, 1]] - a, sphere_v[sphere_f[:, 2]] - a)  # outward of the ball
    return ((x @ nrm.T) - np.einsum("ij,ij->i", a, nrm)[None, :] > 0).any(axis=1)


def read_vtu_tets(path):
    """Points and tetrahedra of a .vtu (through meshio)."""
    import meshio
    m = meshio.read(path)
    tets = [c.data for c in m.cells if c.type == "tetra"]
    if not tets:
        raise ValueError("%s has no tetrahedra" % path)
    return np.asarray(m.points, float)[:, :3], np.vstack(tets).astype(np.int64)


def orient_positive(p, t):
    """Tetrahedra reordered so that each has a positive volume."""
    a, b, c, d = (p[t[:, k]] for k in range(4))
    vol = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)
    t = t.copy()
    neg = vol < 0
    t[neg, 0], t[neg, 1] = t[neg, 1], t[neg, 0].copy()
    return t


# The six edges of a tetrahedron and, for each, its opposite edge.
EDGES = np.array([(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)])
OPPOSITE = np.array([(2, 3), (1, 3), (1, 2), (0, 3), (0, 2), (0, 1)])


def circumcentres(p, t):
    """Circumcentre of each tetrahedron (solving the 3x3 system, in floating point)."""
    a = p[t[:, 0]]
    e = np.stack([p[t[:, k]] - a for k in (1, 2, 3)], axis=1)
    rhs = 0.5 * np.einsum("ijk,ijk->ij", e, e)
    return a + np.linalg.solve(e, rhs[..., None])[..., 0]


def tri_circumcentres(x0, x1, x2):
    """Circumcentres of the triangles (x0, x1, x2), arrays of shape (n, 3)."""
    a, b = x1 - x0, x2 - x0
    n = np.cross(a, b)
    nn = np.einsum("ij,ij->i", n, n)
    num = (np.einsum("ij,ij->i", a, a)[:, None] * np.cross(b, n)
           + np.einsum("ij,ij->i", b, b)[:, None] * np.cross(n, a))
    return x0 + num / (2 * nn[:, None])


def dual_coefficients(p, t):
    """Per-edge coefficient |dual face| / |edge| from the circumcentres.

    Returns (edges (E,2) sorted pairs, c (E,)). For tetrahedron T and its edge ij with
    opposite vertices k, l, the dual face's piece inside T is the quadrilateral
    (midpoint of ij, circumcentre of ijk, circumcentre of T, circumcentre of ijl), which lies
    in the bisector plane of ij; its area is signed, positive when the circumcentres lie on
    the side of their faces and edge that the tetrahedron does (always so in a well-centred
    tetrahedron), and the pieces of the tetrahedra around an edge add up to its dual face.
    """
    t = orient_positive(p, t)
    cc = circumcentres(p, t)
    a, b, c, d = (p[t[:, k]] for k in range(4))
    x = [a, b, c, d]
    g = 0.25 * (a + b + c + d)
    keys, pieces = [], []
    for (i, j), (k, l) in zip(EDGES, OPPOSITE):
        xi, xj, xk, xl = x[i], x[j], x[k], x[l]
        m = 0.5 * (xi + xj)
        e = xj - xi
        le = np.linalg.norm(e, axis=1)
        u = e / le[:, None]
        # Quadrilateral (m, c_ijk, c_T, c_ijl): its area vector is half the cross product of
        # its diagonals, and projected on the edge it is the signed area.
        area = 0.5 * np.einsum("ij,ij->i", np.cross(cc - m, tri_circumcentres(xi, xj, xl)
                                                   - tri_circumcentres(xi, xj, xk)), u)
        # The same quadrilateral through the centroids (inside T) fixes the orientation.
        ref = np.einsum("ij,ij->i", np.cross(g - m, (xi + xj + xl) / 3 - (xi + xj + xk) / 3), u)
        keys.append(np.sort(t[:, [i, j]], axis=1))
        pieces.append(area * np.sign(ref) / le)
    edges, inv = np.unique(np.vstack(keys), axis=0, return_inverse=True)
    c = np.bincount(inv.ravel(), weights=np.concatenate(pieces), minlength=len(edges))
    return edges, c


def compact(p, t):
    """Drop points no tetrahedron uses (TetGen keeps the ball's Steiner points)."""
    used = np.zeros(len(p), bool)
    used[t.ravel()] = True
    new = -np.ones(len(p), np.int64)
    new[used] = np.arange(used.sum())
    return p[used], new[t]


def boundary_vertices(t, n):
    """Vertices on a face that belongs to one tetrahedron only."""
    faces = np.vstack([np.sort(t[:, [a, b, c]], axis=1)
                       for a, b, c in ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))])
    uniq, counts = np.unique(faces, axis=0, return_counts=True)
    on = np.zeros(n, bool)
    on[uniq[counts == 1].ravel()] = True
    return on


def exact_u(p):
    return np.sin(p[:, 0]) * np.cos(p[:, 1]) * np.exp(0.5 * p[:, 2])


def solve_manufactured(p, t):
    """Max nodal error of the co-volume scheme for -lap u = 1.75 u_exact, u exact on the boundary."""
    edges, c = dual_coefficients(p, t)
    n = len(p)
    on = boundary_vertices(t, n)
    length2 = np.einsum("ij,ij->i", p[edges[:, 1]] - p[edges[:, 0]], p[edges[:, 1]] - p[edges[:, 0]])
    # Control volume of vertex i: the pyramids over its dual faces, sum of c_ij |ij|^2 / 6.
    vol = np.bincount(edges[:, 0], c * length2 / 6, n) + np.bincount(edges[:, 1], c * length2 / 6, n)
    ue = exact_u(p)
    f = 1.75 * ue
    free = np.flatnonzero(~on)
    idx = -np.ones(n, np.int64)
    idx[free] = np.arange(len(free))
    i, j = edges[:, 0], edges[:, 1]
    diag = np.bincount(i, c, n) + np.bincount(j, c, n)
    rhs = f * vol
    # Known boundary values move to the right-hand side.
    rhs = rhs + np.bincount(i, c * np.where(on[j], ue[j], 0), n) + np.bincount(j, c * np.where(on[i], ue[i], 0), n)
    both = ~on[i] & ~on[j]
    ii, jj, cc = idx[i[both]], idx[j[both]], c[both]
    dg = diag[free]
    b = rhs[free]

    def matvec(x):
        y = dg * x
        y -= np.bincount(ii, cc * x[jj], len(free))
        y -= np.bincount(jj, cc * x[ii], len(free))
        return y

    # Jacobi-preconditioned conjugate gradients (the matrix is SPD when every c_ij > 0).
    x = np.zeros(len(free))
    r = b - matvec(x)
    z = r / dg
    d = z.copy()
    rz = r @ z
    bnorm = np.linalg.norm(b)
    for _ in range(20000):
        if np.linalg.norm(r) <= 1e-12 * bnorm:
            break
        ad = matvec(d)
        alpha = rz / (d @ ad)
        x += alpha * d
        r -= alpha * ad
        z = r / dg
        rz_new = r @ z
        d = z + (rz_new / rz) * d
        rz = rz_new
    err = np.abs(x - ue[free]).max() if len(free) else 0.0
    return err, edges, c, vol, on


def tet_volume(p, t):
    a, b, c, d = (p[t[:, k]] for k in range(4))
    return np.abs(np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)).sum() / 6


def report(name, p, t, h_nominal):
    p, t = compact(p, t)
    err, edges, c, vol, on = solve_manufactured(p, t)
    # Independent facts the dual must satisfy: the control volumes tile the domain, and the
    # closed dual cell of an interior vertex reproduces linear functions (sum c_ij (x_j - x_i) = 0).
    total = tet_volume(p, t)
    if abs(vol.sum() - total) > 1e-9 * total:
        raise AssertionError("%s: control volumes sum to %.12g, the mesh's volume is %.12g"
                             % (name, vol.sum(), total))
    d = p[edges[:, 1]] - p[edges[:, 0]]
    lin = np.zeros_like(p)
    for k in range(3):
        lin[:, k] = np.bincount(edges[:, 0], c * d[:, k], len(p)) - np.bincount(edges[:, 1], c * d[:, k], len(p))
    scale = np.abs(c).max() * np.sqrt(np.einsum("ij,ij->i", d, d)).max()
    if np.abs(lin[~on]).max() > 1e-9 * scale:
        raise AssertionError("%s: an interior dual cell is not closed" % name)
    inner = ~on[edges[:, 0]] | ~on[edges[:, 1]]  # the edges the scheme uses
    # |dual face| / |edge|^2, dimensionless: a co-spherical group of points (a lattice) has dual
    # faces of zero area, computed as +-1e-16; those count as zero, not as negative.
    rel = c[inner] / np.sqrt(np.einsum("ij,ij->i", d[inner], d[inner]))
    neg = int((rel < -1e-9).sum())
    zero = int((np.abs(rel) <= 1e-9).sum())
    print("%-7s h %-6g %7d vertices %8d tetrahedra %8d edges used: negative %5d (%.2f %%),"
          " zero %5d, smallest %+.2e; max error %.3e"
          % (name, h_nominal, len(p), len(t), int(inner.sum()), neg, 100.0 * neg / max(1, inner.sum()),
             zero, rel.min(), err))
    return h_nominal, err, neg


def orders(rows):
    out = []
    for (h1, e1, _), (h2, e2, _) in zip(rows, rows[1:]):
        out.append(np.log(e1 / e2) / np.log(h1 / h2) if e2 > 0 and e1 > 0 else float("nan"))
    return out


def mesh_cvmesh(cli, poly, h, tmp):
    out = os.path.join(tmp, "cvmesh_%g.vtu" % h)
    subprocess.run([cli, "mesh3", poly, "--size", str(h), "--uniform", "-o", out], check=True,
                   stdout=subprocess.DEVNULL)
    return read_vtu_tets(out)


def mesh_tetgen(off, h, sphere_v, sphere_f):
    import tetgen
    v, f = read_off(off)
    vol = h ** 3 / (6 * np.sqrt(2))  # a regular tetrahedron of edge h
    nodes, elems = tetgen.TetGen(v, f.astype(np.int32)).tetrahedralize(
        switches="pq1.414a%.10fQ" % vol)[:2]
    p, t = np.asarray(nodes, float), np.asarray(elems, np.int64)
    # This interface takes no hole point: TetGen meshes the ball too; drop its tetrahedra.
    return p, t[outside_ball_polyhedron(p[t].mean(axis=1), sphere_v, sphere_f)]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cvmesh", default=os.environ.get("CVMESH", "cvmesh"), help="the cvmesh CLI")
    ap.add_argument("--levels", type=int, default=3, help="number of sizes (each halves the last)")
    ap.add_argument("--tetgen", action="store_true", help="also TetGen's mesh (tetgen from PyPI)")
    ap.add_argument("--check", action="store_true", help="exit 1 unless cvmesh's coefficients are"
                    " all positive (or zero) and the order between the finest sizes is at least 1.8")
    args = ap.parse_args(argv)
    have_tetgen = False
    if args.tetgen:
        try:
            import tetgen  # noqa: F401
            have_tetgen = True
        except ImportError:
            print("tetgen  skipped: the tetgen package is not installed")
    rows, trows = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(args.levels):
            n, h = 4 * 2 ** k, 0.5 / 2 ** k
            p, tris, sv, sf = sphere_in_box(k + 1, n)
            off, poly = write_surface(os.path.join(tmp, "sphere_in_box_%d" % k), p, tris)
            rows.append(report("cvmesh", *mesh_cvmesh(args.cvmesh, poly, h, tmp), h))
            if have_tetgen:
                trows.append(report("tetgen", *mesh_tetgen(off, h, sv, sf), h))
    o = orders(rows)
    print("cvmesh  observed order of the max error: %s" % ", ".join("%.2f" % x for x in o))
    if trows:
        print("tetgen  observed order of the max error: %s"
              % ", ".join("%.2f" % x for x in orders(trows)))
    if args.check:
        bad = sum(1 for r in rows if r[2] > 0)
        if bad or not o or not o[-1] >= 1.8:
            print("check: FAILED (negative coefficients on %d meshes, order %s)"
                  % (bad, "%.2f" % o[-1] if o else "-"))
            return 1
        print("check: every cvmesh coefficient positive or zero, order %.2f" % o[-1])
    return 0


if __name__ == "__main__":
    sys.exit(main())
