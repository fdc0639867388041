"""close() from another thread, or from a callback, while a call runs on the handle."""

import threading
import time

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Sizing, Status


def run_in_thread(fn):
    """Start fn in a thread; returns (thread, result dict with "value" or "error")."""
    out = {}

    def target():
        try:
            out["value"] = fn()
        except BaseException as e:  # reported by the test, not lost in the thread
            out["error"] = e

    th = threading.Thread(target=target)
    th.start()
    return th, out


def test_mesh_close_waits_for_a_running_triangulate():
    pts = np.random.default_rng(2).random((300_000, 2))
    mesh = Mesh.from_points(pts)
    started = threading.Event()
    ticks = []

    def progress(stage, fraction):
        ticks.append(fraction)
        if not started.is_set():
            started.set()
            time.sleep(0.2)          # let close() arrive while the call runs
        return False

    th, out = run_in_thread(lambda: mesh.triangulate(progress=progress, every=2000))
    assert started.wait(60)
    mesh.close()                     # must wait for the call, not free under it
    ticks_at_close = len(ticks)
    th.join()
    assert "error" not in out, out.get("error")
    assert out["value"] == Status.OK # the call ran to its end on a live handle
    assert len(ticks) == ticks_at_close  # no progress after close() returned
    assert ticks_at_close > 1
    with pytest.raises(cvmesh.StateError, match="closed"):
        mesh.count("triangle")
    mesh.close()                     # closing twice stays fine


def test_mesh_close_from_its_own_progress_callback_raises():
    pts = np.random.default_rng(4).random((20_000, 2))
    mesh = Mesh.from_points(pts)
    with pytest.raises(cvmesh.StateError, match="progress callback"):
        mesh.triangulate(progress=lambda stage, fraction: mesh.close(), every=100)
    assert mesh.triangulate() == Status.OK   # still open and usable
    assert mesh.count("triangle") > 0
    mesh.close()


def test_sizing_close_waits_for_a_running_refine():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    mesh = Mesh.from_pslg(square, [[0, 1], [1, 2], [2, 3], [3, 0]])
    started = threading.Event()
    calls = []

    def size(x, y):
        calls.append(1)
        if not started.is_set():
            started.set()
            time.sleep(0.2)          # let close() arrive while the refinement runs
        return 0.02

    sizing = Sizing(callback=size)
    th, out = run_in_thread(lambda: mesh.refine(sizing=sizing, min_angle=25))
    assert started.wait(60)
    sizing.close()                   # must wait for the refinement
    calls_at_close = len(calls)
    th.join()
    assert "error" not in out, out.get("error")
    assert out["value"] == Status.OK
    assert len(calls) == calls_at_close  # the callback never ran after close()
    assert mesh.count("vertex") > 1000   # sized by the callback: h = 0.02 in a unit square
    mesh.check()
    with pytest.raises(cvmesh.StateError, match="closed"):
        sizing(0.5, 0.5)


def test_sizing_close_from_its_own_callback_raises():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    mesh = Mesh.from_pslg(square, [[0, 1], [1, 2], [2, 3], [3, 0]])
    sizing = Sizing()

    def size(x, y):
        sizing.close()
        return 0.1

    sizing.set_callback(size)
    with pytest.raises(cvmesh.StateError, match="sizing callback"):
        mesh.refine(sizing=sizing)
    sizing.set_callback(None)        # still open and usable
    sizing.set_uniform(0.1)
    assert sizing(0.5, 0.5) == 0.1
    sizing.close()


def test_collecting_an_unclosed_mesh_and_sizing_frees_them():
    for _ in range(200):
        mesh = Mesh.from_points([[0, 0], [1, 0], [0, 1]])
        mesh.triangulate()
        sizing = Sizing(uniform=0.5)
        del mesh, sizing             # __del__ frees without blocking
