"""A 3D mesh through the binding: points (n, 3), tetrahedra (m, 4), the 3D
measures and histograms in quality(), dual vertices and cell volumes."""

import numpy as np

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
