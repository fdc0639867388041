"""Mesh.optimise_dual3 through the binding: on the tetrahedron surface the
optimiser without flips keeps every tetrahedron and surface face, reports fewer
tetrahedra outside their power vertex, and its report agrees with a count made
here from the points, weights and tetrahedra; with flips (the default) the
vertices and the volume stay and two runs give the same mesh."""

import os
from pathlib import Path

import numpy as np

from cvmesh import Mesh

ROOT = Path(__file__).resolve().parents[2]


def data3d(name):
    d = os.environ.get("CVM_DATA3D_DIR")
    path = Path(d) / name if d else ROOT / "examples" / "data3d" / name
    assert path.is_file(), "%s is missing" % path
    return path


def outside_pct(p, w, tets):
    """% of tetrahedra whose power vertex lies outside them, by the signs of
    its barycentric coordinates in long double (ties are rare off a lattice)."""
    p = p.astype(np.longdouble)
    w = w.astype(np.longdouble)
    out = 0
    for t in tets:
        a = p[t]
        A = 2 * (a[1:] - a[0])
        r = (a[1:] ** 2).sum(1) - (a[0] ** 2).sum() - (w[t[1:]] - w[t[0]])
        c = np.linalg.solve(A.astype(float), r.astype(float))
        T = np.column_stack([a[1] - a[0], a[2] - a[0], a[3] - a[0]]).astype(float)
        lam = np.linalg.solve(T, (c - a[0]).astype(float))
        bary = np.concatenate([[1 - lam.sum()], lam])
        out += bool((bary < 0).any())
    return 100.0 * out / len(tets)


def test_optimise_dual3_keeps_the_mesh_and_lowers_the_outside_share():
    m = Mesh.read(data3d("tetra.off"))
    m.generate3(0.25, gen3_size_from_surface=0)
    tets0 = m.tetrahedra.copy()
    n0 = len(m.points)
    m.optimise_dual3(seed=3, dual3_flips=0)
    assert m.check()
    assert len(m.points) == n0
    assert np.array_equal(m.tetrahedra, tets0)
    before = m.report("dual3_outside_before_pct")
    after = m.report("dual3_outside_after_pct")
    assert after < before
    w = m.weights
    mine = outside_pct(m.points, w, m.tetrahedra)
    assert abs(mine - after) <= 100.0 / len(tets0) + 1e-9


def volume(p, t):
    a, b, c, d = (p[t[:, k]] for k in range(4))
    return abs(float(np.sum(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))) / 6.0))


def test_optimise_dual3_with_flips_keeps_vertices_and_volume():
    runs = []
    for _ in range(2):
        m = Mesh.read(data3d("tetra.off"))
        m.generate3(0.25, gen3_size_from_surface=0)
        n0 = len(m.points)
        vol0 = volume(m.points, m.tetrahedra)
        m.optimise_dual3(seed=3)
        assert m.check()
        assert len(m.points) == n0
        assert abs(volume(m.points, m.tetrahedra) - vol0) <= 1e-12 * vol0
        assert len(np.unique(m.tetrahedra)) == n0  # no vertex lost
        assert m.report("dual3_outside_after_pct") < m.report("dual3_outside_before_pct")
        runs.append((m.points.copy(), m.weights.copy(), m.tetrahedra.copy()))
    for a, b in zip(runs[0], runs[1]):
        assert np.array_equal(a, b)


def test_a_mesh_from_elsewhere_is_taken_and_optimised():
    """Bring your own mesh: another mesh's points and tetrahedra (reversed, so
    negatively oriented) given through Mesh.set_tetrahedra, then optimised."""
    src = Mesh.read(data3d("tetra.off"))
    src.generate3(0.25, gen3_size_from_surface=0)
    p, t = src.points.copy(), src.tetrahedra[:, ::-1].copy()
    m = Mesh()
    m.set_points(p)
    m.set_tetrahedra(t, attributes=np.ones(len(t)))
    assert m.check()
    assert np.array_equal(np.sort(m.tetrahedra, 1), np.sort(t, 1))
    assert abs(volume(m.points, m.tetrahedra) - volume(p, t)) <= 1e-12 * volume(p, t)
    m.optimise_dual3(seed=3)
    assert m.check()
    assert m.report("dual3_outside_after_pct") < m.report("dual3_outside_before_pct")
    bad = t.copy()
    bad[0, 1] = len(p)
    m2 = Mesh()
    m2.set_points(p)
    try:
        m2.set_tetrahedra(bad)
    except Exception as e:  # CVMError naming the tetrahedron
        assert "tetrahedron 0" in str(e)
    else:
        raise AssertionError("a bad index was accepted")
