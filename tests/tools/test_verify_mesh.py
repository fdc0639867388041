"""The independent checker rejects what it must: each case writes a small mesh
by hand, breaks one property and expects verify_mesh.py to name it."""

import json
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import verify_mesh  # noqa: E402

SQUARE = """4 2 0 1
1 0 0 1
2 1 0 1
3 1 1 1
4 0 1 1
4 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
0
"""


def write_mesh(d, pts, tris, weights=None):
    with open(d / "m.node", "w") as f:
        f.write("%d 2 %d 0\n" % (len(pts), 1 if weights else 0))
        for i, (x, y) in enumerate(pts):
            f.write("%d %r %r%s\n" % (i, x, y, " %r" % weights[i] if weights else ""))
    with open(d / "m.ele", "w") as f:
        f.write("%d 3 0\n" % len(tris))
        for i, t in enumerate(tris):
            f.write("%d %d %d %d\n" % ((i,) + tuple(t)))
    return str(d / "m")


def run(tmp_path, capsys, poly, pts, tris, *args, weights=None):
    (tmp_path / "in.poly").write_text(poly)
    prefix = write_mesh(tmp_path, pts, tris, weights)
    rc = verify_mesh.main([str(tmp_path / "in.poly"), prefix] + list(args))
    return rc, json.loads(capsys.readouterr().out.strip().splitlines()[-1])


# A square with a centre point: the Delaunay fan of four triangles.
FAN_PTS = [(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0.5)]
FAN = [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]


def test_accepts_a_valid_mesh(tmp_path, capsys):
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, FAN)
    assert rc == 0 and r["ok"] and r["area"] == 1.0 and r["euler"] == 1


def test_rejects_a_non_delaunay_edge(tmp_path, capsys):
    pts = [(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0.1)]
    # the edge 1-3 with apex 4 below: 0 lies inside the circle of (1, 3, 4)...
    tris = [(0, 1, 4), (1, 3, 4), (1, 2, 3), (3, 0, 4)]
    rc, r = run(tmp_path, capsys, SQUARE, pts, tris)
    assert rc == 1 and any("in-circle" in f for f in r["failures"])


def test_rejects_a_missing_triangle(tmp_path, capsys):
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, FAN[:3])
    assert rc == 1
    assert any(f.startswith("area") for f in r["failures"])
    assert any("boundary edge" in f for f in r["failures"])


def test_rejects_a_clockwise_triangle(tmp_path, capsys):
    tris = [(0, 4, 1)] + FAN[1:]
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, tris)
    assert rc == 1 and any("counter-clockwise" in f for f in r["failures"])


def test_rejects_an_uncovered_segment(tmp_path, capsys):
    # the diagonal 0-2 is a segment of the input but not an edge of the fan
    poly = SQUARE.replace("4 1\n1 1 2 1", "5 1\n5 1 3 1\n1 1 2 1")
    pts = FAN_PTS[:4] + [(0.4, 0.5)]
    rc, r = run(tmp_path, capsys, poly, pts, FAN)
    assert rc == 1 and any("segment 0" in f for f in r["failures"])


def test_power_test_and_power_vertex(tmp_path, capsys):
    # zero weights keep the fan regular; a centre weight below -0.5 lifts it above
    # the plane of the corners, so every edge at it fails the power test
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, FAN, "--weights", weights=[0.0] * 5)
    assert rc == 0 and r["pct_power_outside"] == 0.0
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, FAN, "--weights", weights=[0.0, 0.0, 0.0, 0.0, -0.6])
    assert rc == 1 and any("power" in f for f in r["failures"])
    assert r["pct_power_outside"] > 0


def test_min_angle_is_a_check(tmp_path, capsys):
    rc, r = run(tmp_path, capsys, SQUARE, FAN_PTS, FAN, "--min-angle", "46")
    assert rc == 1 and r["min_angle"] == pytest.approx(45.0)
