"""Status codes become exceptions of the right family, carrying the message."""

import math

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Status, capi


def test_hierarchy():
    for cls, builtin in ((cvmesh.InputError, ValueError), (cvmesh.OptionError, ValueError),
                         (cvmesh.ArgumentError, ValueError), (cvmesh.FileError, OSError),
                         (cvmesh.NoMemoryError, MemoryError), (cvmesh.StateError, RuntimeError),
                         (cvmesh.UnsupportedError, NotImplementedError),
                         (cvmesh.InternalError, RuntimeError)):
        assert issubclass(cls, cvmesh.Error) and issubclass(cls, builtin)
    assert cvmesh.error_class(capi.CVM_E_INPUT_INTERSECTING) is cvmesh.InputError
    assert cvmesh.error_class(capi.CVM_E_IO_FORMAT) is cvmesh.FileError
    assert cvmesh.error_class(capi.CVM_E_TOO_LARGE) is cvmesh.InputError
    assert cvmesh.error_class(capi.CVM_E_INTERNAL) is cvmesh.InternalError


def test_nonfinite_point_names_the_point():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    pts[3, 1] = math.nan
    mesh = Mesh()
    with pytest.raises(cvmesh.InputError) as info:
        mesh.set_points(pts)
    e = info.value
    assert e.status == Status.E_INPUT_NONFINITE
    assert e.status_name == "E_INPUT_NONFINITE"
    assert "point 3" in str(e)
    assert e.item_kind == cvmesh.Entity.INPUT_POINT and e.item_index == 3
    assert mesh.last_error == str(e)         # the handle keeps the message too


def test_bad_segment_index_names_the_segment(square_pslg):
    pts, _ = square_pslg
    mesh = Mesh.from_pslg(pts, [[0, 1], [1, 2], [2, 9], [3, 0]])
    with pytest.raises(cvmesh.InputError) as info:
        mesh.triangulate()
    assert info.value.status == Status.E_INPUT_INDEX
    assert "segment 2" in str(info.value)
    assert info.value.item_index == 2


def test_zero_length_segment(square_pslg):
    pts, _ = square_pslg
    mesh = Mesh.from_pslg(pts, [[0, 1], [1, 2], [2, 2], [3, 0]])
    with pytest.raises(cvmesh.InputError, match="segment 2") as info:
        mesh.triangulate()
    assert info.value.status == Status.E_INPUT_DEGENERATE


def test_intersecting_segments_when_not_split():
    pts = [[0, 0], [1, 1], [1, 0], [0, 1]]
    mesh = Mesh.from_pslg(pts, [[0, 1], [2, 3]], split_intersections=0, keep_convex_hull=1)
    with pytest.raises(cvmesh.InputError, match="segment") as info:
        mesh.triangulate()
    assert info.value.status == Status.E_INPUT_INTERSECTING


def test_collinear_input_is_degenerate():
    mesh = Mesh.from_points([[0, 0], [1, 1], [2, 2]])
    with pytest.raises(cvmesh.InputError) as info:
        mesh.triangulate()
    assert info.value.status == Status.E_INPUT_DEGENERATE


def test_empty_input():
    with pytest.raises(cvmesh.InputError) as info:
        Mesh().triangulate()
    assert info.value.status == Status.E_INPUT_EMPTY


def test_option_errors():
    mesh = Mesh()
    with pytest.raises(cvmesh.OptionError) as info:
        mesh.set_option("min_angle_deg", 90)
    assert info.value.status == Status.E_OPTION_RANGE
    b = cvmesh.option_bounds("min_angle_deg")
    assert "%g" % b.hi in str(info.value)       # the message quotes the bounds
    with pytest.raises(cvmesh.OptionError, match="unknown option 'no_such_option'"):
        mesh.set_option("no_such_option", 1)
    with pytest.raises(cvmesh.OptionError) as info:
        mesh.set_option(12345, 1)
    assert info.value.status == Status.E_OPTION_KEY
    with pytest.raises(cvmesh.OptionError):         # no handle: message from the status
        capi.cvm_option_bounds(12345)
    with pytest.raises(cvmesh.OptionError):
        Mesh(seed=0.5)                              # integer option


def test_state_errors(square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    with pytest.raises(cvmesh.StateError):
        mesh.insert_points([[0.5, 0.5]])
    with pytest.raises(cvmesh.StateError):
        mesh.check()
    mesh.close()
    with pytest.raises(cvmesh.StateError, match="closed"):
        mesh.triangulate()
    mesh.close()                                    # twice is fine


def test_file_errors(tmp_path):
    with pytest.raises(cvmesh.FileError) as info:
        Mesh.read(tmp_path / "missing.poly")
    assert isinstance(info.value, OSError)
    assert info.value.status == Status.E_IO_OPEN
    assert "missing.poly" in str(info.value)
    bad = tmp_path / "bad.node"
    bad.write_text("4 2 0 0\n0 0.0 0.0\n1 1.0 zero\n")
    with pytest.raises(cvmesh.FileError) as info:
        Mesh.read(bad)
    assert info.value.status == Status.E_IO_FORMAT
    assert "bad.node:3" in str(info.value)           # file and line


def test_errors_after_reading_use_the_files_numbers_and_lines(tmp_path):
    node = tmp_path / "d.node"
    node.write_text("# numbered from 1\n4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0 0\n")
    mesh = Mesh.read(node)
    mesh.set_option("reject_duplicates", 1)
    with pytest.raises(cvmesh.InputError,
                       match=r"d\.node:6: point 4 at \(0, 0\) duplicates point 1 \(line 3\)") as info:
        mesh.triangulate()
    assert info.value.status == Status.E_INPUT_DUPLICATE
    # a field with control bytes is echoed escaped, and the message stays valid text
    esc = tmp_path / "esc.node"
    esc.write_bytes(b"3 2 0 0\n1 0 0\n2 1 \x1b]0;x\x07\n3 0 1\n")
    with pytest.raises(cvmesh.FileError) as info:
        Mesh.read(esc)
    assert "found '\\x1b]0;x\\x07'" in str(info.value)
    assert "\x1b" not in str(info.value)


def test_write_errors(tmp_path, square_pslg):
    mesh = Mesh.from_pslg(*square_pslg)
    with pytest.raises(cvmesh.StateError):
        mesh.write(tmp_path / "early.vtu")
    mesh.triangulate()
    with pytest.raises(cvmesh.UnsupportedError):
        mesh.write(tmp_path / "mesh.unknown_extension")
    with pytest.raises(cvmesh.FileError):
        mesh.write(tmp_path / "no_such_dir" / "mesh.vtu")
    assert not (tmp_path / "no_such_dir").exists()


def test_raw_capi_errors_carry_the_message():
    m = capi.cvm_mesh_create()
    try:
        with pytest.raises(cvmesh.InputError, match="point 1"):
            capi.cvm_mesh_set_points(m, [[0.0, 0.0], [math.inf, 1.0]])
        assert "point 1" in capi.cvm_mesh_errmsg(m)
        with pytest.raises(cvmesh.ArgumentError):
            capi.cvm_mesh_set_point_markers(m, [1, 2, 3])   # count differs from points
    finally:
        capi.cvm_mesh_free(m)
    with pytest.raises(cvmesh.ArgumentError):
        capi.cvm_mesh_triangulate(None)                    # NULL handle
    assert capi.cvm_status_str(capi.CVM_E_NOMEM) == "out of memory"


def test_the_mesh_stays_usable_after_an_error(square_pslg):
    pts, segs = square_pslg
    mesh = Mesh.from_pslg(pts, segs)
    with pytest.raises(cvmesh.InputError):
        mesh.set_points([[0, 0], [math.nan, 0]])
    mesh.triangulate()                               # previous input kept
    assert len(mesh.triangles) == 2
