"""Dual quality q1-q5, dual cells, the dual .vtu and .vtu read-back through the binding."""

import math

import numpy as np
import pytest

import cvmesh
from cvmesh import Histogram, Measure, Mesh, capi

pytestmark = pytest.mark.skipif(not hasattr(capi, "cvm_mesh_copy_dual_cells"),
                                reason="no dual cells in this library")


@pytest.fixture
def weighted(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(size=0.1, min_angle=28)
    rng = np.random.default_rng(4)
    mesh.weights = 0.2 * 0.01 * rng.random(len(mesh.points))
    return mesh


def power_vertices(p, t, w):
    a, b, c = (p[t[:, k]] for k in range(3))
    wa, wb, wc = (w[t[:, k]] for k in range(3))
    m = np.stack([2 * (b - a), 2 * (c - a)], axis=1)  # (m, 2, 2)
    r = np.column_stack([(b ** 2).sum(1) - (a ** 2).sum(1) - wb + wa,
                         (c ** 2).sum(1) - (a ** 2).sum(1) - wc + wa])
    return np.linalg.solve(m, r[:, :, None])[:, :, 0]


def test_q1_q2_match_numpy(weighted):
    p, t, w = weighted.points, weighted.triangles, weighted.weights
    q1 = weighted.dual_quality("q1")
    q2 = weighted.dual_quality(Histogram.Q2)
    assert q1.shape == (len(t),) and q1.dtype == np.float64
    np.testing.assert_allclose(q1, weighted.triangle_min_angles(), rtol=1e-9)
    a, b, c = (p[t[:, k]] for k in range(3))
    la, lb, lc = (np.hypot(*(y - x).T) for x, y in ((a, b), (b, c), (c, a)))
    area = 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    r = 2 * area / (la + lb + lc)
    centroid = (a + b + c) / 3
    want = np.hypot(*(centroid - power_vertices(p, t, w)).T) / r
    np.testing.assert_allclose(q2, want, rtol=1e-8, atol=1e-12)


def test_q_histograms_and_measures(weighted):
    q = weighted.quality()
    assert len(q.hist_q1) == 12 and sum(q.hist_q1) == len(weighted.triangles)
    assert len(q.hist_q5) == 20
    q5 = weighted.dual_quality("q5")
    assert q5.shape == (len(weighted.edges),)
    assert q.q5_min > 0 and q.q2_max == pytest.approx(weighted.dual_quality("q2").max())
    assert q.q1_mean_deg == pytest.approx(weighted.dual_quality("q1").mean())


def shoelace(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * (x * np.roll(y, -1) - np.roll(x, -1) * y).sum()


def test_dual_cells_tile_the_domain(weighted):
    offsets, corners = weighted.dual_cells
    n = len(weighted.points)
    assert offsets.shape == (n + 1,) and offsets.dtype == np.int32 and offsets[0] == 0
    assert corners.shape == (offsets[-1], 2) and corners.dtype == np.float64
    areas = np.array([shoelace(corners[offsets[v]:offsets[v + 1]]) for v in range(n)])
    np.testing.assert_allclose(areas, weighted.dual_areas, atol=1e-12)
    assert areas.sum() == pytest.approx(1.0, abs=1e-12)


def test_write_dual_and_vtu_round_trip(weighted, tmp_path):
    weighted.write_dual(tmp_path / "dual.vtu")
    text = (tmp_path / "dual.vtu").read_text()
    assert 'Name="area"' in text and 'Name="weight"' in text
    with pytest.raises(cvmesh.UnsupportedError):
        weighted.write_dual(tmp_path / "dual.svg")
    weighted.write(tmp_path / "m.vtu")
    again = Mesh.read(tmp_path / "m.vtu")
    np.testing.assert_array_equal(again.points, weighted.points)
    np.testing.assert_array_equal(again.triangles, weighted.triangles)
    np.testing.assert_array_equal(again.weights, weighted.weights)
    again.write(tmp_path / "m2.vtu")
    assert (tmp_path / "m.vtu").read_bytes() == (tmp_path / "m2.vtu").read_bytes()


def test_bad_vtu_raises_with_the_line(tmp_path):
    bad = tmp_path / "bad.vtu"
    bad.write_text('<VTKFile type="UnstructuredGrid"><Piece NumberOfPoints="3" NumberOfCells="1">\n'
                   '<Points><DataArray NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 zz'
                   '</DataArray></Points></Piece></VTKFile>\n')
    with pytest.raises(cvmesh.FileError, match=r"bad.vtu:2: Points: entry 8 \(from 0\) is 'zz', not a number"):
        Mesh.read(bad)


@pytest.mark.skipif(not hasattr(capi, "cvm_mesh_count_dual"), reason="no finite-volume dual")
def test_dual_fv_mesh_is_consistent(weighted):
    d = weighted.dual()
    p, e, t = weighted.points, weighted.edges, weighted.triangles
    n, ne = len(p), len(e)
    assert d.points.shape[1] == 2 and d.points.dtype == np.float64
    assert d.offsets.shape == (n + 1,) and d.polygons.shape == (d.offsets[-1],)
    assert d.faces.shape[1] == 6 and d.face_lengths.shape == (len(d.faces), 2)
    # the corners are the doubles of dual_cells; the power vertices come first
    _, corners = weighted.dual_cells
    np.testing.assert_array_equal(d.points[d.polygons], corners)
    np.testing.assert_array_equal(d.points[:len(t)], weighted.dual_vertices)
    assert np.unique(d.polygons).size == len(d.points)
    # one face per edge, in edge order, then two per boundary edge
    np.testing.assert_array_equal(d.faces[:ne, :2], e)
    np.testing.assert_array_equal(d.face_lengths[:ne, 1], weighted.dual_edge_lengths)
    nb = len(d.faces) - ne
    assert nb % 2 == 0 and (d.faces[ne:, 1] == -1).all() and (d.faces[:ne, 1] >= 0).all()
    a, b = p[d.faces[:, 2]], p[d.faces[:, 3]]
    np.testing.assert_allclose(d.face_lengths[:, 0], np.hypot(*(a - b).T), rtol=1e-15)
    fp, fq = d.points[d.faces[:, 4]], d.points[d.faces[:, 5]]
    np.testing.assert_allclose(d.face_lengths[:, 1], np.hypot(*(fq - fp).T), rtol=1e-15)
    # every cell is closed by its faces: outward normals sum to 0
    normal = np.column_stack([fq[:, 1] - fp[:, 1], fp[:, 0] - fq[:, 0]])
    total = np.zeros((n, 2))
    np.add.at(total, d.faces[:, 0], normal)
    inner = d.faces[:, 1] >= 0
    np.add.at(total, d.faces[inner, 1], -normal[inner])
    assert np.abs(total).max() < 1e-12
    areas = np.array([shoelace(d.points[d.polygons[d.offsets[v]:d.offsets[v + 1]]]) for v in range(n)])
    np.testing.assert_allclose(areas, d.areas, atol=1e-12)
    assert d.areas.sum() == pytest.approx(1.0, abs=1e-12)


@pytest.mark.skipif(not hasattr(capi, "cvm_mesh_count_dual"), reason="no finite-volume dual")
def test_dual_vtu_is_one_polygon_mesh_for_meshio(weighted, tmp_path):
    meshio = pytest.importorskip("meshio")
    weighted.write_dual(tmp_path / "dual.vtu")
    d = weighted.dual()
    m = meshio.read(tmp_path / "dual.vtu")
    assert len(m.points) == len(d.points)
    assert {c.type for c in m.cells} == {"polygon"}
    sizes = [c.data.shape[1] for c in m.cells]
    assert sizes == sorted(set(sizes))  # one block per corner count
    assert sum(len(c.data) for c in m.cells) == len(weighted.points)
    assert m.field_data["face_cells"].shape == (len(d.faces), 2)
    np.testing.assert_array_equal(m.field_data["face_edge"], d.faces[:, 2:4])
    np.testing.assert_array_equal(m.field_data["face_points"], d.faces[:, 4:6])
    np.testing.assert_array_equal(m.field_data["face_lengths"], d.face_lengths)
    vertex = np.concatenate(m.cell_data["vertex"])
    cell_of = np.full(len(weighted.points), -1)
    cell_of[vertex] = np.arange(len(vertex))
    np.testing.assert_array_equal(m.field_data["face_cells"][:, 0], cell_of[d.faces[:, 0]])
