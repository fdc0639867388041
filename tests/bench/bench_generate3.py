#!/usr/bin/env python3
"""3D co-volume generation: `cvmesh mesh3` side by side with TetGen 1.5's
quality mesh (`-pq1.414a<V>`, V the mean tetrahedron volume of cvmesh's mesh,
so both have about as many tetrahedra) and Gmsh's HXT and Delaunay volume
meshers (the gmsh wheel, Mesh.Algorithm3D = 10 and 1, one thread, on the
surfaces as given, which Gmsh keeps: the .stl classified into one discrete
surface per shell, Mesh.MeshSizeMax = H, sizes otherwise Gmsh's own
interpolation from the surface, so its meshes are coarser; a crash of Gmsh is
reported as the row's error), on the same surfaces, in the same run.

Rows: the unit cube (8 x 8 squares per face) at uniform size 1/8, and at
1/16 (finer than its surface, which is used as given), the sphere of radius
0.5 in the box [-2, 2]^3 and the swept NACA 0012 wing slab, both graded from
their surfaces (size 0.5 and 1.0, grading 0.3); the last three rows again with
--remesh-planar (planar facets re-meshed at the 3D size first); then the
re-meshed surfaces again with --optimise (cvm_mesh_optimise_dual3(), defaults;
its seconds are "generate" + "optimise"); after each TetGen row of a surface as
given, cvmesh's optimiser on TetGen's mesh (`cvmesh optimise TETGEN.ele`: the
mesh read as it is, its seconds the optimiser's; again with --opt-slide-surface,
boundary vertices of smooth patches sliding on the surface); then the first
four again with each other free-space method (--freespace octree, refine;
cvmesh only). cvmesh rows also give the exact % of tetrahedra whose power vertex lies
strictly outside them, all and at the boundary (`--quality`, with the weights
of an optimised mesh: the numpy columns below ignore weights, so they describe
an optimised mesh's circumcentres, not its dual), and the % not compliant after
merging (CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT).
All meshes are measured here by the same numpy code from their .node/.ele
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
CASES += [(name + " optimise", surf, args + ["--optimise"], False)
          for name, surf, args in CASES[7:10]]
# Each free-space method on the first four surfaces (cvmesh rows only: the TetGen rows
# above are the peer at the lattice's density).
for _fs in ("octree", "refine"):
    CASES += [(name + " " + _fs, surf, args + ["--freespace", _fs], False)
              for name, surf, args in CASES[:4]]
CASES = [c if len(c) == 4 else c + (True,) for c in CASES]


GMSH_CODE = r"""
import json, math, sys, time
import numpy as np, gmsh
stl, hmax, out, algo = sys.argv[1], float(sys.argv[2]), sys.argv[3], int(sys.argv[4])
gmsh.initialize(['-noenv'])
gmsh.option.setNumber('General.Terminal', 0)
gmsh.option.setNumber('General.NumThreads', 1)
gmsh.merge(stl)
gmsh.model.mesh.classifySurfaces(math.pi, True, False)  # one surface per shell
def extent(tag):
    b = gmsh.model.getBoundingBox(2, tag)
    return (b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2])
surfs = sorted((e[1] for e in gmsh.model.getEntities(2)), key=extent, reverse=True)
gmsh.model.geo.addVolume([gmsh.model.geo.addSurfaceLoop([s]) for s in surfs])
gmsh.model.geo.synchronize()
gmsh.option.setNumber('Mesh.Algorithm3D', algo)
gmsh.option.setNumber('Mesh.MeshSizeMax', hmax)
t0 = time.perf_counter()
gmsh.model.mesh.generate(3)
t = time.perf_counter() - t0
tags, xyz, _ = gmsh.model.mesh.getNodes()
xyz = xyz.reshape(-1, 3)
_, nodes = gmsh.model.mesh.getElementsByType(4)
pos = np.zeros(int(tags.max()) + 1, int)
pos[tags.astype(int)] = np.arange(len(tags))
tet = pos[nodes.astype(int)].reshape(-1, 4)
gmsh.finalize()
with open(out + '.node', 'w') as f:
    f.write('%d 3 0 0\n' % len(xyz))
    f.writelines('%d %.17g %.17g %.17g\n' % (i, p[0], p[1], p[2]) for i, p in enumerate(xyz))
with open(out + '.ele', 'w') as f:
    f.write('%d 4 0\n' % len(tet))
    f.writelines('%d %d %d %d %d\n' % (i, q[0], q[1], q[2], q[3]) for i, q in enumerate(tet))
print(json.dumps({"seconds": t}))
"""


def gmsh_row(name, src, hmax, tmp, algo):
    """Gmsh's volume mesher algo (10 HXT, 1 Delaunay) on the surface src (its .stl),
    in a child process (a crash of Gmsh is a row's error, not the bench's)."""
    stl = os.path.splitext(src)[0] + ".stl"
    base = os.path.join(tmp, "gm")
    label = "gmsh " + {10: "hxt", 1: "delaunay"}[algo]
    r = subprocess.run([sys.executable, "-c", GMSH_CODE, stl, str(hmax), base, str(algo)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        err = r.stderr.strip().splitlines()
        why = "killed by signal %d" % -r.returncode if r.returncode < 0 else \
            (err[-1] if err else "exit %d" % r.returncode)
        return {"case": name, "mesher": label, "error": why}
    info = json.loads(r.stdout.strip().splitlines()[-1])
    return dict(case=name, mesher=label, seconds=round(info["seconds"], 3),
                **measure(*read_mesh(base)))


def optimise_row(name, base, tmp, extra=()):
    """cvmesh's optimiser on a mesh made elsewhere (`cvmesh optimise BASE.ele`): the
    exact outside and non-compliant shares its --quality prints, the optimiser's
    seconds, and the numpy measures of the result."""
    out = os.path.join(tmp, "opt")
    label = " ".join(("tetgen + cvmesh optimise",) + tuple(extra))
    r = subprocess.run([CLI, "optimise", base + ".ele", "-o", out + ".node", "--timings",
                        "--quality", "--quiet"] + list(extra), capture_output=True, text=True)
    if r.returncode != 0:
        return {"case": name, "mesher": label, "error": r.stderr.strip()}
    lines = r.stdout.splitlines()
    val = {l.split(":")[0]: float(l.split()[1]) for l in lines if l.startswith("optimise:")}
    k = [i for i, l in enumerate(lines) if l.startswith("circumcentre outside")][0]
    nc = [float(l.split()[-2]) for l in lines if l.startswith("non-compliant after merging")][0]
    bef = [float(l.split()[-2]) for l in lines if l.startswith("outside before optimising")][0]
    return dict(case=name, mesher=label, seconds=round(val["optimise"], 3),
                exact_outside_before_pct=bef,
                exact_outside_pct=[float(lines[k].split()[-2]), float(lines[k + 1].split()[-2])],
                noncompliant_after_merge_pct=nc, **measure(*read_mesh(out)))


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
        t = sum(float(l.split()[1]) for l in r.stdout.splitlines()
                if l.startswith("generate:") or l.startswith("optimise:"))
        nc = [float(l.split()[-2]) for l in r.stdout.splitlines()
              if l.startswith("non-compliant after merging")][0]
        lines = r.stdout.splitlines()
        k = [i for i, l in enumerate(lines) if l.startswith("circumcentre outside")][0]
        exact = [float(lines[k].split()[-2]), float(lines[k + 1].split()[-2])]
        row = measure(*read_mesh(base))
        print(json.dumps(dict(case=name, mesher="cvmesh mesh3", seconds=round(t, 3),
                              exact_outside_pct=exact, noncompliant_after_merge_pct=nc, **row)))
        if peer and not any(a.startswith("--remesh") for a in args):  # Gmsh keeps the surface
            for algo in (10, 1):
                print(json.dumps(gmsh_row(name, src, float(args[args.index("--size") + 1]), tmp,
                                          algo)))
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
            if not any(a.startswith("--remesh") for a in args):
                for extra in ((), ("--opt-slide-surface",)):
                    print(json.dumps(optimise_row(name, tb, tmp, extra)))


if __name__ == "__main__":
    main()
