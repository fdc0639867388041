#!/usr/bin/env python3
"""bench_quad.py - metric-aligned quad-dominant meshes (issue 19): cvmesh quad beside Gmsh (PyPI
`gmsh`) on the paper's four metric cases, every mesh measured by the same numpy code here.

Cases (g as in `cvmesh quad --metric builtin:NAME`, times a scale s chosen so that the metric area
s * Int sqrt(det g) dA, about the vertex count of a unit quad mesh, is N, default 2500; set
CVM_BENCH_QUAD_N=10000 for the issue's 1e4 size, about ten times slower):
  identity  g = I on [0,4]^2
  stretch   diag(1, 1 + 4y^2) on [0,5]x[0,1.3]
  saddle    I + grad f grad f^T, f = x^2 - y^2, on [-1.3,1.3]^2
  sshock    |Hessian| of 3/4 tanh(2(sin 5y - 3x)), eigen-sizes clamped to [0.005, 0.2], aspect
            <= 50, on [-1,1]^2
  constant  diag(1, 16) on [0,2]^2 (`--metric constant:s,0,16s`), aspect 4: the one case where
            cvmesh's default takes the energy's Voronoi cells in the metric itself

Runs per case:
  cvmesh    the CLI: `cvmesh quad --domain-box ... --metric builtin:NAME:s -o OUT.msh`, default
            options, one thread; time = the process's wall time (write included).
  gmsh-a8   Mesh.Algorithm 8 (Frontal-Delaunay for quads), RecombineAll 1, RecombinationAlgorithm
            1 (Blossom), the scalar size h = (det(s g))^(-1/4) through the size callback.
  gmsh-bamg Mesh.Algorithm 7 (BAMG) with the tensor s g as a MathEvalAniso background field
            (edges of unit length in it), RecombineAll 1, Blossom.
  Gmsh: one thread, no size from points, curvature or boundary; time = generate(2) (wall).

CVM_BENCH_QUAD_FLAGS adds flags to the cvmesh command (e.g. "--mean-metric-voronoi 1");
CVM_BENCH_QUAD_CASES=a,b runs only those cases.
CVM_BENCH_QUAD_SVG=DIR also writes each mesh as DIR/CASE_MESHER.svg (quads blue, triangles red;
optionally only the window CVM_BENCH_QUAD_SVG_WINDOW=x0,y0,x1,y1).

The measure (one function for every mesh; nothing read from a mesher's own report):
  quads %          quads / cells, by count
  dev mean/P95     |corner angle - 90| in metric space, g at the quad's vertex mean, over every
                   corner of every quad (degrees)
  align mean/P95   the Euclidean angle between each quad edge and the nearer eigenvector of g at
                   the edge midpoint, folded to [0, 45] (degrees; isotropic g: the axes)
  L_M in range     % of the mesh's edges (all cells) with metric length in [1/sqrt 2, sqrt 2],
                   the length by 4-point Gauss-Legendre along the edge
  honours          "yes" when the mesh's L_M in range is >= 90% and its alignment mean is below
                   the 22.5 deg of edges at random angles by half (a yes/no read of the issue's
                   "whether each peer honoured the anisotropy")

Times are wall seconds of one run on a machine that may be shared: indicative only.

usage: bench_quad.py BUILD DOMAINS   (make bench calls it through run.sh; DOMAINS unused)
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
NTARGET = float(os.environ.get("CVM_BENCH_QUAD_N", "2500"))
CASES = [("identity", (0.0, 0.0, 4.0, 4.0)), ("stretch", (0.0, 0.0, 5.0, 1.3)),
         ("saddle", (-1.3, -1.3, 1.3, 1.3)), ("sshock", (-1.0, -1.0, 1.0, 1.0)),
         ("constant", (0.0, 0.0, 2.0, 2.0))]
ONLY = [c for c in os.environ.get("CVM_BENCH_QUAD_CASES", "").split(",") if c]


# ---- the metrics, written here from their definitions (not read from cvmesh) ----

def _sshock(x, y):
    z = 2 * (np.sin(5 * y) - 3 * x)
    t = np.tanh(z)
    u = 1 - t * t
    f1, f2 = 0.75 * u, -1.5 * t * u                      # f'(z), f''(z) of f = 3/4 tanh z
    zx, zy, zyy = -6.0, 10 * np.cos(5 * y), -50 * np.sin(5 * y)
    hxx, hxy, hyy = f2 * zx * zx, f2 * zx * zy, f2 * zy * zy + f1 * zyy
    H = np.stack([np.stack([hxx, hxy], -1), np.stack([hxy, hyy], -1)], -2)
    lam, Q = np.linalg.eigh(H)
    a = np.abs(lam)
    with np.errstate(divide="ignore"):
        h = np.where(a > 0, 1 / np.sqrt(a), 0.2)
    h = np.clip(h, 0.005, 0.2)
    hmax, hmin = h.max(-1), h.min(-1)
    h = np.where(h == hmax[..., None], np.minimum(h, 50 * hmin[..., None]), h)
    mu = 1 / h ** 2
    return np.einsum("...ik,...k,...jk->...ij", Q, mu, Q)


def metric(name, scale, xy):
    """s g at points xy (n, 2): (n, 2, 2)."""
    x, y = xy[:, 0], xy[:, 1]
    g = np.zeros((len(xy), 2, 2))
    if name == "identity":
        g[:, 0, 0] = g[:, 1, 1] = 1
    elif name == "stretch":
        g[:, 0, 0] = 1
        g[:, 1, 1] = 1 + 4 * y * y
    elif name == "saddle":
        gx, gy = 2 * x, -2 * y
        g[:, 0, 0], g[:, 0, 1], g[:, 1, 1] = 1 + gx * gx, gx * gy, 1 + gy * gy
        g[:, 1, 0] = g[:, 0, 1]
    elif name == "sshock":
        g = _sshock(x, y)
    elif name == "constant":
        g[:, 0, 0], g[:, 1, 1] = 1, 16
    return scale * g


def metric_area(name, box, n=400):
    """Int sqrt(det g) over the box (midpoint rule on an n x n grid), g unscaled."""
    x0, y0, x1, y1 = box
    hx, hy = (x1 - x0) / n, (y1 - y0) / n
    X, Y = np.meshgrid(x0 + hx * (np.arange(n) + 0.5), y0 + hy * (np.arange(n) + 0.5))
    g = metric(name, 1.0, np.column_stack([X.ravel(), Y.ravel()]))
    return np.sqrt(np.linalg.det(g)).sum() * hx * hy


# ---- the one measure ----

GL_T = (np.array([-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                  0.8611363115940526]) + 1) / 2
GL_W = np.array([0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                 0.3478548451374538]) / 2


def measure(name, scale, xy, tris, quads):
    """The columns for one mesh: points xy (n, 2), triangles (nt, 3), quads (nq, 4)."""
    nt, nq = len(tris), len(quads)
    r = {"vertices": len(xy), "quads_pct": 100.0 * nq / max(1, nt + nq)}
    if nq:
        P = xy[quads]                                             # (nq, 4, 2)
        g = metric(name, scale, P.mean(axis=1))
        u = np.roll(P, 1, axis=1) - P                             # to the previous corner
        v = np.roll(P, -1, axis=1) - P                            # to the next corner
        uv = np.einsum("qki,qij,qkj->qk", u, g, v)
        uu = np.einsum("qki,qij,qkj->qk", u, g, u)
        vv = np.einsum("qki,qij,qkj->qk", v, g, v)
        ang = np.degrees(np.arccos(np.clip(uv / np.sqrt(uu * vv), -1, 1)))
        dev = np.abs(ang - 90).ravel()
        r["dev_mean"], r["dev_p95"] = dev.mean(), np.percentile(dev, 95)
        a, b = P.reshape(-1, 2), np.roll(P, -1, axis=1).reshape(-1, 2)
        gm = metric(name, scale, 0.5 * (a + b))
        _, Q = np.linalg.eigh(gm)
        e = b - a
        e = e / np.linalg.norm(e, axis=1)[:, None]
        c = np.abs(np.einsum("ni,ni->n", e, Q[:, :, 0]))         # |cos| to the first eigenvector
        th = np.degrees(np.arccos(np.clip(c, 0, 1)))              # in [0, 90]
        al = np.minimum(th, 90 - th)                              # nearer eigenvector: [0, 45]
        r["align_mean"], r["align_p95"] = al.mean(), np.percentile(al, 95)
    else:
        r["dev_mean"] = r["dev_p95"] = r["align_mean"] = r["align_p95"] = float("nan")
    edges = []
    for cells, k in ((tris, 3), (quads, 4)):
        if len(cells):
            for j in range(k):
                edges.append(np.column_stack([cells[:, j], cells[:, (j + 1) % k]]))
    E = np.unique(np.sort(np.vstack(edges), axis=1), axis=0)
    a, b = xy[E[:, 0]], xy[E[:, 1]]
    d = b - a
    L = np.zeros(len(E))
    for t, w in zip(GL_T, GL_W):
        gm = metric(name, scale, a + t * d)
        L += w * np.sqrt(np.einsum("ni,nij,nj->n", d, gm, d))
    inr = (L >= 1 / np.sqrt(2)) & (L <= np.sqrt(2))
    r["lm_pct"] = 100.0 * inr.mean()
    r["honours"] = "yes" if r["lm_pct"] >= 90 and r["align_mean"] <= 11.25 else "no"
    return r


# ---- cvmesh ----

def read_msh41(path):
    """Points and 0-based triangles and quads of an ASCII Gmsh 4.1 file (2D elements only)."""
    lines = open(path).read().split("\n")
    i, tags, xy, tris, quads = 0, [], [], [], []
    while i < len(lines):
        s = lines[i].strip()
        if s == "$Nodes":
            nb = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nb):
                n = int(lines[i].split()[3])
                tags += [int(t) for t in lines[i + 1:i + 1 + n]]
                xy += [[float(c) for c in l.split()[:2]] for l in lines[i + 1 + n:i + 1 + 2 * n]]
                i += 1 + 2 * n
            continue
        if s == "$Elements":
            nb = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nb):
                h = lines[i].split()
                et, n = int(h[2]), int(h[3])
                rows = [[int(t) for t in l.split()[1:]] for l in lines[i + 1:i + 1 + n]]
                if et == 2:
                    tris += rows
                elif et == 3:
                    quads += rows
                i += 1 + n
            continue
        i += 1
    index = {t: k for k, t in enumerate(tags)}
    remap = np.vectorize(index.get)
    xy = np.array(xy)
    T = remap(np.array(tris)) if tris else np.zeros((0, 3), int)
    Q = remap(np.array(quads)) if quads else np.zeros((0, 4), int)
    used = np.unique(np.concatenate([T.ravel(), Q.ravel()]))
    return xy, T, Q, len(used)


def run_cvmesh(name, box, scale, tmp):
    out = os.path.join(tmp, "%s.msh" % name)
    spec = ("constant:%.17g,0,%.17g" % (scale, 16 * scale) if name == "constant"
            else "builtin:%s:%.17g" % (name, scale))
    cmd = [os.path.join(BUILD, "bin", "cvmesh"), "quad", "--domain-box",
           ",".join("%.17g" % v for v in box), "--metric", spec, "-o", out, "--quality"]
    cmd += os.environ.get("CVM_BENCH_QUAD_FLAGS", "").split()
    env = dict(os.environ, OMP_NUM_THREADS="1")
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    t = time.perf_counter() - t0
    if p.returncode != 0:
        raise SystemExit("bench_quad: %s failed: %s" % (" ".join(cmd), p.stderr.strip()))
    xy, T, Q, _ = read_msh41(out)
    extra = {}
    for line in p.stdout.splitlines() + p.stderr.splitlines():
        low = line.lower()
        if "grad" in low and "gradient" not in extra:
            extra["gradient"] = line.strip()
        if "iteration" in low and "iterations" not in extra:
            extra["iterations"] = line.strip()
    return xy, T, Q, t, extra


# ---- Gmsh ----

def _gmsh_elements(gmsh):
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xy = coords.reshape(-1, 3)[:, :2]
    index = {int(t): k for k, t in enumerate(tags)}
    out = []
    for et, k in ((2, 3), (3, 4)):
        _, nodes = gmsh.model.mesh.getElementsByType(et)
        out.append(np.array([index[int(t)] for t in nodes], dtype=int).reshape(-1, k))
    used = np.unique(np.concatenate([out[0].ravel(), out[1].ravel()]))
    # keep only the nodes the cells use (Gmsh keeps none other in 2D, but be sure)
    remap = -np.ones(len(xy), int)
    remap[used] = np.arange(len(used))
    return xy[used], remap[out[0]], remap[out[1]]


def _aniso_expr(name, s):
    """(M11, M12, M22) expressions of s g for MathEvalAniso."""
    S = "%.17g" % s
    if name == "identity":
        return S, "0", S
    if name == "stretch":
        return S, "0", "%s*(1+4*y*y)" % S
    if name == "saddle":
        return "%s*(1+4*x*x)" % S, "%s*(-4*x*y)" % S, "%s*(1+4*y*y)" % S
    if name == "constant":
        return S, "0", "%.17g" % (16 * s)
    return None


def run_gmsh(gmsh, name, box, scale, algo):
    x0, y0, x1, y1 = box
    gmsh.clear()
    gmsh.model.add(name)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.model.occ.addRectangle(x0, y0, 0, x1 - x0, y1 - y0)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
    gmsh.option.setNumber("Mesh.Algorithm", algo)
    if algo == 8:
        def size(dim, tag, x, y, z, lc):
            g = metric(name, scale, np.array([[x, y]]))[0]
            return float(np.linalg.det(g) ** -0.25)
        gmsh.model.mesh.setSizeCallback(size)
    else:
        f = gmsh.model.mesh.field.add("MathEvalAniso")
        ex = _aniso_expr(name, scale)
        if ex is None:
            # sshock: |Hessian| with clamped eigen-sizes has no closed MathEval form; the
            # tensor is sampled at the nodes of a fine grid into a list-based tensor view
            # (TT: 3 nodes x 9 components) and read through a PostView field.
            m = 160
            X, Y = np.meshgrid(np.linspace(x0, x1, m + 1), np.linspace(y0, y1, m + 1))
            P = np.column_stack([X.ravel(), Y.ravel()])
            G = metric(name, scale, P)
            data = []
            for j in range(m):
                for i in range(m):
                    a, b, c, d = j * (m + 1) + i, j * (m + 1) + i + 1, \
                        (j + 1) * (m + 1) + i + 1, (j + 1) * (m + 1) + i
                    for tri in ((a, b, c), (a, c, d)):
                        data += [P[k, 0] for k in tri] + [P[k, 1] for k in tri] + [0, 0, 0]
                        for k in tri:
                            g = G[k]
                            data += [g[0, 0], g[0, 1], 0, g[1, 0], g[1, 1], 0, 0, 0, 1.0]
            gmsh.model.mesh.field.remove(f)
            v = gmsh.view.add("metric")
            gmsh.view.addListData(v, "TT", 2 * m * m, data)
            f = gmsh.model.mesh.field.add("PostView")
            gmsh.model.mesh.field.setNumber(f, "ViewTag", v)
        else:
            for key, e in zip(("M11", "M12", "M22"), ex):
                gmsh.model.mesh.field.setString(f, key, e)
            gmsh.model.mesh.field.setString(f, "M13", "0")
            gmsh.model.mesh.field.setString(f, "M23", "0")
            gmsh.model.mesh.field.setString(f, "M33", "1")
        gmsh.model.mesh.field.setAsBackgroundMesh(f)
    t0 = time.perf_counter()
    gmsh.model.mesh.generate(2)
    t = time.perf_counter() - t0
    xy, T, Q = _gmsh_elements(gmsh)
    if algo == 8:
        gmsh.model.mesh.removeSizeCallback()
    return xy, T, Q, t


def write_svg(path, xy, T, Q, width=800):
    """The cells as an SVG picture: quads light blue, triangles red, edges black."""
    win = os.environ.get("CVM_BENCH_QUAD_SVG_WINDOW")
    if win:
        x0, y0, x1, y1 = (float(v) for v in win.split(","))
    else:
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    sc = width / (x1 - x0)
    height = int((y1 - y0) * sc) + 1
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">' % (width, height),
           '<rect width="100%" height="100%" fill="white"/>']
    for cells, fill in ((Q, "#cfe0f0"), (T, "#f08a8a")):
        for c in cells:
            P = xy[c]
            if (P[:, 0].max() < x0 or P[:, 0].min() > x1 or P[:, 1].max() < y0
                    or P[:, 1].min() > y1):
                continue
            pts = " ".join("%.2f,%.2f" % ((x - x0) * sc, (y1 - y) * sc) for x, y in P)
            out.append('<polygon points="%s" fill="%s" stroke="black" stroke-width="0.4"/>'
                       % (pts, fill))
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out))


def main():
    try:
        if os.environ.get("CVM_BENCH_NO_GMSH"):
            raise ImportError("CVM_BENCH_NO_GMSH")
        import gmsh
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gver = gmsh.option.getString("General.Version")
    except Exception as e:  # no gmsh or its X11/GL libraries: cvmesh rows only
        print("# bench_quad: gmsh unavailable (%s): cvmesh rows only" % e)
        gmsh, gver = None, "-"
    print("# bench_quad: quad-dominant meshes in a metric, cvmesh quad vs Gmsh %s; target metric "
          "area N = %g; one measure for every mesh (dev: metric corner deviation from 90 deg; "
          "align: edge vs nearer eigenvector; L_M: %% of edges in [1/sqrt2, sqrt2]); wall "
          "seconds, one thread, one run" % (gver, NTARGET))
    hdr = "%-9s %-10s %9s %7s %7s %7s %7s %7s %7s %8s %8s" % (
        "case", "mesher", "scale", "verts", "quads%", "dev", "devP95", "align", "alP95", "L_M%",
        "time_s")
    print(hdr + "  honours")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, box in CASES:
            if ONLY and name not in ONLY:
                continue
            scale = NTARGET / metric_area(name, box)
            runs = []
            xy, T, Q, t, extra = run_cvmesh(name, box, scale, tmp)
            runs.append(("cvmesh", xy, T, Q, t))
            if gmsh is not None:
                for label, algo in (("gmsh-a8", 8), ("gmsh-bamg", 7)):
                    try:
                        xy, T, Q, t = run_gmsh(gmsh, name, box, scale, algo)
                    except Exception as e:
                        print("# bench_quad: %s %s failed: %s" % (name, label, e))
                        continue
                    runs.append((label, xy, T, Q, t))
            for label, xy, T, Q, t in runs:
                if os.environ.get("CVM_BENCH_QUAD_SVG"):
                    write_svg(os.path.join(os.environ["CVM_BENCH_QUAD_SVG"],
                                           "%s_%s.svg" % (name, label)), xy, T, Q)
                r = measure(name, scale, xy, T, Q)
                row = "%-9s %-10s %9.4g %7d %7.1f %7.1f %7.1f %7.1f %7.1f %8.1f %8.2f  %s" % (
                    name, label, scale, r["vertices"], r["quads_pct"], r["dev_mean"],
                    r["dev_p95"], r["align_mean"], r["align_p95"], r["lm_pct"], t,
                    r["honours"])
                print(row)
                rows.append((name, label, scale, r, t))
            for k in ("gradient", "iterations"):
                if k in extra:
                    print("#   cvmesh %s: %s" % (name, extra[k]))
            sys.stdout.flush()
    if gmsh is not None:
        gmsh.finalize()
    return rows


if __name__ == "__main__":
    main()
