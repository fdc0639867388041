"""Mesh.read of a conforming triangulation that is not Delaunay ("bring your
own mesh"): it is flipped to the constrained Delaunay triangulation, and the
flips are reported."""
import numpy as np
import pytest

import cvmesh


def write_sheared_grid(path, n):
    """An n x n grid as a legacy .vtk, each square split by its long diagonal
    after a shear: not Delaunay."""
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\nsheared grid\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        f.write("POINTS %d double\n" % ((n + 1) ** 2))
        for j in range(n + 1):
            for i in range(n + 1):
                f.write("%r %r 0\n" % (i + 0.8 * j, 0.5 * j))
        f.write("CELLS %d %d\n" % (2 * n * n, 8 * n * n))
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i
                b, c, d = a + 1, a + n + 2, a + n + 1
                f.write("3 %d %d %d\n3 %d %d %d\n" % (a, b, c, a, c, d))
        f.write("CELL_TYPES %d\n" % (2 * n * n) + "5\n" * (2 * n * n))


def test_read_flips_a_mesh_that_is_not_delaunay(tmp_path):
    n = 5
    path = tmp_path / "grid.vtk"
    write_sheared_grid(path, n)
    mesh = cvmesh.Mesh.read(path)
    assert mesh.report("read_flips") == n * n
    assert mesh.check()
    assert mesh.triangles.shape == (2 * n * n, 3)
    assert mesh.count("segment") == 4 * n
    mesh.write(tmp_path / "grid.vtu")
    again = cvmesh.Mesh.read(tmp_path / "grid.vtu")
    assert again.report("read_flips") == 0
    assert np.array_equal(again.triangles, mesh.triangles)


def test_read_refuses_an_inverted_triangle(tmp_path):
    path = tmp_path / "fold.vtk"
    path.write_text("# vtk DataFile Version 3.0\nfold\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                    "POINTS 4 double\n0 0 0 3 0 0 4 1 0 2 -1 0\n"
                    "CELLS 2 8\n3 0 1 2\n3 0 2 3\nCELL_TYPES 2\n5\n5\n")
    with pytest.raises(cvmesh.InputError, match="triangle 1 .* is inverted"):
        cvmesh.Mesh.read(path)
