"""The sizing in 3D through the binding: point, line and triangle sources and a
background of tetrahedra evaluated where they have a closed form, errors
naming the source, one dimension per sizing, and Mesh.generate3 refining
around a point source."""

import math
import os
from pathlib import Path

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Sizing

ROOT = Path(__file__).resolve().parents[2]


def data3d(name):
    d = os.environ.get("CVM_DATA3D_DIR")
    path = Path(d) / name if d else ROOT / "examples" / "data3d" / name
    assert path.is_file(), "%s is missing" % path
    return path


def test_sources_in_3d_have_their_closed_form_sizes():
    with Sizing() as s:
        s.add_point_source_nd([1, 2, 3], 0.1, 0.5)
        assert s.eval_nd([1, 2, 3]) == 0.1
        assert s.eval_nd([4, 6, 3]) == 0.1 + 0.5 * 5
    with Sizing() as s:
        s.add_line_source_nd([[0, 0, 0], [2, 0, 0]], 0.2, 0.25)
        assert s.eval_nd([1, 3, 4]) == 0.2 + 0.25 * 5
        assert s.eval_nd([-3, 0, 4]) == 0.2 + 0.25 * 5
    with Sizing() as s:
        s.add_triangle_source_nd([[0, 0, 0], [4, 0, 0], [0, 4, 0]], 0.1, 0.5)
        assert s.eval_nd([1, 1, 3]) == 0.1 + 0.5 * 3
        assert s.eval_nd([-3, -4, 0]) == 0.1 + 0.5 * 5
        assert abs(s.eval_nd([5, 5, 4]) - (0.1 + 0.5 * math.sqrt(34))) < 1e-14
    with Sizing() as s:  # the triangle source in 2D too
        s.add_triangle_source_nd([[0, 0], [4, 0], [0, 4]], 0.1, 0.5)
        assert s(1, 1) == 0.1


def test_background_of_tetrahedra_interpolates():
    with Sizing() as s:
        pts = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
        s.set_background_nd(pts, [[0, 1, 2, 3]], [1, 2, 3, 4])
        assert abs(s.eval_nd([0.25, 0.25, 0.25]) - 2.5) < 1e-13
        assert math.isinf(s.eval_nd([2, 2, 2]))
        with pytest.raises(ValueError):
            s.set_background_nd(pts, [[0, 1, 2]], [1, 2, 3, 4])
        with pytest.raises(cvmesh.Error, match="tetrahedron 0"):
            s.set_background_nd(pts, [[0, 1, 2, 0]], [1, 2, 3, 4])


def test_errors_name_the_source_and_dimensions_do_not_mix():
    with Sizing() as s:
        s.add_point_source_nd([0, 0, 0], 0.5, 0.1)
        with pytest.raises(cvmesh.Error, match="point source 1"):
            s.add_point_source_nd([0, 0, 0], -1.0, 0.0)
        with pytest.raises(cvmesh.Error, match="triangle source 0"):
            s.add_triangle_source_nd([[0, 0, 0], [1, 0, 0], [0, math.nan, 0]], 0.1)
        with pytest.raises(cvmesh.Error, match="3D sources"):
            s.add_point_source(0, 0, 0.1)
        assert s.eval_nd([0, 0, 10]) == 0.5 + 0.1 * 10  # unchanged by the failures


def test_generate3_refines_around_a_point_source():
    def mean_near(mesh, r):
        p, t = mesh.points, mesh.tetrahedra
        e = np.unique(np.sort(np.concatenate([t[:, [i, j]] for i in range(4)
                                              for j in range(i + 1, 4)]), axis=1), axis=0)
        mid = 0.5 * (p[e[:, 0]] + p[e[:, 1]])
        near = np.linalg.norm(mid, axis=1) <= r
        return np.linalg.norm(p[e[near, 0]] - p[e[near, 1]], axis=1).mean()

    plain = Mesh.read(data3d("tetra.off"))
    plain.generate3(0.5, gen3_size_from_surface=0)
    sized = Mesh.read(data3d("tetra.off"))
    with Sizing() as s:
        s.add_point_source_nd([0, 0, 0], 0.08, 0.3)
        sized.generate3(0.5, sizing=s, gen3_size_from_surface=0)
    assert sized.check() and plain.check()
    assert len(sized.points) > len(plain.points)
    assert mean_near(sized, 0.25) < 0.6 * mean_near(plain, 0.25)
