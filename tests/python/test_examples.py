"""examples/python/*.py run to completion and write the mesh they describe."""

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import cvmesh

# Examples run elsewhere, with why: they are not 2D meshing scripts taking OUT.vtu.
ELSEWHERE = {
    "covolume_laplacian3d.py": "make check-examples runs it with the CLI and --check (3D dual)",
}
EXAMPLES = sorted(p for p in (Path(__file__).resolve().parents[2] / "examples" / "python").glob("*.py")
                  if p.name not in ELSEWHERE)

# What the mesh each example writes must be: the area of its domain and the
# smallest angle its refinement asks for. A new example needs an entry here.
EXPECT = {
    "channel.py": {"area": 3.0, "min_angle_deg": 28.0},
}


def test_every_example_says_what_it_meshes():
    assert EXAMPLES, "no examples/python/*.py found"
    missing = [p.name for p in EXAMPLES if p.name not in EXPECT]
    assert not missing, "add the expected mesh of %s to EXPECT" % missing


@pytest.mark.parametrize("script", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_example_writes_its_mesh(script, tmp_path):
    out = tmp_path / "out.vtu"
    r = subprocess.run([sys.executable, str(script), str(out)], cwd=tmp_path,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    want = EXPECT[script.name]
    # the file holds a valid mesh (read back through the library, checked
    # with exact predicates), the one the example reported
    mesh = cvmesh.Mesh.read(out)
    mesh.check()
    pts, tri = mesh.points, mesh.triangles
    said = re.search(r"(\d+) vertices, (\d+) triangles", r.stdout)
    assert said, r.stdout
    assert (len(pts), len(tri)) == (int(said.group(1)), int(said.group(2)))
    assert len(tri) > 0
    # it covers the domain: the area computed here from its triangles
    a, b, c = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert np.all(cross > 0), "a triangle is not counter-clockwise"
    assert 0.5 * cross.sum() == pytest.approx(want["area"], rel=1e-12)
    # and meets the angle it asked for
    assert mesh.quality().min_angle_deg >= want["min_angle_deg"]
