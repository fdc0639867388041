#!/usr/bin/env python3
"""quad_pairs.py - why triangles stay unpaired in a cvmesh quad mesh: runs `cvmesh quad` twice with
the same options (deterministic: the same sites), once with --recombine none (the triangles) and
once as given (the cells), and classifies every interior edge of the triangulation (pair not
strictly convex / metric quality below the threshold / kept) and every triangle left unmatched
(no candidate pair at all, or its candidates taken by neighbours). Quality as the recombiner's:
1 - max |corner - 90| / 90 in the metric at the quad's vertex mean, measured here in numpy.

usage: quad_pairs.py BUILD NAME SCALE [extra cvmesh quad flags]
   e.g. quad_pairs.py build saddle 16
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from bench_quad import CASES, metric, read_msh41  # noqa: E402


def run(build, name, box, scale, flags, out):
    spec = ("constant:%.17g,0,%.17g" % (scale, 16 * scale) if name == "constant"
            else "builtin:%s:%.17g" % (name, scale))
    cmd = [os.path.join(build, "bin", "cvmesh"), "quad", "--domain-box",
           ",".join("%.17g" % v for v in box), "--metric", spec, "-o", out] + flags
    subprocess.run(cmd, check=True, capture_output=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    return read_msh41(out)


def quality(name, scale, P):
    g = metric(name, scale, P.mean(axis=1))
    u = np.roll(P, 1, axis=1) - P
    v = np.roll(P, -1, axis=1) - P
    uv = np.einsum("qki,qij,qkj->qk", u, g, v)
    uu = np.einsum("qki,qij,qkj->qk", u, g, u)
    vv = np.einsum("qki,qij,qkj->qk", v, g, v)
    ang = np.degrees(np.arccos(np.clip(uv / np.sqrt(uu * vv), -1, 1)))
    return 1 - np.abs(ang - 90).max(axis=1) / 90


def cross(o, a, b):
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - \
        (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0])


def main():
    build, name, scale = sys.argv[1], sys.argv[2], float(sys.argv[3])
    flags = sys.argv[4:]
    box = dict(CASES)[name]
    qmin = 0.5
    with tempfile.TemporaryDirectory() as tmp:
        xy, T, _, _ = run(build, name, box, scale, flags + ["--recombine", "none"],
                          os.path.join(tmp, "t.msh"))
        xy2, T2, Q2, _ = run(build, name, box, scale, flags, os.path.join(tmp, "q.msh"))
    assert np.array_equal(xy, xy2)
    nt = len(T)
    side = {}
    for t in range(nt):
        for k in range(3):
            a, b = T[t, k], T[t, (k + 1) % 3]
            side[(a, b)] = (t, T[t, (k + 2) % 3])
    pairs = []  # (t1, t2, convex, q)
    for (a, b), (t1, c) in side.items():
        if (b, a) in side and a < b:
            t2, d = side[(b, a)]
            P = xy[[a, d, b, c]]
            convex = cross(P[3], P[0], P[1]) > 0 and cross(P[1], P[2], P[3]) > 0
            q = quality(name, scale, P[None])[0] if convex else 0.0
            pairs.append((t1, t2, convex, q))
    pairs = np.array(pairs)
    nc = int((pairs[:, 2] == 0).sum())
    nlow = int(((pairs[:, 2] == 1) & (pairs[:, 3] < qmin)).sum())
    good = pairs[pairs[:, 3] >= qmin]
    print("%s x%g: %d points, %d triangles, %d interior edges: %d not convex, %d convex below "
          "%.2f, %d candidate pairs" % (name, scale, len(xy), nt, len(pairs), nc, nlow, qmin,
                                        len(good)), )
    # which triangles were matched: a quad's vertex set contains a triangle's
    qsets = [frozenset(q) for q in Q2]
    tri_in = set()
    tset = {frozenset(t): i for i, t in enumerate(T)}
    unmatched = set(range(nt))
    for q in Q2:
        for k in range(4):
            s = frozenset([q[k], q[(k + 1) % 4], q[(k + 2) % 4]])
            if s in tset:
                unmatched.discard(tset[s])
    deg = np.zeros(nt, int)
    for t1, t2, _, _ in good:
        deg[int(t1)] += 1
        deg[int(t2)] += 1
    un = np.array(sorted(unmatched), int)
    print("  quads %d (%.1f%% of cells), triangles left %d: %d with no candidate pair, %d whose "
          "candidates all went to neighbours; quality of kept quads: mean %.3f" % (
              len(Q2), 100.0 * len(Q2) / (len(Q2) + len(un)), len(un), int((deg[un] == 0).sum()),
              int((deg[un] > 0).sum()), quality(name, scale, xy[Q2]).mean() if len(Q2) else 0))
    # the unmatched triangles with no candidate: why (their best pair)
    best = np.full(nt, -1.0)
    conv = np.zeros(nt, int)
    for t1, t2, c, q in pairs:
        for t in (int(t1), int(t2)):
            best[t] = max(best[t], q)
            conv[t] += int(c)
    lone = un[deg[un] == 0]
    if len(lone):
        print("  of those with none: %d have no convex pair; best quality of the others: %s" % (
            int((conv[lone] == 0).sum()),
            np.round(np.percentile(best[lone][conv[lone] > 0], [10, 50, 90]), 3)
            if (conv[lone] > 0).any() else "-"))
    x0, y0, x1, y1 = box
    onb = (np.isclose(xy[:, 0], x0) | np.isclose(xy[:, 0], x1) | np.isclose(xy[:, 1], y0) |
           np.isclose(xy[:, 1], y1))
    touch = onb[T[un]].any(axis=1)
    print("  triangles left touching the boundary: %d of %d (boundary points %d of %d)" % (
        int(touch.sum()), len(un), int(onb.sum()), len(xy)))
    hist = np.histogram(pairs[pairs[:, 2] == 1, 3], bins=[0, .2, .3, .4, .5, .6, .7, .8, .9, 1.01])
    print("  convex-pair quality histogram:", dict(zip([round(b, 1) for b in hist[1][:-1]],
                                                      hist[0].tolist())))


if __name__ == "__main__":
    main()
