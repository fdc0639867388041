"""Marker names (Gmsh physical names) through the binding: set, list, .msh round trip."""

import pytest

import cvmesh
from cvmesh import Mesh, capi

pytestmark = pytest.mark.skipif(not hasattr(capi, "cvm_mesh_set_marker_name"),
                                reason="no marker names in this library")


def test_names_set_list_and_msh_round_trip(square_pslg, tmp_path):
    pts, segs = square_pslg
    mesh = Mesh.from_pslg(pts, segs, segment_markers=[1, 2, 3, 4])
    assert mesh.marker_names == {}
    mesh.set_marker_name(1, 1, "inlet")
    mesh.set_marker_name(2, 1, "plate")
    mesh.set_marker_name(1, 9, "unused")
    mesh.set_marker_name(1, 9, None)
    assert mesh.marker_names == {(1, 1): "inlet", (2, 1): "plate"}
    with pytest.raises(cvmesh.ArgumentError, match="double quote"):
        mesh.set_marker_name(1, 2, 'a"b')
    mesh.triangulate()
    mesh.write(tmp_path / "m.msh")
    text = (tmp_path / "m.msh").read_text()
    assert '2 1 "plate"' in text and '1 1 "inlet"' in text and '1 2 "marker_2"' in text
    again = Mesh.read(tmp_path / "m.msh")
    assert again.marker_names == {(1, 1): "inlet", (1, 2): "marker_2", (1, 3): "marker_3",
                                  (1, 4): "marker_4", (2, 1): "plate"}


def test_names_from_meshio_msh(tmp_path):
    meshio = pytest.importorskip("meshio")
    import numpy as np
    dom = meshio.Mesh(np.array([[0, 0], [2, 0], [2, 1], [0, 1]], float),
                      [("line", np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))],
                      cell_data={"gmsh:physical": [np.array([1, 2, 3, 4])],
                                 "gmsh:geometrical": [np.array([1, 2, 3, 4])]},
                      field_data={"bottom": np.array([1, 1]), "right": np.array([2, 1]),
                                  "top": np.array([3, 1]), "left": np.array([4, 1])})
    meshio.write(tmp_path / "d.msh", dom, file_format="gmsh22", binary=False)
    mesh = Mesh.read(tmp_path / "d.msh")
    assert mesh.marker_names == {(1, 1): "bottom", (1, 2): "right", (1, 3): "top", (1, 4): "left"}
    mesh.refine(size=0.3)
    mesh.write(tmp_path / "out.msh")
    back = meshio.read(tmp_path / "out.msh")
    assert {k: tuple(int(x) for x in v) for k, v in back.field_data.items()
            if k != "domain"} == {"bottom": (1, 1), "right": (2, 1), "top": (3, 1), "left": (4, 1)}
