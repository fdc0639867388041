"""The dimension-generic calls across the binding: dim, _nd inputs and outputs,
mixed cells, cell neighbours and attributes, reports, _nd sizing and the metric."""

import math

import numpy as np
import pytest

import cvmesh
from cvmesh import CellType, Entity, Mesh, Report, Sizing, capi

# [0,3]^2 with the hole [1,2]^2
OUTER = [[0, 0], [3, 0], [3, 3], [0, 3]]
INNER = [[1, 1], [2, 1], [2, 2], [1, 2]]
PTS = np.array(OUTER + INNER, dtype=float)
SEGS = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]], dtype=np.int32)


def refined(nd=True):
    mesh = Mesh()
    mesh.set_points(PTS)
    mesh.set_segments(SEGS)
    if nd:
        mesh.set_holes_nd([[1.5, 1.5]])
        mesh.set_regions_nd([[0.5, 0.5, 7.0, 0.05]])
    else:
        mesh.set_holes([[1.5, 1.5]])
        mesh.set_regions([[0.5, 0.5, 7.0, 0.05]])
    assert mesh.triangulate() == cvmesh.Status.OK
    mesh.refine("delaunay")
    return mesh


def test_dim_is_2():
    assert Mesh().dim == 2
    assert refined().dim == 2
    assert capi.cvm_mesh_dim(Mesh()._m) == 2


def test_nd_inputs_give_the_mesh_of_the_2d_inputs():
    a, b = refined(nd=False), refined(nd=True)
    assert np.array_equal(a.points, b.points_nd)
    assert np.array_equal(a.triangles, b.triangles)
    assert set(b.cell_attributes().tolist()) == {7.0}
    extra = [[0.25, 0.75], [2.5, 2.75], [1.5, 1.5]]
    ida = a.insert_points(extra)
    idb = b.insert_points_nd(extra)
    assert ida.dtype == idb.dtype == np.int32
    assert np.array_equal(ida, idb)
    assert idb[2] == cvmesh.REJECTED  # in the hole
    assert b.points_nd.shape == (b.count("vertex"), 2)
    assert np.array_equal(a.dual_vertices, b.dual_vertices_nd)


def test_three_dimensions_are_unsupported_with_a_message():
    mesh = refined()
    nv = mesh.count("vertex")
    with pytest.raises(cvmesh.UnsupportedError, match="3D kernel"):
        mesh.set_holes_nd([[1.5, 1.5, 0.0]])
    with pytest.raises(cvmesh.UnsupportedError, match="3D kernel"):
        mesh.set_regions_nd([[0.5, 0.5, 0.0, 7.0, 0.0]])
    with pytest.raises(cvmesh.UnsupportedError, match="3D kernel"):
        mesh.insert_points_nd([[0.5, 0.5, 0.5]])
    assert mesh.count("vertex") == nv
    assert mesh.count("hole") == 1 and mesh.count("region") == 1
    with pytest.raises(cvmesh.ArgumentError, match="got 1"):
        mesh.set_holes_nd([[1.5]])
    with pytest.raises(cvmesh.UnsupportedError):
        capi.cvm_mesh_copy_points_nd(3 * nv, 3, mesh._m)
    with pytest.raises(cvmesh.ArgumentError):
        capi.cvm_mesh_copy_points_nd(3 * nv, 4, mesh._m)


def test_cells_mixed_are_the_triangles():
    mesh = refined()
    offsets, types, conn = mesh.cells_mixed()
    tri = mesh.triangles
    assert offsets.dtype == types.dtype == conn.dtype == np.int32
    assert offsets.shape == (len(tri) + 1,) and types.shape == (len(tri),)
    assert np.array_equal(offsets, 3 * np.arange(len(tri) + 1))
    assert np.all(types == CellType.TRIANGLE) and CellType.TRIANGLE == 5
    assert np.array_equal(conn.reshape(-1, 3), tri)
    with pytest.raises(cvmesh.ArgumentError):
        mesh.cells_mixed(Entity.TRIANGLE)


def test_cells_mixed_short_buffer_raises_and_writes_nothing():
    mesh = refined()
    nc, nconn = capi.cvm_mesh_count_cells_mixed(mesh._m, Entity.CELL)
    off = np.full(nc + 1, -7, dtype=np.int32)
    types = np.full(nc, -7, dtype=np.int32)
    conn = np.full(nconn - 1, -7, dtype=np.int32)
    with pytest.raises(cvmesh.Error) as e:
        capi.cvm_mesh_copy_cells_mixed(off, types, conn, mesh._m, Entity.CELL)
    assert e.value.status == cvmesh.Status.E_BUFFER_TOO_SMALL
    assert np.all(off == -7) and np.all(types == -7) and np.all(conn == -7)


def test_cell_neighbours_are_symmetric():
    mesh = refined()
    nb = mesh.cell_neighbors()
    assert np.array_equal(nb.reshape(-1, 3), mesh.neighbors)
    assert np.array_equal(mesh.cell_neighbors(Entity.TRIANGLE), mesh.neighbors)
    nb = nb.reshape(-1, 3)
    for c, row in enumerate(nb):
        for d in row:
            if d >= 0:
                assert c in nb[d]
    assert np.count_nonzero(nb < 0) == mesh.count("segment")
    with pytest.raises(cvmesh.UnsupportedError):
        mesh.cell_neighbors(Entity.TETRAHEDRON)


def test_reports_equal_the_measures_of_the_same_number():
    mesh = refined()
    reports = mesh.reports()
    assert reports["refine_steiner"] > 0
    assert reports["refine_requested_angle"] == 30
    for r in Report:
        if r != Report.DUAL_OPT_SECONDS:
            assert mesh.report(r) == capi.cvm_mesh_get_measure(mesh._m, int(r)), r.name
    with pytest.raises(cvmesh.ArgumentError):
        capi.cvm_mesh_get_report(mesh._m, int(cvmesh.Measure.MIN_ANGLE_DEG))


def test_sizing_nd_equals_the_2d_sizing():
    a, b = Sizing(), Sizing()
    a.add_point_source(0.5, 0.5, 0.1, 0.5)
    b.add_point_source_nd([0.5, 0.5], 0.1, 0.5)
    a.add_line_source(3, 0, 3, 3, 0.2, 0.3)
    b.add_line_source_nd([[3, 0], [3, 3]], 0.2, 0.3)
    for x, y in [(0, 0), (1, 2), (2.5, 0.5), (-4, 7)]:
        assert a(x, y) == b.eval_nd([x, y])
    # a sizing holds sources of one dimension: 3D ones do not join 2D ones
    with pytest.raises(cvmesh.ArgumentError, match="2D sources"):
        b.add_point_source_nd([0, 0, 0], 1.0)
    with pytest.raises(cvmesh.ArgumentError, match="2D sources"):
        b.eval_nd([0.0, 0.0, 0.0])
    with pytest.raises(ValueError):
        b.add_line_source_nd([[0, 0]], 1.0)


def test_sizing_callback_nd_drives_the_refinement():
    seen = []

    def size(x):
        seen.append(x.shape)
        return 0.25 + 0.1 * abs(x[0] - 1.5)

    a, b = refined(), refined()
    sa = Sizing(callback=lambda x, y: 0.25 + 0.1 * abs(x - 1.5))
    sb = Sizing()
    sb.set_callback_nd(size)
    a.refine("frontal", sizing=sa)
    b.refine("frontal", sizing=sb)
    assert seen and set(seen) == {(2,)}
    assert np.array_equal(a.points, b.points)
    assert sb.eval_nd([3.5, 0.0]) == pytest.approx(0.45)

    def bad(x):
        raise KeyError("boom")
    sb.set_callback_nd(bad)
    with pytest.raises(KeyError):
        sb.eval_nd([0.0, 0.0])


def test_metric_is_checked_and_refused_by_the_refiners():
    s = Sizing(uniform=0.5)
    with pytest.raises(cvmesh.StateError):
        s.metric_at([0.0, 0.0])
    s.set_metric(lambda x: (4.0, 1.0, 2.0) if x[0] >= 0 else None)
    assert np.array_equal(s.metric_at([0.5, 0.5]), [4.0, 1.0, 2.0])
    assert s(0.5, 0.5) == 0.5  # the scalar size does not read the metric
    with pytest.raises(cvmesh.InputError, match="refused"):
        s.metric_at([-1.0, 0.0])
    s.set_metric(lambda x: (1.0, 3.0, 1.0))
    with pytest.raises(cvmesh.ArgumentError, match="not positive definite"):
        s.metric_at([0.0, 0.0])
    s.set_metric(lambda x: (1.0, 0.0))
    with pytest.raises(ValueError, match="3 values"):
        s.metric_at([0.0, 0.0])
    s.set_metric(lambda x: (1.0, 0.0, 1.0))
    mesh = refined()
    nv = mesh.count("vertex")
    with pytest.raises(cvmesh.UnsupportedError, match="metric"):
        mesh.refine("frontal", sizing=s)
    with pytest.raises(cvmesh.UnsupportedError, match="metric"):
        mesh.optimise_dual(sizing=s)
    assert mesh.count("vertex") == nv
    s.set_metric(None)
    mesh.refine("frontal", sizing=s)
    assert mesh.count("vertex") >= nv
    s.close()


def test_enums_of_the_new_constants():
    assert Entity.CELL == capi.CVM_ENT_CELL
    assert Report.REFINE_STEINER == cvmesh.Measure.REFINE_STEINER
    assert {c.name for c in CellType} == {"TRIANGLE", "POLYGON", "QUAD", "TETRAHEDRON",
                                          "POLYHEDRON"}
    assert not math.isnan(refined().report("dual_opt_sweeps"))
