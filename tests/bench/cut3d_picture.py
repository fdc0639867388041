"""A cut through a tetrahedral mesh coloured by whether each tetrahedron contains its power
vertex (issue 18's pictures).

usage: python cut3d_picture.py MESH.vtu AXIS VALUE OUT.svg [--window U0,V0,U1,V1] [--title T]

MESH.vtu: a tetrahedral .vtu, its power weights as point data "weight" when it has them (what
`cvmesh mesh3 ... --optimise -o MESH.vtu` writes); read with meshio. The cut of every
tetrahedron by the plane AXIS = VALUE (AXIS x, y or z) is drawn light blue when the power vertex
(weights included, doubles) lies inside it, red otherwise; --window crops to the plane's two other
coordinates. Doubles only: a picture, not a check (`cvmesh mesh3 --quality` is the exact count).
"""
import sys

import numpy as np

def power_vertices(P, W, T):
    """The power vertex of each tetrahedron: |c - p_i|^2 - w_i equal for its 4 corners."""
    A = P[T[:, 1:]] - P[T[:, :1]]
    b = 0.5 * ((P[T[:, 1:]] ** 2).sum(-1) - (P[T[:, :1]] ** 2).sum(-1)
               - (W[T[:, 1:]] - W[T[:, :1]]))
    return np.linalg.solve(A, b[..., None])[..., 0]


def bary_signs(P, T, c):
    """Per tetrahedron and face f (opposite corner f): > 0 when c is on the inner side."""
    out = np.empty((len(T), 4))
    for f in range(4):
        o = [k for k in range(4) if k != f]
        a, b, d = P[T[:, o[0]]], P[T[:, o[1]]], P[T[:, o[2]]]
        n = np.cross(b - a, d - a)
        out[:, f] = np.einsum("ij,ij->i", n, c - a) * np.einsum("ij,ij->i", n, P[T[:, f]] - a)
    return out


def cut_polygon(X, axis, value):
    """The polygon where the plane cuts the tetrahedron X (4 x 3), or None."""
    s = X[:, axis] - value
    pts = []
    for i in range(4):
        for j in range(i + 1, 4):
            if (s[i] < 0) != (s[j] < 0):
                t = s[i] / (s[i] - s[j])
                pts.append(X[i] + t * (X[j] - X[i]))
    if len(pts) < 3:
        return None
    pts = np.array(pts)
    keep = [k for k in range(3) if k != axis]
    q = pts[:, keep]
    c = q.mean(axis=0)
    order = np.argsort(np.arctan2(q[:, 1] - c[1], q[:, 0] - c[0]))
    return q[order]


def main():
    if len(sys.argv) < 5:
        raise SystemExit(__doc__)
    import meshio
    mesh = meshio.read(sys.argv[1])
    axis, value, out = "xyz".index(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    P = np.asarray(mesh.points, dtype=float)
    T = np.asarray(mesh.cells_dict["tetra"], dtype=np.int64)
    W = np.asarray(mesh.point_data["weight"], dtype=float) if "weight" in mesh.point_data \
        else np.zeros(len(P))
    C = power_vertices(P, W, T)
    inside = (bary_signs(P, T, C) >= 0).all(axis=1)
    polys = []
    for t in range(len(T)):
        X = P[T[t]]
        if X[:, axis].min() > value or X[:, axis].max() < value:
            continue
        q = cut_polygon(X, axis, value)
        if q is not None:
            polys.append((q, "#cfe0f0" if inside[t] else "#e04040"))
    allq = np.concatenate([q for q, _ in polys])
    lo, hi = allq.min(axis=0), allq.max(axis=0)
    if "--window" in sys.argv:
        u0, v0, u1, v1 = (float(v) for v in sys.argv[sys.argv.index("--window") + 1].split(","))
        lo, hi = np.array([u0, v0]), np.array([u1, v1])
        polys = [(q, c) for q, c in polys
                 if q[:, 0].max() >= u0 and q[:, 0].min() <= u1 and q[:, 1].max() >= v0
                 and q[:, 1].min() <= v1]
    title = (sys.argv[sys.argv.index("--title") + 1] if "--title" in sys.argv else
             "%d tetrahedra, %.2f %% not containing their power vertex (red)"
             % (len(T), 100.0 * (~inside).mean()))
    width = 900
    sc = width / (hi[0] - lo[0])
    height = int((hi[1] - lo[1]) * sc) + 34
    lines = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">' % (width, height),
             '<rect width="100%" height="100%" fill="white"/>']
    for q, fill in polys:
        pts = " ".join("%.2f,%.2f" % ((x - lo[0]) * sc, 34 + (hi[1] - y) * sc) for x, y in q)
        lines.append('<polygon points="%s" fill="%s" stroke="black" stroke-width="0.3"/>'
                     % (pts, fill))
    lines.append('<rect width="100%" height="30" fill="white"/>')
    lines.append('<text x="6" y="21" font-family="sans-serif" font-size="15">%s; cut %s = %g</text>'
                 % (title, "xyz"[axis], value))
    lines.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(lines))
    print("%s: %d polygons of %d tetrahedra, %.2f %% outside (doubles)"
          % (out, len(polys), len(T), 100.0 * (~inside).mean()))


if __name__ == "__main__":
    main()
