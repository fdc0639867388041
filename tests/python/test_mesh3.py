"""A 3D mesh through the binding: points (n, 3), tetrahedra (m, 4), the 3D
measures and histograms in quality(), dual vertices and cell volumes."""

import numpy as np
import pytest

from cvmesh import Mesh


def bcc(k):
    pts = []
    for x in range(k + 1):
        for y in range(k + 1):
            for z in range(k + 1):
                pts.append((x, y, z))
                if x < k and y < k and z < k:
                    pts.append((x + 0.5, y + 0.5, z + 0.5))
    return np.array(pts, dtype=float)


def tet_volumes(p, t):
    a, b, c, d = (p[t[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", a - d, np.cross(b - d, c - d)) / 6


def test_points_and_tetrahedra_of_a_bcc_lattice():
    pts = bcc(3)
    mesh = Mesh.from_points(pts)
    mesh.triangulate()
    assert mesh.dim == 3
    p, t = mesh.points, mesh.tetrahedra
    assert p.shape == (len(pts), 3) and t.shape[1] == 4 and t.dtype == np.int32
    v = tet_volumes(p, t)
    assert (v > 0).all() and abs(v.sum() - 27.0) < 1e-12
    assert mesh.check()


def test_quality_has_the_3d_measures_and_histograms():
    mesh = Mesh.from_points(bcc(3))
    mesh.triangulate()
    q = mesh.quality()
    assert abs(q.volume - 27.0) < 1e-12
    assert abs(q.min_dual_edge_3d - np.sqrt(2) / 4) < 1e-12
    assert 0 < q.valence14_pct <= 100
    assert q.hist_dihedral_deg.sum() == 6 * len(mesh.tetrahedra)
    assert len(q.hist_valence_3d) == 32
    assert len(q.hist_angle_deg) == 0  # a 2D histogram of a 3D mesh


def test_dual_vertices_and_volumes():
    mesh = Mesh.from_points(bcc(4))
    mesh.triangulate()
    dv = mesh.dual_vertices_nd
    assert dv.shape == (len(mesh.tetrahedra), 3)
    vol = mesh.dual3_volumes
    p = mesh.points
    full = np.all((p >= 1) & (p <= 3), axis=1)
    assert full.sum() > 0 and np.abs(vol[full] - 0.5).max() < 1e-12
    assert (vol[~full] != 0).all()


def test_a_2d_mesh_has_no_tetrahedra_and_its_quality_still_computes():
    mesh = Mesh.from_points([[0, 0], [1, 0], [0, 1], [1, 1]])
    mesh.triangulate()
    assert mesh.tetrahedra.shape == (0, 4)
    q = mesh.quality()
    assert len(q.hist_dihedral_deg) == 0 and len(q.hist_angle_deg) == 18


def test_insert_points_in_3d():
    """(k, 3) points go into a 3D mesh: the result is the Delaunay
    tetrahedralisation of all points; outside, duplicates and near points are
    rejected; NaN raises and names the point."""
    import pytest
    import cvmesh

    pts = bcc(3)
    mesh = Mesh.from_points(pts)
    mesh.triangulate()
    rng = np.random.default_rng(7)
    new = rng.uniform(0.1, 2.9, size=(50, 3))
    extra = np.array([[5.0, 1.0, 1.0], pts[4]])
    ids = mesh.insert_points(np.vstack([new, extra]))
    assert ids.dtype == np.int32
    assert (ids[:50] == np.arange(len(pts), len(pts) + 50)).all()
    assert ids[50] == cvmesh.REJECTED and ids[51] == cvmesh.REJECTED
    assert mesh.check()
    p, t = mesh.points, mesh.tetrahedra
    assert abs(tet_volumes(p, t).sum() - 27.0) < 1e-12
    ref = Mesh.from_points(p)
    ref.triangulate()
    assert (ref.tetrahedra == t).all()
    near = mesh.insert_points(new[1:2] + 1e-3, min_dist=0.01)
    assert near[0] == cvmesh.REJECTED
    bad = new[:3].copy()
    bad[2, 1] = np.nan
    with pytest.raises(cvmesh.InputError) as err:
        mesh.insert_points(bad)
    assert "point 2" in str(err.value)
    assert len(mesh.points) == len(p)


def test_dual3_merge_groups_of_a_cubic_lattice():
    """Each cube of a cubic lattice is one merged dual cell: its tetrahedra share
    their circumcentre; dual3_merge_tol 0 merges nothing."""
    g = np.arange(4, dtype=float)
    pts = np.array([(x, y, z) for x in g for y in g for z in g])
    mesh = Mesh.from_points(pts)
    mesh.triangulate()
    groups = mesh.dual3_merge_groups
    tets = mesh.tetrahedra
    assert groups.shape == (len(tets),) and groups.dtype == np.int32
    assert len(np.unique(groups)) == 27
    assert (groups <= np.arange(len(tets))).all() and (groups[groups] == groups).all()
    # the tetrahedra of a group lie in one cube: the same floor of their centroids
    cube = np.floor(mesh.points[tets].mean(axis=1)).astype(int)
    for r in np.unique(groups):
        assert len(np.unique(cube[groups == r], axis=0)) == 1
    q = mesh.quality()
    assert q.dual3_merged_pct == 100 and q.dual3_noncompliant_pct == 0
    mesh.set_option("dual3_merge_tol", 0)
    assert (mesh.dual3_merge_groups == np.arange(len(tets))).all()


def test_vtu_of_merged_cells_reads_with_meshio(tmp_path):
    """vtu_merged_cells: one closed, outward-oriented polyhedron per merged cell;
    the volumes add up to the lattice's."""
    meshio = pytest.importorskip("meshio")
    g = np.arange(4, dtype=float)
    mesh = Mesh.from_points(np.array([(x, y, z) for x in g for y in g for z in g]))
    mesh.triangulate()
    mesh.set_option("vtu_merged_cells", 1)
    mesh.write(tmp_path / "m.vtu")
    m = meshio.read(tmp_path / "m.vtu")
    cells = [c for block in m.cells for c in block.data]
    assert len(cells) == 27
    vol = 0.0
    for faces in cells:
        assert len(faces) == 12
        edges = [(int(f[i]), int(f[(i + 1) % 3])) for f in faces for i in range(3)]
        assert sorted(edges) == sorted((b, a) for a, b in edges)  # closed, consistently oriented
        for f in faces:
            a, b, c = m.points[np.asarray(f)]
            vol += np.dot(a, np.cross(b, c)) / 6
    assert abs(vol - 27.0) < 1e-9
