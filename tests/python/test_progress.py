"""Progress callbacks, cancellation, Ctrl-C and the GIL."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import cvmesh
from cvmesh import Mesh, Stage, Status


@pytest.fixture(scope="module")
def many_points():
    return np.random.default_rng(7).random((50000, 2))


def test_callback_is_called(many_points):
    calls = []
    mesh = Mesh.from_points(many_points)
    status = mesh.triangulate(progress=lambda stage, f: calls.append((stage, f)), every=500)
    assert status == Status.OK
    assert len(calls) >= 10
    assert all(isinstance(s, Stage) for s, _ in calls)
    assert all(0.0 <= f <= 1.0 for _, f in calls)
    assert len(mesh.triangles) > 0


def test_persistent_callback(many_points):
    calls = []
    mesh = Mesh.from_points(many_points)
    mesh.set_progress(lambda stage, f: calls.append(f), every=1000)
    mesh.triangulate()
    n = len(calls)
    assert n > 0
    mesh.triangulate()
    assert len(calls) > n
    mesh.set_progress(None)                  # removed: no more calls
    before = len(calls)
    mesh.triangulate()
    assert len(calls) == before


def test_returning_true_cancels(many_points):
    mesh = Mesh.from_points(many_points)
    calls = []

    def stop_at_third(stage, f):
        calls.append(f)
        return len(calls) >= 3

    status = mesh.triangulate(progress=stop_at_third, every=100)
    assert status == Status.INCOMPLETE_CANCELLED
    assert mesh.last_status == Status.INCOMPLETE_CANCELLED
    assert len(calls) == 3
    assert mesh.count("triangle") == 0       # triangulation rolls back to empty
    assert mesh.triangulate() == Status.OK   # and the mesh is usable again
    assert mesh.count("triangle") > 0


def test_raising_cancels_and_propagates(many_points):
    class Stop(Exception):
        pass

    def boom(stage, f):
        raise Stop("from the callback")

    mesh = Mesh.from_points(many_points)
    with pytest.raises(Stop, match="from the callback"):
        mesh.triangulate(progress=boom, every=100)
    assert mesh.count("triangle") == 0
    mesh.triangulate()
    mesh.check()


def test_callback_must_not_reenter_its_mesh(many_points):
    mesh = Mesh.from_points(many_points)
    with pytest.raises(cvmesh.StateError, match="progress callback"):
        mesh.triangulate(progress=lambda stage, f: mesh.count("vertex"), every=100)
    other = Mesh.from_points([[0, 0], [1, 0], [0, 1]])
    other.triangulate()
    counts = []
    mesh.triangulate(progress=lambda stage, f: counts.append(other.count("triangle")), every=1000)
    assert counts and set(counts) == {1}     # another mesh may be used


def test_insert_points_progress_and_cancel(many_points):
    mesh = Mesh.from_points([[-1, -1], [2, -1], [2, 2], [-1, 2]])
    mesh.triangulate()
    calls = []
    ids = mesh.insert_points(many_points, progress=lambda s, f: calls.append(f), every=1000)
    assert calls and (ids >= 0).all()
    mesh2 = Mesh.from_points([[-1, -1], [2, -1], [2, 2], [-1, 2]])
    mesh2.triangulate()
    ids = mesh2.insert_points(many_points, progress=lambda s, f: True, every=1000)
    assert mesh2.last_status == Status.INCOMPLETE_CANCELLED
    assert (ids == cvmesh.REJECTED).any()    # the rest were not inserted
    mesh2.check()


def test_ctrl_c_interrupts_a_long_call():
    pts = np.random.default_rng(3).random((1_000_000, 2))
    mesh = Mesh.from_points(pts)
    timer = threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            mesh.triangulate()
            time.sleep(10)   # reached only when the call ended before the signal
    finally:
        timer.cancel()
    if mesh.count("triangle") > 0:
        pytest.skip("triangulation finished in %.3f s, before the signal"
                    % (time.monotonic() - started))
    assert mesh.triangulate() == Status.OK   # usable after the interrupt


def test_long_calls_release_the_gil():
    pts = np.random.default_rng(5).random((400_000, 2))
    mesh = Mesh.from_points(pts)
    mesh.interrupt_every = None              # no GIL round trips at all
    ticks = 0
    worker = threading.Thread(target=mesh.triangulate)
    worker.start()
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    assert mesh.count("triangle") > 0
    assert ticks > 5                         # the main thread ran meanwhile


def test_threads_with_separate_meshes_agree():
    pts = np.random.default_rng(9).random((20000, 2))
    ref = Mesh.from_points(pts)
    ref.triangulate()
    expected = ref.triangles
    results = [None] * 4

    def run(k):
        m = Mesh.from_points(pts)
        m.triangulate()
        results[k] = m.triangles

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, expected)
