"""cvm_mesh_quadmesh() through the binding: quads as mixed cells, the quad reports."""
import numpy as np
import pytest

import cvmesh


def box_mesh(x0, y0, x1, y1):
    m = cvmesh.Mesh()
    m.set_points(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=np.float64))
    m.set_segments(np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.int32))
    return m


def test_quadmesh_unit_lattice_gives_16_quads():
    m = box_mesh(0, 0, 4, 4)
    s = cvmesh.Sizing()
    s.set_metric_builtin("identity")
    assert m.quadmesh(s) == cvmesh.Status.OK
    off, types, conn = m.cells_mixed()
    assert len(types) == 16 and (types == cvmesh.CellType.QUAD).all()
    assert m.report("quad_pct") == 100.0
    assert m.report("quad_quads") == 16.0
    p = m.points[conn.reshape(-1, 4)]
    q = np.roll(p, -1, axis=1)
    area = 0.5 * (p[:, :, 0] * q[:, :, 1] - p[:, :, 1] * q[:, :, 0]).sum(axis=1)
    assert abs(area.sum() - 16.0) < 1e-12
    assert len(m.triangles) == 32  # the triangulation before recombination


def test_quadmesh_options_and_bad_metric():
    m = box_mesh(0, 0, 2, 1)
    s = cvmesh.Sizing()
    s.set_metric_constant(4.0, 0.0, 16.0)
    assert m.quadmesh(s, quad_p=4, quad_recombine=1) == cvmesh.Status.OK
    assert m.report("quad_pct") > 50
    with pytest.raises(cvmesh.Error):
        s.set_metric_constant(1.0, 2.0, 1.0)  # not positive definite
    s.set_metric(lambda x: (1.0, 0.0, 1.0))  # a Python callback gives no derivatives
    with pytest.raises(cvmesh.Error, match="derivatives"):
        m.quadmesh(s)


def test_quadmesh_all_quad_and_smoothing_options():
    m = box_mesh(-1.3, -1.3, 1.3, 1.3)
    s = cvmesh.Sizing()
    s.set_metric_builtin("saddle", 36.0)
    assert m.quadmesh(s, quad_all_quad=1) == cvmesh.Status.OK
    off, types, conn = m.cells_mixed()
    assert (types == cvmesh.CellType.QUAD).all()
    assert m.report("quad_pct") == 100.0
    p = m.points[conn.reshape(-1, 4)]
    q = np.roll(p, -1, axis=1)
    area = 0.5 * (p[:, :, 0] * q[:, :, 1] - p[:, :, 1] * q[:, :, 0]).sum(axis=1)
    assert (area > 0).all() and abs(area.sum() - 2.6 * 2.6) < 1e-12
    assert m.check()
    # no smoothing, the Halton start: still a valid mesh, the option names reach the library
    assert m.quadmesh(s, quad_all_quad=0, quad_smooth=0, quad_initial_sites=1) == cvmesh.Status.OK
    assert m.check()
