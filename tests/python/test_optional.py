"""meshio and matplotlib integration, when those packages are installed."""

import numpy as np
import pytest

from cvmesh import Mesh


@pytest.fixture
def mesh():
    m = Mesh.from_points(np.random.default_rng(2).random((50, 2)))
    m.triangulate()
    return m


def test_to_meshio(mesh):
    meshio = pytest.importorskip("meshio")
    mm = mesh.to_meshio()
    assert isinstance(mm, meshio.Mesh)
    np.testing.assert_array_equal(mm.points[:, :2], mesh.points)
    np.testing.assert_array_equal(mm.cells_dict["triangle"], mesh.triangles)


def test_plot(mesh):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots()
    assert mesh.plot(ax) is ax
    assert mesh.plot(ax, color_by=None) is ax
    with pytest.raises(ValueError):
        mesh.plot(ax, color_by="colour")
    plt.close(fig)


def test_missing_packages_are_reported(mesh, monkeypatch):
    import builtins
    real_import = builtins.__import__

    def fake_import(name, *args, **kwargs):
        if name.split(".")[0] in ("meshio", "matplotlib"):
            raise ImportError(name)
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", fake_import)
    with pytest.raises(ImportError, match="pip install meshio"):
        mesh.to_meshio()
    with pytest.raises(ImportError, match="pip install matplotlib"):
        mesh.plot()
