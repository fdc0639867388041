"""Mesh.to_meshio() carries segments and weights; Mesh.from_meshio() reads
them back, through meshio's own files too."""

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh

meshio = pytest.importorskip("meshio")


def tri_set(tris):
    return sorted(tuple(t) for t in np.sort(np.asarray(tris), axis=1).tolist())


def boundary_edges(tris):
    e = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    u, c = np.unique(e, axis=0, return_counts=True)
    return sorted(map(tuple, u[c == 1].tolist()))


@pytest.fixture
def annulus():
    from conftest import domain_dir
    mesh = Mesh.read(domain_dir() / "annulus.poly", seed=1)
    mesh.refine(max_area=0.05)
    return mesh


def test_to_meshio_carries_segments_markers_and_weights(annulus):
    rng = np.random.default_rng(5)
    annulus.weights = 1e-4 * rng.random(len(annulus.points))
    mm = annulus.to_meshio()
    assert [b.type for b in mm.cells] == ["triangle", "line"]
    np.testing.assert_array_equal(mm.cells_dict["line"], annulus.segments)
    markers = mm.cell_data["marker"]
    np.testing.assert_array_equal(markers[1], annulus.segment_markers)
    assert not markers[0].any() and len(set(markers[1].tolist())) > 1
    np.testing.assert_array_equal(mm.point_data["weight"], annulus.weights)
    np.testing.assert_array_equal(mm.point_data["marker"], annulus.point_markers)
    assert np.all(mm.points[:, 2] == 0)


@pytest.mark.parametrize("ext", [".vtu", ".msh"])
def test_round_trip_through_meshio_files(annulus, tmp_path, ext):
    path = tmp_path / ("annulus" + ext)
    mm = annulus.to_meshio()
    if ext == ".msh":
        # gmsh keeps tags as gmsh:physical / gmsh:geometrical
        mm.cell_data = {"gmsh:physical": mm.cell_data["marker"],
                        "gmsh:geometrical": mm.cell_data["marker"]}
        mm.point_data = {}
        meshio.write(path, mm, file_format="gmsh22", binary=False)
    else:
        meshio.write(path, mm)
    back = Mesh.from_meshio(meshio.read(path))
    np.testing.assert_array_equal(back.points, annulus.points)
    assert tri_set(back.triangles) == tri_set(annulus.triangles)   # the hole stays a hole
    assert tri_set(back.segments) == tri_set(annulus.segments)
    got = dict(zip(map(tuple, np.sort(back.segments, 1).tolist()), back.segment_markers))
    want = dict(zip(map(tuple, np.sort(annulus.segments, 1).tolist()), annulus.segment_markers))
    assert got == want
    back.check()


def test_from_meshio_keeps_weights(annulus):
    annulus.weights = 1e-4 * np.random.default_rng(6).random(len(annulus.points))
    back = Mesh.from_meshio(annulus.to_meshio())
    np.testing.assert_array_equal(back.weights, annulus.weights)
    assert tri_set(back.triangles) == tri_set(annulus.triangles)
    back.check()


def grid(n, holes=()):
    """An n x n grid of unit squares, two triangles each, without the squares in holes."""
    xs = np.arange(n + 1, dtype=float)
    pts = np.array([[x, y] for y in xs for x in xs])
    tris = []
    for j in range(n):
        for i in range(n):
            if (i, j) in holes:
                continue
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            tris += [[a, b, c], [a, c, d]]
    return pts, np.array(tris)


def test_from_meshio_without_lines_uses_the_boundary_and_finds_holes():
    holes = {(2, 2), (2, 3), (3, 2), (3, 3), (0, 5), (5, 5)}    # a hole and two notches
    pts, tris = grid(6, holes)
    pts3 = np.column_stack([pts, np.zeros(len(pts))])
    mm = meshio.Mesh(pts3, [("triangle", tris)])
    mesh = Mesh.from_meshio(mm)
    assert boundary_edges(mesh.triangles) == boundary_edges(tris)
    assert tri_set(mesh.segments) == boundary_edges(tris)
    assert np.all(mesh.segment_markers == 1)
    # every triangle lies in a kept square: the hole and the notches stay empty
    centre = mesh.points[mesh.triangles].mean(axis=1)
    cells = {(int(x), int(y)) for x, y in np.floor(centre).tolist()}
    assert not cells & holes
    assert len(mesh.triangles) == len(tris)
    mesh.check()


def test_from_meshio_refuses_what_it_cannot_mesh():
    pts, tris = grid(2)
    lifted = np.column_stack([pts, np.zeros(len(pts))])
    lifted[4, 2] = 0.5
    with pytest.raises(cvmesh.InputError, match="point 4 has z = 0.5") as e:
        Mesh.from_meshio(meshio.Mesh(lifted, [("triangle", tris)]))
    assert e.value.item_index == 4
    with pytest.raises(cvmesh.ArgumentError, match="cell block 0 has type quad"):
        Mesh.from_meshio(meshio.Mesh(pts, [("quad", np.array([[0, 1, 4, 3]]))]))


def test_from_meshio_takes_2d_points_and_marker_names():
    pts, tris = grid(1)
    lines = np.array([[0, 1], [1, 3], [3, 2], [2, 0]])
    mm = meshio.Mesh(pts, [("triangle", tris), ("line", lines)],
                     cell_data={"gmsh:physical": [np.zeros(2, int), np.array([5, 6, 7, 8])]})
    mesh = Mesh.from_meshio(mm)
    got = dict(zip(map(tuple, np.sort(mesh.segments, 1).tolist()), mesh.segment_markers.tolist()))
    assert got == {(0, 1): 5, (1, 3): 6, (2, 3): 7, (0, 2): 8}
