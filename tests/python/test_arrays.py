"""Arrays across the binding: dtypes, shapes, conversions and round trips."""

import numpy as np
import pytest

import cvmesh
from cvmesh import Entity, Mesh, capi


def signed_areas(points, triangles):
    p = points[triangles]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) -
                  (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def test_output_dtypes_and_shapes(square_pslg):
    pts, segs = square_pslg
    mesh = Mesh.from_pslg(pts, segs)
    assert mesh.triangulate() == cvmesh.Status.OK
    assert mesh.points.dtype == np.float64 and mesh.points.shape == (4, 2)
    for name, width in (("triangles", 3), ("edges", 2), ("segments", 2), ("neighbors", 3)):
        a = getattr(mesh, name)
        assert a.dtype == np.int32, name
        assert a.ndim == 2 and a.shape[1] == width, name
        assert a.flags.c_contiguous and a.flags.writeable, name
    assert mesh.triangles.shape == (2, 3)
    assert mesh.edges.shape == (5, 2)
    assert mesh.segments.shape == (4, 2)
    assert mesh.point_markers.shape == (4,)
    assert mesh.triangle_attributes.shape == (2,)
    assert mesh.triangle_attributes.dtype == np.float64
    assert mesh.input_map.tolist() == [0, 1, 2, 3]


def test_delaunay_round_trip(random_points):
    mesh = Mesh.from_points(random_points)
    mesh.triangulate()
    # Distinct input points become vertices 0..n-1 in input order, bit for bit.
    np.testing.assert_array_equal(mesh.points, random_points)
    tris = mesh.triangles
    assert tris.min() >= 0 and tris.max() < len(random_points)
    assert (signed_areas(mesh.points, tris) > 0).all()       # counter-clockwise
    v, e, f = len(mesh.points), len(mesh.edges), len(tris)
    assert v - e + f == 1                                     # a disc
    assert mesh.check() is True
    # every triangle edge is in the edge list; neighbours are symmetric
    edges = {tuple(sorted(x)) for x in mesh.edges.tolist()}
    for t in tris.tolist():
        for k in range(3):
            assert tuple(sorted((t[k], t[(k + 1) % 3]))) in edges
    nb = mesh.neighbors
    for t, row in enumerate(nb.tolist()):
        for n in row:
            assert n == -1 or t in nb[n].tolist()


def test_input_conversions(square_pslg):
    pts, segs = square_pslg
    variants = [
        (pts.tolist(), segs.tolist()),                        # nested lists
        (pts.astype(np.int64), segs.astype(np.int64)),        # integer coordinates, int64 ids
        (np.asfortranarray(pts), np.asfortranarray(segs)),    # column-major
        (np.repeat(pts, 2, axis=0)[::2], segs.astype(np.uint16)),  # strided view
    ]
    for p, s in variants:
        mesh = Mesh.from_pslg(p, s)
        mesh.triangulate()
        np.testing.assert_array_equal(mesh.points, pts)
        assert len(mesh.triangles) == 2


def test_shape_errors(square_pslg):
    pts, segs = square_pslg
    mesh = Mesh()
    with pytest.raises(ValueError, match=r"points must be a 2-D array"):
        mesh.set_points(pts.ravel())
    with pytest.raises(ValueError, match=r"segments must have shape \(n, 2\), got shape \(4, 3\)"):
        mesh.set_segments(np.zeros((4, 3), dtype=np.int32))
    with pytest.raises(TypeError, match="segments must be an integer array"):
        mesh.set_segments(segs.astype(float))
    with pytest.raises(OverflowError, match=r"segments\[1, 0\] = 4294967296"):
        mesh.set_segments(np.array([[0, 1], [2**32, 0]], dtype=np.int64))
    with pytest.raises(TypeError, match="real numbers"):
        mesh.set_points([["a", "b"]])
    with pytest.raises(ValueError, match=r"regions must have shape \(n, 4\)"):
        mesh.set_regions([[0.5, 0.5]])
    with pytest.raises(TypeError):
        mesh.set_points(None)


def test_empty_inputs_are_accepted():
    mesh = Mesh()
    mesh.set_points(np.zeros((0, 2)))
    mesh.set_segments([])
    mesh.set_holes(np.zeros((0, 2)))
    assert mesh.count(Entity.INPUT_POINT) == 0
    assert mesh.points.shape == (0, 2)
    assert mesh.triangles.shape == (0, 3)


def test_inputs_are_copied(square_pslg):
    pts, segs = square_pslg
    p = pts.copy()
    mesh = Mesh.from_pslg(p, segs)
    p[:] = 99.0                       # the library copied the input on set
    mesh.triangulate()
    np.testing.assert_array_equal(mesh.points, pts)


def test_outputs_are_independent_copies(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.triangulate()
    a = mesh.points
    a[:] = -1
    assert (mesh.points >= 0).all()


def test_count_then_copy_in_capi(square_pslg):
    pts, segs = square_pslg
    m = capi.cvm_mesh_create()
    try:
        capi.cvm_mesh_set_points(m, pts)
        capi.cvm_mesh_set_segments(m, segs)
        assert capi.cvm_mesh_triangulate(m) == capi.CVM_OK
        n = capi.cvm_mesh_count(m, capi.CVM_ENT_TRIANGLE)
        cells = capi.cvm_mesh_copy_cells(3 * n, m, capi.CVM_ENT_TRIANGLE)
        assert cells.dtype == np.int32 and cells.shape == (3 * n,)
        # an existing array is filled in place and returned
        buf = np.full(3 * n + 3, 7, dtype=np.int32)
        out = capi.cvm_mesh_copy_cells(buf, m, capi.CVM_ENT_TRIANGLE)
        assert out is buf
        np.testing.assert_array_equal(buf[:3 * n], cells)
        with pytest.raises(cvmesh.ArgumentError) as info:
            capi.cvm_mesh_copy_cells(3 * n - 1, m, capi.CVM_ENT_TRIANGLE)
        assert info.value.status == capi.CVM_E_BUFFER_TOO_SMALL
        with pytest.raises(TypeError, match="dtype"):
            capi.cvm_mesh_copy_cells(np.zeros(3 * n, dtype=np.int64), m, capi.CVM_ENT_TRIANGLE)
        with pytest.raises(TypeError):
            capi.cvm_mesh_copy_points(np.zeros(8)[::2], m)     # not contiguous
        view = capi.cvm_mesh_view_points(m)
        np.testing.assert_array_equal(view, pts)
    finally:
        capi.cvm_mesh_free(m)
    capi.cvm_mesh_free(None)          # a no-op, as in C


def test_insert_points_returns_ids(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.triangulate()
    ids = mesh.insert_points([[0.5, 0.5], [0.25, 0.75], [2.0, 2.0], [0.5, 0.5]])
    assert ids.dtype == np.int32
    assert ids.tolist() == [4, 5, cvmesh.REJECTED, cvmesh.REJECTED]
    assert len(mesh.points) == 6
    np.testing.assert_array_equal(mesh.points[4], [0.5, 0.5])
    mesh.check()
    ids = mesh.insert_points([[0.51, 0.5]], min_dist=0.1)
    assert ids.tolist() == [cvmesh.REJECTED]


def test_markers_regions_and_holes():
    outer = [[0, 0], [4, 0], [4, 4], [0, 4]]
    inner = [[1, 1], [3, 1], [3, 3], [1, 3]]
    pts = np.array(outer + inner, dtype=float)
    segs = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
    mesh = Mesh.from_pslg(pts, segs, holes=[[2, 2]], markers=[1, 1, 1, 1, 2, 2, 2, 2],
                          segment_markers=[1, 1, 1, 1, 2, 2, 2, 2],
                          regions=[[0.5, 0.5, 7.0, 0.0]])
    mesh.triangulate()
    centroids = mesh.points[mesh.triangles].mean(axis=1)
    inside_hole = (np.abs(centroids - 2) < 1).all(axis=1)
    assert not inside_hole.any()
    assert (mesh.triangle_attributes == 7.0).all()
    assert mesh.point_markers.tolist() == [1, 1, 1, 1, 2, 2, 2, 2]
    assert sorted(mesh.segment_markers.tolist()) == [1] * 4 + [2] * 4
    mesh.check()


def test_point_attributes_round_trip(random_points):
    attrs = np.column_stack([random_points.sum(axis=1), np.arange(len(random_points))])
    mesh = Mesh.from_points(random_points, attributes=attrs)
    mesh.triangulate()
    np.testing.assert_array_equal(mesh.point_attributes, attrs)


def test_write_read_round_trip(tmp_path, random_points):
    mesh = Mesh.from_points(random_points)
    mesh.triangulate()
    for ext in (".vtu", ".msh", ".svg", ".node"):
        mesh.write(tmp_path / ("out" + ext))
        assert (tmp_path / ("out" + ext)).stat().st_size > 0
    again = Mesh.read(tmp_path / "out.node")
    again.triangulate()
    np.testing.assert_array_equal(again.points, mesh.points)
    np.testing.assert_array_equal(again.triangles, mesh.triangles)


def test_read_poly(poly_file):
    mesh = Mesh.read(poly_file)
    assert mesh.count("input_point") > 0
    mesh.triangulate()
    mesh.check()
    assert mesh.count(Entity.TRIANGLE) > 0


def test_options(random_points):
    mesh = Mesh(seed=5)
    assert mesh.get_option("seed") == 5
    mesh.set_option(cvmesh.Option.TIME_LIMIT_S, 2.5)
    assert mesh.get_option(capi.CVM_OPT_TIME_LIMIT_S) == 2.5
    assert mesh.options["seed"] == 5
    b = cvmesh.option_bounds("min_angle_deg")
    assert isinstance(b, cvmesh.Bounds) and b.lo <= b.default <= b.hi
    assert cvmesh.option_bounds(cvmesh.Option.SEED).is_integer is True


def test_quality(random_points):
    mesh = Mesh.from_points(random_points)
    mesh.triangulate()
    q = mesh.quality()
    assert isinstance(q, cvmesh.Quality)
    assert 0 < q.min_angle_deg <= 60 <= q.max_angle_deg < 180
    assert q.area == pytest.approx(np.abs(signed_areas(mesh.points, mesh.triangles)).sum())
    assert q.hist_angle_deg.shape == (18,)
    assert q.hist_angle_deg.sum() == 3 * len(mesh.triangles)
    assert q.hist_degree.shape == (16,)
    assert set(q.as_dict()) >= {"min_angle_deg", "obtuse_pct", "hist_degree"}
    np.testing.assert_allclose(mesh.triangle_min_angles().min(), q.min_angle_deg)


def test_version():
    assert cvmesh.version() == cvmesh.__version__
    assert capi.cvm_version_number() == capi.CVM_VERSION_NUMBER
    major, minor, patch = (int(x) for x in cvmesh.version().split("."))
    assert capi.CVM_VERSION_NUMBER == major * 10000 + minor * 100 + patch


def test_enums_follow_the_header():
    assert cvmesh.Status.OK == 0 and cvmesh.Status.E_INPUT_INDEX == capi.CVM_E_INPUT_INDEX
    assert cvmesh.Status.INCOMPLETE_CANCELLED.incomplete
    assert cvmesh.Status.E_NOMEM.is_error and not cvmesh.Status.OK.is_error
    assert cvmesh.Entity.TRIANGLE == capi.CVM_ENT_TRIANGLE
    assert cvmesh.Option["MIN_ANGLE_DEG"] == capi.CVM_OPT_MIN_ANGLE_DEG
    assert cvmesh.Stage.INSERT == capi.CVM_STAGE_INSERT
    assert {m.name for m in cvmesh.Measure} >= {"MIN_ANGLE_DEG", "AREA"}
