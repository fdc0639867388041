#!/usr/bin/env python3
"""3D co-volume generation: `cvmesh mesh3` side by side with TetGen 1.5's
quality mesh (`-pq1.414a<V>`, V the mean tetrahedron volume of cvmesh's mesh,
so both have about as many tetrahedra), on the same surfaces, in the same run.

Rows: the unit cube (8 x 8 squares per face) at uniform size 1/8, and at
1/16 (finer than its surface, which is used as given), the sphere of radius
0.5 in the box [-2, 2]^3 and the swept NACA 0012 wing slab, both graded from
their surfaces (size 0.5 and 1.0, grading 0.3); the last three rows again with
--remesh-planar (planar facets re-meshed at the 3D size first); then the first
four again with each other free-space method (--freespace octree, refine;
cvmesh only). cvmesh rows also give the % of tetrahedra not compliant after
merging (`--quality`, exact, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT).
Both meshes are measured here by the same numpy code from their .node/.ele
files: tetrahedra, % whose circumcentre lies outside them (all, and those
with a face on the boundary; floating point, as CVM_MEASURE 704/705), the
smallest dihedral angle, and the wall time of the meshing call (cvmesh:
`--timings` "generate", read and write excluded; TetGen: tetrahedralize()).
Usage: bench_generate3.py BUILD [DOMAINS]; the surfaces come from
BUILD/data3d (`make data3d`).
"""
import json, os, subprocess, sys, tempfile
import numpy as np

BUILD = sys.argv[1]
CLI = os.path.join(BUILD, "bin", "cvmesh")
TETGEN = os.path.join(BUILD, "bench", "bench_tetgen_quality")
DATA3D = os.path.join(BUILD, "data3d")

CASES = [
    ("cube h=1/8", "cube.poly", ["--size", "0.125", "--uniform"]),
    ("cube h=1/16", "cube.poly", ["--size", "0.0625", "--uniform"]),
    ("sphere_in_box graded", "sphere_in_box.poly", ["--size", "0.5", "--grading", "0.3"]),
    ("wing_slab graded", "wing_slab.poly", ["--size", "1.0", "--grading", "0.3"]),
    ("cube h=1/16 remesh-planar", "cube.poly", ["--size", "0.0625", "--uniform", "--remesh-planar"]),
    ("sphere_in_box graded remesh-planar", "sphere_in_box.poly",
     ["--size", "0.5", "--grading", "0.3", "--remesh-planar"]),
    ("wing_slab graded remesh-planar", "wing_slab.poly",
     ["--size", "1.0", "--grading", "0.3", "--remesh-planar"]),
    ("cube h=1/8 remesh-surface", "cube.poly", ["--size", "0.125", "--uniform", "--remesh-surface"]),
    ("sphere_in_box graded remesh-surface", "sphere_in_box.poly",
     ["--size", "0.5", "--grading", "0.3", "--remesh-surface"]),
    ("wing_slab graded remesh-surface", "wing_slab.poly",
     ["--size", "1.0", "--grading", "0.3", "--remesh-surface"]),
]
# Each free-space method on the first four surfaces (cvmesh rows only: the TetGen rows
# above are the peer at the lattice's density).
for _fs in ("octree", "refine"):
    CASES += [(name + " " + _fs, surf, args + ["--freespace", _fs], False)
              for name, surf, args in CASES[:4]]
CASES = [c if len(c) == 4 else c + (True,) for c in CASES]


def read_mesh(base):
    def rows(path):
        with open(path) as f:
            lines = [l.split("#")[0].split() for l in f]
        lines = [l for l in lines if l]
        return lines[0], lines[1:]
    head, r = rows(base + ".node")
    ids = np.array([int(l[0]) for l in r])
    xyz = np.array([[float(v) for v in l[1:4]] for l in r])
    pos = np.empty(ids.max() + 1, int)
    pos[ids] = np.arange(len(ids))
    _, r = rows(base + ".ele")
    tet = pos[np.array([[int(v) for v in l[1:5]] for l in r])]
    return xyz, tet


def measure(xyz, tet):
    p = xyz[tet]
    a = p[:, 0]
    m = np.stack([p[:, 1] - a, p[:, 2] - a, p[:, 3] - a], 1)
    rhs = 0.5 * np.einsum("tij,tij->ti", m, m)
    c = np.linalg.solve(m, rhs[..., None])[..., 0]
    # barycentric coordinates of a + c in the tetrahedron: solve m^T l = c
    lam = np.linalg.solve(np.transpose(m, (0, 2, 1)), c[..., None])[..., 0]
    lam = np.concatenate([1 - lam.sum(1, keepdims=True), lam], 1)
    outside = (lam < 0).any(1)
    faces = np.sort(np.concatenate([tet[:, [1, 2, 3]], tet[:, [0, 2, 3]], tet[:, [0, 1, 3]],
                                    tet[:, [0, 1, 2]]]), 1)
    _, inv, cnt = np.unique(faces, axis=0, return_inverse=True, return_counts=True)
    inv = inv.reshape(-1)
    bnd = (cnt[inv] == 1).reshape(4, -1).any(0)
    # dihedral angles from the face normals
    idx = [(0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)]
    dmin = 180.0
    for i, j, k, l in idx:
        e = p[:, j] - p[:, i]
        n1 = np.cross(e, p[:, k] - p[:, i])
        n2 = np.cross(e, p[:, l] - p[:, i])
        cosv = -np.einsum("ti,ti->t", n1, n2) / (np.linalg.norm(n1, axis=1) * np.linalg.norm(n2, axis=1))
        ang = 180 - np.degrees(np.arccos(np.clip(cosv, -1, 1)))
        dmin = min(dmin, float(ang.min()))
    vol = np.abs(np.einsum("ti,ti->t", m[:, 0], np.cross(m[:, 1], m[:, 2]))) / 6
    return {
        "tetrahedra": int(len(tet)),
        "outside_pct": round(100.0 * outside.mean(), 2),
        "outside_boundary_pct": round(100.0 * outside[bnd].mean(), 2),
        "min_dihedral_deg": round(dmin, 2),
        "volume": float(vol.sum()),
        "mean_volume": float(vol.mean()),
    }


def main():
    if not os.path.exists(TETGEN):
        print("# bench_generate3: no %s (tests/bench/run.sh builds it when tetgen.h exists):"
              " cvmesh rows only" % TETGEN)
    tmp = tempfile.mkdtemp(prefix="bench_g3_")
    for name, surf, args, peer in CASES:
        src = os.path.join(DATA3D, surf)
        base = os.path.join(tmp, "cvm")
        r = subprocess.run([CLI, "mesh3", src] + args + ["-o", base + ".node", "--timings",
                                                         "--quality"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            print(json.dumps({"case": name, "mesher": "cvmesh", "error": r.stderr.strip()}))
            continue
        t = [float(l.split()[1]) for l in r.stdout.splitlines() if l.startswith("generate:")][0]
        nc = [float(l.split()[-2]) for l in r.stdout.splitlines()
              if l.startswith("non-compliant after merging")][0]
        row = measure(*read_mesh(base))
        print(json.dumps(dict(case=name, mesher="cvmesh mesh3", seconds=round(t, 3),
                              noncompliant_after_merge_pct=nc, **row)))
        if peer and os.path.exists(TETGEN):
            sw = "pq1.414a%.6gQ" % row["mean_volume"]
            tb = os.path.join(tmp, "tg")
            r = subprocess.run([TETGEN, src, sw, tb], capture_output=True, text=True)
            if r.returncode != 0:
                print(json.dumps({"case": name, "mesher": "tetgen", "error": r.stderr.strip()}))
                continue
            info = json.loads(r.stdout.strip().splitlines()[-1])
            row2 = measure(*read_mesh(tb))
            print(json.dumps(dict(case=name, mesher="tetgen -" + sw, seconds=round(info["seconds"], 3),
                                  **row2)))


if __name__ == "__main__":
    main()
