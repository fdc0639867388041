"""Mesh.refine() and Sizing: bounds met, sizes honoured, errors, limits, callbacks."""

import math
import warnings

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Sizing, Status, capi

pytestmark = pytest.mark.skipif(not hasattr(capi, "cvm_mesh_refine"),
                                reason="cvm_mesh_refine() is not in this library")


def edge_lengths(mesh):
    p = mesh.points[mesh.edges]
    return np.hypot(*(p[:, 1] - p[:, 0]).T)


@pytest.mark.parametrize("algorithm", ["frontal", "delaunay", cvmesh.Algorithm.FRONTAL])
def test_refine_meets_the_angle_bound(square_pslg, algorithm):
    mesh = Mesh.from_pslg(*square_pslg)
    assert mesh.refine(algorithm=algorithm, min_angle=25, size=0.1) == Status.OK
    mesh.check()
    assert mesh.quality().min_angle_deg >= 25 - 1e-9
    assert mesh.triangle_min_angles().min() >= 25 - 1e-9
    assert len(mesh.triangles) > 50
    assert mesh.quality().area == pytest.approx(1.0)


def test_refine_without_triangulate_first_and_with_max_area(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(max_area=0.001, min_angle=20)
    p = mesh.points[mesh.triangles]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    areas = 0.5 * np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    assert areas.max() <= 0.001 * (1 + 1e-12)


def test_sizing_sources_make_a_graded_mesh(square_pslg):
    sizing = Sizing(uniform=0.2)
    sizing.add_point_source(0.0, 0.0, h=0.02, growth=0.3)
    assert sizing(0.0, 0.0) == pytest.approx(0.02)
    assert sizing(1.0, 1.0) == pytest.approx(0.2)
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(sizing=sizing, min_angle=25)
    mesh.check()
    mid = mesh.points[mesh.edges].mean(axis=1)
    lengths = edge_lengths(mesh)
    near = np.hypot(*mid.T) < 0.1
    assert lengths[near].mean() < 0.7 * lengths[~near].mean()


def test_callable_size(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(size=lambda x, y: 0.03 + 0.2 * x, min_angle=20)
    mid = mesh.points[mesh.edges].mean(axis=1)
    lengths = edge_lengths(mesh)
    assert lengths[mid[:, 0] < 0.2].mean() < lengths[mid[:, 0] > 0.8].mean()


def test_sizing_callback_is_evaluated_directly():
    s = Sizing(uniform=0.5, callback=lambda x, y: 0.1 + x)
    assert s(0.2, 0.0) == pytest.approx(0.3)
    assert s(3.0, 0.0) == pytest.approx(0.5)        # the minimum of the sources
    with pytest.raises(cvmesh.StateError, match="sizing callback"):
        s.set_callback(lambda x, y: s(x, y))        # re-entering its own sizing
        s(0.0, 0.0)


def test_sizing_errors():
    s = Sizing()
    assert math.isinf(s(0.5, 0.5))
    with pytest.raises(cvmesh.ArgumentError, match="uniform size") as info:
        s.set_uniform(-1)
    assert info.value.status == Status.E_ARGUMENT
    with pytest.raises(cvmesh.InputError, match="uniform size"):
        s.set_uniform(math.nan)
    s.add_point_source(0, 0, 0.1)
    with pytest.raises(cvmesh.ArgumentError, match="point source 1"):
        s.add_point_source(0, 0, 0.1, growth=-1)
    with pytest.raises(cvmesh.ArgumentError, match="line source 0"):
        s.add_line_source(0, 0, 1, 1, h=0)
    with pytest.raises(cvmesh.ArgumentError, match="grading"):
        s.set_automatic(1.0, -1.0)
    with pytest.raises(cvmesh.ArgumentError, match="node 1"):
        s.set_background([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], [1.0, -2.0, 1.0])
    with pytest.raises(cvmesh.InputError, match="triangle 0"):
        s.set_background([[0, 0], [1, 0], [0, 1]], [[0, 1, 5]], [1.0, 2.0, 1.0])
    # indices are checked, never cast: 2**32 + 3 is not 3, 1.7 is not 1 (as for segments)
    pts, h = [[0, 0], [1, 0], [0, 1]], [1.0, 2.0, 1.0]
    with pytest.raises(OverflowError, match=r"background triangles\[0, 2\] = 4294967299 does not fit"):
        s.set_background(pts, np.array([[0, 1, 2**32 + 3]], dtype=np.int64), h)
    with pytest.raises(TypeError, match="background triangles must be an integer array"):
        s.set_background(pts, np.array([[0, 1, 1.7]]), h)
    with pytest.raises(TypeError, match="background triangles must be an integer array"):
        s.set_background(pts, [[0, 1, 1.7]], h)
    with pytest.raises(TypeError):
        s.set_callback(42)
    s.close()
    with pytest.raises(cvmesh.StateError):
        s.set_uniform(1)


def test_sizing_callback_errors(square_pslg):
    class Boom(Exception):
        pass

    def boom(x, y):
        raise Boom("sizing says no")

    mesh = Mesh.from_pslg(*square_pslg)
    with pytest.raises(Boom, match="sizing says no"):
        mesh.refine(size=boom)
    mesh.check()                                  # still a valid mesh
    with pytest.raises(cvmesh.ArgumentError, match="sizing callback"):
        mesh.refine(size=lambda x, y: -1.0)
    with pytest.raises(cvmesh.InputError, match="sizing callback"):
        mesh.refine(size=lambda x, y: math.inf)
    with pytest.raises(TypeError):
        mesh.refine(size=lambda x, y: "big")


def test_refine_argument_errors(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    with pytest.raises(cvmesh.ArgumentError, match="known: delaunay, frontal"):
        mesh.refine(algorithm="bogus")
    with pytest.raises(ValueError, match="size or sizing"):
        mesh.refine(size=0.1, sizing=Sizing(uniform=0.1))
    with pytest.raises(cvmesh.OptionError):
        mesh.refine(min_angle=60)


def test_limits_and_cancellation(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    with pytest.warns(cvmesh.IncompleteWarning, match="STEINER_LIMIT"):
        status = mesh.refine(size=0.01, max_steiner=10)
    assert status == Status.INCOMPLETE_STEINER_LIMIT
    mesh.check()
    mesh2 = Mesh.from_pslg(*square_pslg)
    mesh2.triangulate()
    with warnings.catch_warnings():
        warnings.simplefilter("error")            # a requested stop is not warned about
        status = mesh2.refine(size=0.005, progress=lambda stage, f: True, every=10)
    assert status == Status.INCOMPLETE_CANCELLED
    mesh2.check()


def test_refine_progress_reports_the_stage(square_pslg):
    stages = set()
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.triangulate()
    mesh.refine(size=0.01, progress=lambda stage, f: stages.add(stage), every=50)
    assert cvmesh.Stage.REFINE in stages


def test_refine_markers_on_boundary_steiner_points(square_pslg):
    pts, segs = square_pslg
    mesh = Mesh.from_pslg(pts, segs, markers=[1, 1, 1, 1], segment_markers=[5, 5, 5, 5])
    mesh.refine(size=0.1)
    x, y = mesh.points.T
    on_boundary = (x == 0) | (x == 1) | (y == 0) | (y == 1)
    marks = mesh.point_markers
    assert (marks[~on_boundary] == 0).all()
    assert set(marks[on_boundary][4:].tolist()) <= {5}


def test_automatic_and_background_sizing(square_pslg):
    bg = Sizing()
    bg.set_background([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1, 2], [0, 2, 3]],
                      [0.05, 0.3, 0.3, 0.3])
    assert bg(0.0, 0.0) == pytest.approx(0.05)
    assert bg(0.5, 0.25) == pytest.approx(0.05 + 0.25 * 0.5)  # linear in the first triangle
    assert math.isinf(bg(2.0, 2.0))
    auto = Sizing()
    auto.set_automatic(8, 4)
    meshes = []
    for s in (bg, auto):
        mesh = Mesh.from_pslg(*square_pslg)
        mesh.refine(sizing=s, algorithm="frontal")
        mesh.check()
        meshes.append(mesh)
    # the square's feature size is 1: edges about 1/8 with the automatic size
    assert 40 < meshes[1].triangles.shape[0] < 600
    assert meshes[0].triangles.shape[0] > meshes[1].triangles.shape[0] / 4


def test_boundary_grading_carries_a_fine_wall_inwards():
    """The unit square with its bottom side in 50 segments of 0.02: with the
    boundary grading the triangles along that side stay fine a few layers up
    (the size is capped by 0.02 + 0.3 y there, well below what the refiner's own
    grading gives); bad slopes raise."""
    n = 50
    pts = np.concatenate([np.c_[np.arange(n + 1) / n, np.zeros(n + 1)], [[1, 1], [0, 1]]])
    segs = np.c_[np.arange(n + 3), (np.arange(n + 3) + 1) % (n + 3)]

    def band_edge(sizing):
        mesh = Mesh.from_pslg(pts, segs)
        mesh.refine(algorithm="frontal", sizing=sizing)
        mesh.check()
        p = mesh.points[mesh.triangles]
        cy = p[:, :, 1].mean(axis=1)
        mean_edge = np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2).mean(axis=1)
        return mean_edge[(cy > 0.1) & (cy < 0.2)].max()

    uniform = Sizing(uniform=0.3)
    graded = Sizing(uniform=0.3)
    graded.set_boundary_grading(0.3)
    fine = band_edge(graded)
    assert fine <= 1.5 * (0.02 + 0.3 * 0.2)   # the size rule against the expected cap
    assert fine < 0.85 * band_edge(uniform)   # measured 0.077 against 0.102
    for bad, error in ((-1.0, cvmesh.ArgumentError), (float("nan"), cvmesh.InputError)):
        with pytest.raises(error):
            graded.set_boundary_grading(bad)


def test_aflr_layers(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    mesh.refine(algorithm="aflr", size=0.1)
    layers = mesh.layer_index
    assert layers.shape == (mesh.count("triangle"),)
    assert layers.dtype == np.float64
    assert layers.min() >= 0 and layers.min() < 1.05
    mesh.refine(algorithm="delaunay", size=0.05)
    assert (mesh.layer_index == -1).all()


def test_resample_boundary_through_the_option_setter():
    """CVM_OPT_KEEP_SEGMENT_VERTICES = 0 through the generic setter: the circles of an
    annulus (spacing 0.1) are re-discretised at the size 0.3, inner input points get -1
    in the input map, the new boundary points lie on the input polygon."""
    n_in, n_out = 64, 128
    t_in = 2 * np.pi * np.arange(n_in) / n_in
    t_out = 2 * np.pi * np.arange(n_out) / n_out
    pts = np.concatenate([np.c_[np.cos(t_in), np.sin(t_in)], 4 * np.c_[np.cos(t_out), np.sin(t_out)]])
    segs = np.concatenate([np.c_[np.arange(n_in), (np.arange(n_in) + 1) % n_in],
                           n_in + np.c_[np.arange(n_out), (np.arange(n_out) + 1) % n_out]])
    kept, resampled = [], []
    for keep in (1, 0):
        mesh = Mesh.from_pslg(pts, segs, holes=[[0.0, 0.0]])
        mesh.set_option(cvmesh.Option.KEEP_SEGMENT_VERTICES, keep)
        assert mesh.refine(algorithm="frontal", size=0.3) == Status.OK
        mesh.check()
        (kept if keep else resampled).append(mesh)
    a, b = kept[0], resampled[0]
    assert len(b.segments) < len(a.segments) < 300
    assert (a.input_map >= 0).all()
    removed = (b.input_map < 0).sum()
    assert 150 <= removed < n_in + n_out
    r = np.hypot(*b.points[np.unique(b.segments)].T)
    # boundary points on (or, where refinement split a new piece, near) the input circles
    assert (((r <= 1 + 1e-12) & (r >= 0.97)) | ((r <= 4 + 1e-12) & (r >= 3.95))).all()
    assert b.quality().min_angle_deg >= 30 - 1e-9
