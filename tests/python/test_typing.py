"""Type hints, py.typed, and how Status, Mesh and Quality print."""

import dataclasses
import inspect
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import cvmesh


def test_package_ships_py_typed():
    assert (Path(cvmesh.__file__).parent / "py.typed").is_file()


def _public_functions():
    for cls in (cvmesh.Mesh, cvmesh.Sizing):
        for name, member in vars(cls).items():
            if name.startswith("_") and name not in ("__init__", "__call__"):
                continue
            if isinstance(member, property):
                yield "%s.%s" % (cls.__name__, name), member.fget
            elif isinstance(member, (classmethod, staticmethod)):
                yield "%s.%s" % (cls.__name__, name), member.__func__
            elif inspect.isfunction(member):
                yield "%s.%s" % (cls.__name__, name), member
    for name in ("option_bounds", "version", "error_class"):
        yield name, getattr(cvmesh, name)


def test_every_public_function_is_annotated():
    missing = []
    for name, fn in _public_functions():
        sig = inspect.signature(fn)
        if sig.return_annotation is inspect.Signature.empty:
            missing.append(name + " -> ?")
        for p in list(sig.parameters.values())[1:] if "." in name else sig.parameters.values():
            if p.annotation is inspect.Parameter.empty:
                missing.append("%s(%s)" % (name, p.name))
    assert not missing, "not annotated: " + ", ".join(missing)


@pytest.mark.skipif(shutil.which("mypy") is None and
                    not (Path(sys.executable).parent / "mypy").exists(),
                    reason="mypy not installed")
def test_user_code_type_checks_strictly(tmp_path):
    user = tmp_path / "user.py"
    user.write_text(textwrap.dedent("""\
        import numpy as np
        import numpy.typing as npt
        import cvmesh

        pts = np.array([[0.0, 0], [1, 0], [1, 1], [0, 1]])
        mesh = cvmesh.Mesh.from_pslg(pts, [[0, 1], [1, 2], [2, 3], [3, 0]], seed=1)
        status: cvmesh.Status = mesh.refine(min_angle=25.0, max_area=0.01)
        tris: npt.NDArray[np.int32] = mesh.triangles
        xy: npt.NDArray[np.float64] = mesh.points
        q: cvmesh.Quality = mesh.quality()
        b: cvmesh.Bounds = cvmesh.option_bounds("seed")
        hi: float = b.hi
        ok: bool = status == cvmesh.Status.OK
        reveal_type(mesh)
        reveal_type(cvmesh.Status.E_INPUT_INDEX)
        """))
    mypy = shutil.which("mypy") or str(Path(sys.executable).parent / "mypy")
    r = subprocess.run([mypy, "--strict", "--no-incremental", "--cache-dir", str(tmp_path / "c"),
                        str(user)], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert 'Revealed type is "cvmesh.Mesh"' in r.stdout
    assert 'Revealed type is "cvmesh.Status"' in r.stdout


def test_status_prints_as_its_name():
    s = cvmesh.Status.E_INPUT_INDEX
    assert str(s) == "Status.E_INPUT_INDEX"
    assert "%s" % s == "Status.E_INPUT_INDEX"
    assert "{}".format(s) == "Status.E_INPUT_INDEX"
    assert "%d" % s == str(int(s)) and "{:d}".format(s) == str(int(s))
    assert s == int(s) and s.is_error
    assert str(cvmesh.Option.SEED) == "Option.SEED"
    # the name of an error's status, too
    with pytest.raises(cvmesh.InputError) as e:
        cvmesh.Mesh.from_pslg([[0, 0], [1, 0], [0, 1]], [[0, 7]]).triangulate()
    assert str(cvmesh.Status(e.value.status)) == "Status." + e.value.status_name


def test_repr_right_after_read(poly_file):
    mesh = cvmesh.Mesh.read(poly_file)
    n = mesh.count("input_point")
    assert n > 0
    assert repr(mesh) == "<cvmesh.Mesh: input of %d points, %d segments; not triangulated>" % (
        n, mesh.count("input_segment"))
    mesh.triangulate()
    assert repr(mesh) == "<cvmesh.Mesh: %d vertices, %d triangles, %d segments>" % (
        len(mesh.points), len(mesh.triangles), len(mesh.segments))
    mesh.close()
    assert repr(mesh) == "<cvmesh.Mesh (closed)>"


def test_repr_of_an_empty_mesh_and_from_a_progress_callback(square_pslg):
    assert repr(cvmesh.Mesh()) == "<cvmesh.Mesh: empty>"
    seen = []
    mesh = cvmesh.Mesh.from_pslg(*square_pslg)
    mesh.refine(max_area=0.001, progress=lambda st, f: seen.append(repr(mesh)), every=50)
    assert seen and set(seen) == {"<cvmesh.Mesh (busy)>"}


def test_quality_is_a_dataclass_with_a_compact_str(square_pslg):
    mesh = cvmesh.Mesh.from_pslg(*square_pslg, seed=1)
    mesh.refine(min_angle=25, max_area=0.01)
    q = mesh.quality()
    assert dataclasses.is_dataclass(q)
    text = str(q)
    lines = text.splitlines()
    assert lines[0] == "Quality:" and 3 <= len(lines) <= 16
    assert all(len(line) <= 80 for line in lines)
    assert "angles %.4g..%.4g deg" % (q.min_angle_deg, q.max_angle_deg) in text
    assert "angles per 10 degrees: " + " ".join(str(int(c)) for c in q.hist_angle_deg) in text
    assert "array(" not in text and "nan" not in text
    assert repr(q).startswith("Quality(min_angle_deg=")
    assert np.isclose(q.as_dict()["area"], 1.0)
