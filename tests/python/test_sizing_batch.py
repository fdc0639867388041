"""The vectorised sizing callback: numpy arrays in, one size per point out."""

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Sizing


def size_of(x, y):
    return 0.02 + 0.05 * x + 0.02 * y * y


@pytest.fixture
def cloud():
    return np.random.default_rng(4).random((3000, 2))


def refined(points, sizing):
    mesh = Mesh.from_points(points, seed=1)
    mesh.triangulate()
    mesh.refine(algorithm="delaunay", sizing=sizing)
    return mesh


def test_batch_callback_gives_the_mesh_of_the_scalar_one(cloud):
    batches = []

    def vectorised(xy):
        assert xy.dtype == np.float64 and xy.ndim == 2 and xy.shape[1] == 2
        batches.append(len(xy))
        return size_of(xy[:, 0], xy[:, 1])

    a = refined(cloud, Sizing(callback=size_of))
    b = refined(cloud, Sizing(batch=vectorised))
    np.testing.assert_array_equal(a.points, b.points)      # bit for bit
    np.testing.assert_array_equal(a.triangles, b.triangles)
    # the 3000 starting vertices in three calls, then one call per point asked
    assert batches[:3] == [1024, 1024, 952]
    # (a Steiner point may be asked more than once: candidates, segment splits)
    assert set(batches[3:]) == {1} and len(batches) - 3 >= len(b.points) - 3000
    b.check()


def test_batch_callback_may_return_any_sequence_and_keep_its_array(cloud):
    kept = []

    def listing(xy):
        kept.append(xy)                  # the array is the callback's own copy
        return [0.05] * len(xy)

    sizing = Sizing()
    sizing.set_batch_callback(listing)
    mesh = refined(cloud[:100], sizing)
    assert len(mesh.points) > 100
    assert kept[0].shape == (100, 2) and np.array_equal(kept[0], cloud[:100])
    assert sizing(0.3, 0.3) == 0.05      # evaluation asks a batch of one


def test_batch_callback_errors_propagate(cloud):
    class Boom(Exception):
        pass

    def boom(xy):
        raise Boom("no size here")

    with pytest.raises(Boom, match="no size here"):
        refined(cloud[:50], Sizing(batch=boom))
    with pytest.raises(ValueError, match="one size per point: 50 points, 3 values"):
        refined(cloud[:50], Sizing(batch=lambda xy: [1.0, 2.0, 3.0]))
    with pytest.raises(cvmesh.ArgumentError, match="sizing callback returned size -1"):
        refined(cloud[:50], Sizing(batch=lambda xy: -np.ones(len(xy))))
    with pytest.raises(cvmesh.InputError, match="non-finite"):
        refined(cloud[:50], Sizing(batch=lambda xy: np.full(len(xy), np.nan)))
    with pytest.raises(TypeError):
        Sizing().set_batch_callback(3)
    with pytest.raises(ValueError, match="not both"):
        Sizing(callback=size_of, batch=lambda xy: xy[:, 0])


def test_one_user_function_per_sizing():
    s = Sizing(batch=lambda xy: np.full(len(xy), 0.5))
    assert s(0.1, 0.2) == 0.5
    s.set_callback(lambda x, y: 0.25)
    assert s(0.1, 0.2) == 0.25
    s.set_batch_callback(None)
    assert s(0.1, 0.2) == float("inf")
