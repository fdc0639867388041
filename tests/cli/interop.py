"""interop.py CLI TMPDIR - cvmesh against the real clients, both ways.

cvmesh -> client: the cvmesh program writes a mesh as .vtu in each encoding
(ascii, binary, zlib) and as .msh; meshio (and VTK, when the vtk wheel is
installed) must read the same points, triangles and cell data.
client -> cvmesh: meshio writes that mesh as .vtu (ascii, base64, zlib),
legacy .vtk (ascii, binary) and Gmsh 2.2 / 4.1 (ascii, binary); VTK writes
it with its XML writer in every data mode and with its legacy writers; cvmesh
must read each back to exactly the same triangles. A Gmsh domain of lines
and points from meshio is triangulated and refined with its physical tags as
markers. A sheared grid that meshio writes (not Delaunay) is flipped and
optimised. The 3D power dual of a BCC lattice (--dual, VTK_POLYHEDRON cells) is
read by meshio and VTK, and VTK's polyhedron volumes equal cvmesh's. Prints
one line per check; exits 1 when any failed.
Gmsh itself (the gmsh wheel) writes a square with a hole and named physical groups as
.msh 2.2 and 4.1, ASCII and binary; cvmesh reads each, and Gmsh reads cvmesh's .msh back
with the same names.
"""
import os
import random
import subprocess
import sys

import meshio
import numpy as np

CLI, TMP = sys.argv[1], sys.argv[2]
os.makedirs(TMP, exist_ok=True)
failed = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failed.append(what)


def run(*args):
    r = subprocess.run([CLI] + list(args), capture_output=True, text=True)
    return r.returncode, r.stderr.strip()


def tri_set(cells):
    return {tuple(sorted(int(v) for v in t)) for t in cells}


def path(name):
    return os.path.join(TMP, name)


# ---- a mesh made by cvmesh: Delaunay triangulation of random points -------
rng = random.Random(7)
with open(path("pts.node"), "w") as f:
    f.write("300 2 0 0\n")
    for i in range(300):
        f.write("%d %r %r\n" % (i, rng.random(), rng.random()))
code, err = run("triangulate", path("pts.node"), "-o", path("ref.vtu"))
check(code == 0, "cvmesh triangulate pts.node: " + err)
ref = meshio.read(path("ref.vtu"))
ref_pts = ref.points[:, :2]
ref_tris = tri_set(ref.cells_dict["triangle"])

# ---- cvmesh -> meshio / VTK -----------------------------------------------
try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    vtk = None
    print("note: the vtk wheel is not installed: VTK checks skipped")

for enc in ("ascii", "binary", "zlib"):
    out = path("cvm_%s.vtu" % enc)
    code, err = run("triangulate", path("pts.node"), "-o", out, "--vtu-encoding", enc)
    check(code == 0, "cvmesh writes .vtu %s: %s" % (enc, err))
    m = meshio.read(out)
    check(np.array_equal(m.points[:, :2], ref_pts), "meshio reads cvmesh .vtu %s: points" % enc)
    check(tri_set(m.cells_dict["triangle"]) == ref_tris, "meshio reads cvmesh .vtu %s: triangles" % enc)
    check(np.array_equal(m.cell_data["min_angle_deg"][0], ref.cell_data["min_angle_deg"][0]),
          "meshio reads cvmesh .vtu %s: min_angle_deg" % enc)
    if vtk:
        rd = vtk.vtkXMLUnstructuredGridReader()
        rd.SetFileName(out)
        rd.Update()
        g = rd.GetOutput()
        pts = vtk_to_numpy(g.GetPoints().GetData())[:, :2]
        conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
        ntri = sum(1 for c in range(g.GetNumberOfCells()) if g.GetCellType(c) == 5)
        check(rd.GetErrorCode() == 0 and np.array_equal(pts, ref_pts) and ntri == len(ref_tris)
              and tri_set(conn[:3 * ntri].reshape(-1, 3)) == ref_tris,
              "VTK %s reads cvmesh .vtu %s" % (vtk.vtkVersion.GetVTKVersion(), enc))
code, err = run("triangulate", path("pts.node"), "-o", path("cvm.msh"))
m = meshio.read(path("cvm.msh"))
check(code == 0 and tri_set(m.cells_dict["triangle"]) == ref_tris, "meshio reads cvmesh .msh")

# ---- meshio / VTK -> cvmesh ------------------------------------------------
mesh = meshio.Mesh(ref.points, [("triangle", ref.cells_dict["triangle"])])
written = []
for name, kw in (("mio_ascii.vtu", dict(binary=False)),
                 ("mio_base64.vtu", dict(binary=True, compression=None)),
                 ("mio_zlib.vtu", dict(binary=True, compression="zlib")),
                 ("mio_ascii.vtk", dict(binary=False)), ("mio_binary.vtk", dict(binary=True))):
    meshio.write(path(name), mesh, **kw)
    written.append(name)
gmesh = meshio.Mesh(ref_pts, [("triangle", ref.cells_dict["triangle"])])
for name, fmt, binary in (("mio22.msh", "gmsh22", False), ("mio22b.msh", "gmsh22", True),
                          ("mio41.msh", "gmsh", False), ("mio41b.msh", "gmsh", True)):
    meshio.write(path(name), gmesh, file_format=fmt, binary=binary)
    written.append(name)
if vtk:
    rd = vtk.vtkXMLUnstructuredGridReader()
    rd.SetFileName(path("ref.vtu"))
    rd.Update()
    g = rd.GetOutput()
    modes = {"vtk_ascii.vtu": lambda w: w.SetDataModeToAscii(),
             "vtk_binary.vtu": lambda w: (w.SetDataModeToBinary(), w.SetCompressorTypeToNone()),
             "vtk_binary_zlib.vtu": lambda w: (w.SetDataModeToBinary(), w.SetCompressorTypeToZLib()),
             "vtk_appended_raw.vtu": lambda w: (w.SetDataModeToAppended(), w.EncodeAppendedDataOff()),
             "vtk_appended_b64.vtu": lambda w: (w.SetDataModeToAppended(), w.EncodeAppendedDataOn(),
                                                w.SetCompressorTypeToNone()),
             "vtk_lz4.vtu": lambda w: (w.SetDataModeToAppended(), w.SetCompressorTypeToLZ4())}
    for name, setup in modes.items():
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetInputData(g)
        setup(w)
        w.SetFileName(path(name))
        w.Write()
        written.append(name)
    for name, binary in (("vtk_legacy_ascii.vtk", False), ("vtk_legacy_binary.vtk", True)):
        w = vtk.vtkUnstructuredGridWriter()
        w.SetInputData(g)
        if binary:
            w.SetFileTypeToBinary()
        w.SetFileName(path(name))
        w.Write()
        written.append(name)
for name in written:
    out = path("back_" + name.replace(".", "_") + ".vtu")
    code, err = run("triangulate", path(name), "-o", out)
    if name == "vtk_lz4.vtu":  # a compressor cvmesh does not read: a clear refusal
        check(code == 1 and "vtkLZ4DataCompressor" in err and not os.path.exists(out),
              "cvmesh refuses %s with a message: %s" % (name, err))
        continue
    ok = code == 0
    # meshio's ASCII .vtu and VTK's legacy ASCII writer print 12 and 11
    # significant digits: the points move by up to 1e-11, the triangles stay
    lossy = name in ("mio_ascii.vtu", "vtk_legacy_ascii.vtk")
    if ok:
        back = meshio.read(out)
        same = np.abs(back.points[:, :2] - ref_pts).max() < 1e-10 if lossy else \
            np.array_equal(back.points[:, :2], ref_pts)
        ok = tri_set(back.cells_dict["triangle"]) == ref_tris and same
    check(ok, "cvmesh reads %s: the same %spoints and triangles %s"
          % (name, "(to 1e-10) " if lossy else "", err))

# ---- a Gmsh domain (lines with physical tags, a point) --------------------
dom = meshio.Mesh(np.array([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0.5]], float),
                  [("line", np.array([[0, 1], [1, 2], [2, 3], [3, 0]])), ("vertex", np.array([[4]]))],
                  cell_data={"gmsh:physical": [np.array([1, 2, 3, 4]), np.array([9])],
                             "gmsh:geometrical": [np.array([1, 2, 3, 4]), np.array([1])]},
                  field_data={"bottom": np.array([1, 1]), "right": np.array([2, 1]),
                              "top": np.array([3, 1]), "left": np.array([4, 1]),
                              "centre": np.array([9, 0])})
names = {"bottom": 1, "right": 2, "top": 3, "left": 4}
for fmt, binary in (("gmsh22", True), ("gmsh22", False)):
    tag = "%s%s" % (fmt, " binary" if binary else "")
    meshio.write(path("domain.msh"), dom, file_format=fmt, binary=binary)
    code, err = run("refine", path("domain.msh"), "--size", "0.2", "-o", path("domain_out.msh"))
    check(code == 0, "cvmesh refine domain.msh (%s): %s" % (tag, err))
    if code == 0:
        d = meshio.read(path("domain_out.msh"))
        tags = set(int(t) for t in d.cell_data_dict["gmsh:physical"].get("line", []))
        check(len(d.cells_dict["triangle"]) > 50 and tags <= {1, 2, 3, 4} and len(tags) == 4,
              "refined Gmsh domain (%s) keeps its 4 boundary markers (%s)" % (tag, sorted(tags)))
        got = {k: (int(v[0]), int(v[1])) for k, v in d.field_data.items()}
        check(all(got.get(k) == (t, 1) for k, t in names.items()) and "marker_1" not in got,
              "meshio reads the physical names of the refined Gmsh domain (%s): %s" % (tag, got))
        # and once more through cvmesh: the same names
        code, err = run("triangulate", path("domain_out.msh"), "-o", path("domain_again.msh"))
        again = meshio.read(path("domain_again.msh")) if code == 0 else None
        check(code == 0 and {k: tuple(v) for k, v in again.field_data.items()} ==
              {k: tuple(v) for k, v in d.field_data.items()},
              "cvmesh reads its named .msh and writes the same names (%s) %s" % (tag, err))

# ---- the power dual as a finite-volume mesh: shared points, one polygon grid --
code, err = run("refine", path("domain.msh"), "--size", "0.1", "-o", path("fv.vtu"),
                "--dual", path("fv_dual.vtu"))
check(code == 0, "cvmesh refine --dual: " + err)
dual = meshio.read(path("fv_dual.vtu"))
pts2 = dual.points[:, :2]
check(len(np.unique(pts2, axis=0)) == len(pts2),
      "meshio reads the dual: %d points, all distinct" % len(pts2))
conn = np.concatenate([c.data.ravel() for c in dual.cells])
check(np.array_equal(np.unique(conn), np.arange(len(pts2))), "every dual point is a corner of a cell")
sizes = [c.data.shape[1] for c in dual.cells]
check({c.type for c in dual.cells} == {"polygon"} and sizes == sorted(set(sizes)),
      "meshio reads the dual as polygon blocks, one per corner count: %s" % sizes)
fc, fl = dual.field_data["face_cells"], dual.field_data["face_lengths"]
ncell = sum(len(c.data) for c in dual.cells)
check(fc.shape[1] == 2 and fc.shape == fl.shape and fc[:, 0].max() < ncell and (fl[:, 1] >= 0).all(),
      "meshio reads the face table: %d faces over %d cells" % (len(fc), ncell))
if vtk:
    rd = vtk.vtkXMLUnstructuredGridReader()
    rd.SetFileName(path("fv_dual.vtu"))
    rd.Update()
    g = rd.GetOutput()
    types = {g.GetCellType(i) for i in range(g.GetNumberOfCells())}
    check(g.GetNumberOfPoints() == len(pts2) and g.GetNumberOfCells() == ncell and types == {7},
          "VTK reads the dual as one grid of %d VTK_POLYGON cells on %d points"
          % (g.GetNumberOfCells(), g.GetNumberOfPoints()))
    check(g.GetFieldData().GetArray("face_lengths").GetNumberOfTuples() == len(fl),
          "VTK reads the face table as field data")
    # neighbouring cells share points: across each interior face VTK finds cell b
    fp = dual.field_data["face_points"]
    bad = 0
    for (a, b), (p, q) in zip(fc, fp):
        ids, pts = vtk.vtkIdList(), vtk.vtkIdList()
        pts.InsertNextId(int(p))
        pts.InsertNextId(int(q))
        g.GetCellNeighbors(int(a), pts, ids)
        got = sorted(ids.GetId(i) for i in range(ids.GetNumberOfIds()))
        bad += got != ([int(b)] if b >= 0 else [])
    check(bad == 0, "VTK's neighbour of each cell across each face is the face table's (%d wrong)" % bad)

# ---- bring your own mesh: a sheared structured grid, not Delaunay ----------
n = 8
gp = np.array([[i + 0.8 * j, 0.5 * j] for j in range(n + 1) for i in range(n + 1)], float)
gt = []
for j in range(n):
    for i in range(n):
        a = j * (n + 1) + i
        gt += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
grid = meshio.Mesh(np.c_[gp, np.zeros(len(gp))], [("triangle", np.array(gt))])
for name, fmt in (("grid.msh", "gmsh22"), ("grid.vtu", "vtu")):
    meshio.write(path(name), grid, file_format=fmt)
    out = path("grid_opt_" + name.replace(".", "_") + ".vtu")
    code, err = run("optimise", path(name), "--max-sweeps", "1", "-o", out)
    ok = code == 0 and "%d edge flips changed the connectivity" % (n * n) in err
    if ok:
        back = meshio.read(out)
        ok = len(back.cells_dict["triangle"]) == 2 * n * n
    check(ok, "cvmesh optimise flips the sheared grid %s written by meshio (%d flips): %s"
          % (name, n * n, err))

# ---- the 3D power dual: VTK_POLYHEDRON cells of a BCC lattice -------------
K = 4
with open(path("bcc.node"), "w") as f:
    pts = []
    for x in range(K + 1):
        for y in range(K + 1):
            for z in range(K + 1):
                pts.append((x, y, z))
                if x < K and y < K and z < K:
                    pts.append((x + 0.5, y + 0.5, z + 0.5))
    f.write("%d 3 0 0\n" % len(pts))
    for i, q in enumerate(pts):
        f.write("%d %r %r %r\n" % ((i,) + q))
code, err = run("tetrahedralize", path("bcc.node"), "-o", path("bcc.vtu"), "--dual", path("bcc_dual.vtu"))
check(code == 0, "cvmesh tetrahedralize --dual: " + err)
if code == 0:
    # interior vertices: (K-1)^3 corners and K^3 centres; those with all 14
    # lattice neighbours have the truncated octahedron of volume 1/2
    ncell = (K - 1) ** 3 + K ** 3
    d = meshio.read(path("bcc_dual.vtu"))
    n = sum(len(c.data) for c in d.cells)
    vol = np.concatenate(d.cell_data["volume"])
    verts = np.concatenate(d.cell_data["vertex"])
    check(n == ncell and all(c.type.startswith("polyhedron") for c in d.cells),
          "meshio reads the dual: %d polyhedra (want %d)" % (n, ncell))
    full = [i for i, v in enumerate(verts) if all(1 <= c <= K - 1 for c in pts[v])]
    check(len(full) > 0 and np.abs(vol[full] - 0.5).max() < 1e-12,
          "dual cells with all BCC neighbours have volume 1/2 (%d cells)" % len(full))
    check(len(d.points) == len(np.unique(d.points, axis=0)),
          "dual vertices are written once (%d points)" % len(d.points))
    if vtk:
        rd = vtk.vtkXMLUnstructuredGridReader()
        rd.SetFileName(path("bcc_dual.vtu"))
        rd.Update()
        g = rd.GetOutput()
        sz = vtk.vtkCellSizeFilter()
        sz.SetInputData(g)
        sz.ComputeVolumeOn()
        sz.Update()
        vv = vtk_to_numpy(sz.GetOutput().GetCellData().GetArray("Volume"))
        mine = vtk_to_numpy(g.GetCellData().GetArray("volume"))
        types = {g.GetCellType(i) for i in range(g.GetNumberOfCells())}
        check(g.GetNumberOfCells() == ncell and types == {42} and np.abs(vv - mine).max() < 1e-12,
              "VTK reads the dual as %d polyhedra whose volumes equal cvmesh's (max diff %.1e)"
              % (g.GetNumberOfCells(), np.abs(vv - mine).max() if len(vv) else 0))

# ---- Gmsh itself (the gmsh module from PyPI): its .msh in every version and encoding is read
# by cvmesh with markers and physical names, and cvmesh's .msh is read back by Gmsh ----------
try:
    import gmsh
except (ImportError, OSError) as e:  # the wheel needs X11/GL libraries (.ci/deps.sh installs them)
    gmsh = None
    print("skip Gmsh checks: %s" % e)
if gmsh:
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("square_with_hole")
    geo = gmsh.model.geo
    outer = [geo.addPoint(x, y, 0, 0.1) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))]
    inner = [geo.addPoint(x, y, 0, 0.05) for x, y in ((0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6))]
    lo = [geo.addLine(outer[i], outer[(i + 1) % 4]) for i in range(4)]
    li = [geo.addLine(inner[i], inner[(i + 1) % 4]) for i in range(4)]
    surf = geo.addPlaneSurface([geo.addCurveLoop(lo), geo.addCurveLoop(li)])
    geo.synchronize()
    gmsh.model.addPhysicalGroup(1, lo, 5, name="wall")
    gmsh.model.addPhysicalGroup(1, li, 6, name="hole")
    gmsh.model.addPhysicalGroup(2, [surf], 1, name="fluid")
    gmsh.model.mesh.generate(2)
    gnodes = len(gmsh.model.mesh.getNodes()[0])
    for version, binary in ((2.2, 0), (2.2, 1), (4.1, 0), (4.1, 1)):
        name = "gmsh_%s_%s.msh" % (version, "bin" if binary else "ascii")
        gmsh.option.setNumber("Mesh.MshFileVersion", version)
        gmsh.option.setNumber("Mesh.Binary", binary)
        gmsh.write(path(name))
        out = path("cvm_" + name)
        code, err = run("optimise", path(name), "--max-sweeps", "1", "-o", out)
        ok = code == 0
        if ok:
            back = meshio.read(out)
            tris = back.cells_dict["triangle"]
            p2 = back.points[:, :2]
            e1, e2 = p2[tris[:, 1]] - p2[tris[:, 0]], p2[tris[:, 2]] - p2[tris[:, 0]]
            area = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]).sum()
            ok = abs(area - 0.96) < 1e-12 and len(back.points) >= gnodes
        check(ok, "cvmesh optimise reads Gmsh's own .msh %s %s (area 0.96): %s"
              % (version, "binary" if binary else "ASCII", err))
        if not ok:
            continue
        # Gmsh reads cvmesh's .msh back, with the physical names cvmesh read from Gmsh's
        gmsh.model.add("back")
        gmsh.open(out)
        names = {gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()}
        n_back = len(gmsh.model.mesh.getNodes()[0])
        check({"wall", "hole", "fluid"} <= names and n_back == len(meshio.read(out).points),
              "Gmsh reads cvmesh's .msh of %s with its names %s and %d nodes"
              % (name, sorted(names), n_back))
        gmsh.model.remove()
        gmsh.model.setCurrent("square_with_hole")
    gmsh.finalize()

print("%d failed" % len(failed))
sys.exit(1 if failed else 0)
