"""Weights and the power (Voronoi) dual through the binding."""

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, capi

pytestmark = pytest.mark.skipif(not hasattr(capi, "cvm_mesh_copy_dual_areas"),
                                reason="no dual in this library")


def circumcentres(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    B, C = b - a, c - a
    d = 2 * (B[:, 0] * C[:, 1] - B[:, 1] * C[:, 0])
    bb, cc = (B ** 2).sum(1), (C ** 2).sum(1)
    return a + np.column_stack([C[:, 1] * bb - B[:, 1] * cc, B[:, 0] * cc - C[:, 0] * bb]) / d[:, None]


@pytest.fixture
def refined(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(size=0.1, min_angle=28)
    return mesh


def test_dual_shapes_and_sums(refined):
    n, m, e = len(refined.points), len(refined.triangles), len(refined.edges)
    assert refined.dual_vertices.shape == (m, 2) and refined.dual_vertices.dtype == np.float64
    assert refined.dual_inside.shape == (m,) and refined.dual_inside.dtype == bool
    assert refined.dual_areas.shape == (n,)
    assert refined.dual_edge_lengths.shape == (e,)
    assert refined.dual_areas.sum() == pytest.approx(1.0, abs=1e-12)
    assert (refined.dual_edge_lengths >= 0).all()
    np.testing.assert_allclose(refined.dual_vertices,
                               circumcentres(refined.points, refined.triangles), atol=1e-12)


def test_weights_round_trip(refined):
    n = len(refined.points)
    assert (refined.weights == 0).all() and refined.weights.shape == (n,)
    w = np.full(n, 1e-4)
    refined.weights = w
    np.testing.assert_array_equal(refined.weights, w)
    refined.check()
    refined.set_weights(None)
    assert (refined.weights == 0).all()


def test_weight_errors(refined):
    n = len(refined.points)
    with pytest.raises(cvmesh.ArgumentError) as info:
        refined.set_weights(np.zeros(n + 1))
    assert str(n) in str(info.value)
    w = np.zeros(n)
    w[5] = np.nan
    with pytest.raises(cvmesh.InputError, match="vertex 5") as info:
        refined.set_weights(w)
    assert info.value.item_kind == cvmesh.Entity.VERTEX and info.value.item_index == 5
    with pytest.raises(ValueError, match="weights must be a 1-D array"):
        refined.set_weights(np.zeros((n, 2)))
    with pytest.raises(cvmesh.StateError):
        Mesh.from_points([[0, 0], [1, 0], [0, 1]]).set_weights([0, 0, 0])


def test_dual_measures(refined):
    q = refined.quality()
    assert 0 <= q.dual_outside_pct <= 100
    assert q.vanished_vertices == 0
    assert q.min_dual_edge > 0


@pytest.mark.skipif(not hasattr(capi, "cvm_mesh_optimise_dual"), reason="no dual optimiser")
def test_optimise_dual_makes_every_triangle_compliant(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(algorithm="delaunay", size=0.1)
    assert not mesh.dual_inside.all()
    mesh.optimise_dual(dual_solver=1)
    mesh.check()
    q = mesh.quality()
    assert q.dual_noncompliant_pct == 0.0 and q.dual_opt_sweeps >= 1
    groups = mesh.dual_merge_groups
    assert groups.shape == (len(mesh.triangles),) and groups.dtype == np.int32
    assert (groups <= np.arange(len(groups))).all()
    # every triangle holds its power vertex, or is merged with a neighbour
    assert mesh.dual_inside.all() or (groups != np.arange(len(groups))).any()
