"""Ctrl-C during Mesh.write: the write stops, no file is left or changed, and
KeyboardInterrupt is raised only then; a completed write is never reported
as failed."""

import os
import signal
import threading

import numpy as np
import pytest

import cvmesh
from cvmesh import Stage, Status

pytestmark = pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                                reason="SIGINT reaches the main thread only")


@pytest.fixture(scope="module")
def big_mesh():
    """About 200 000 triangles: a .vtu of some 20 MB, many progress checks."""
    mesh = cvmesh.Mesh.from_points(np.random.default_rng(11).random((100_000, 2)))
    mesh.triangulate()
    return mesh


def leftovers(directory):
    return sorted(p for p in os.listdir(directory) if ".tmp" in p)


def sigint_when_writing(mesh, after_ticks=3):
    """A thread that sends SIGINT to this process once the write has reported
    `after_ticks` progress steps (so the signal lands inside the write)."""
    writing = threading.Event()
    ticks = []

    def progress(stage, fraction):
        if stage == Stage.WRITE:
            ticks.append(fraction)
            if len(ticks) == after_ticks:
                writing.set()
        return False

    def killer():
        if writing.wait(30):
            os.kill(os.getpid(), signal.SIGINT)

    mesh.set_progress(progress, every=4096)
    th = threading.Thread(target=killer)
    th.start()
    return th, ticks


def test_sigint_from_a_thread_stops_the_write_and_leaves_no_file(big_mesh, tmp_path):
    target = tmp_path / "big.vtu"
    th, ticks = sigint_when_writing(big_mesh)
    try:
        with pytest.raises(KeyboardInterrupt):
            big_mesh.write(target)
    finally:
        th.join()
        big_mesh.set_progress(None)
    assert ticks and ticks[-1] < 1.0     # it stopped part-way
    assert not target.exists()
    assert leftovers(tmp_path) == []
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_sigint_keeps_the_old_file_of_every_target(big_mesh, tmp_path):
    old = {}
    for ext in (".node", ".ele", ".edge"):
        (tmp_path / ("m" + ext)).write_text("old " + ext)
        old[ext] = "old " + ext
    th, _ = sigint_when_writing(big_mesh)
    try:
        with pytest.raises(KeyboardInterrupt):
            big_mesh.write(tmp_path / "m.node")
    finally:
        th.join()
        big_mesh.set_progress(None)
    for ext, text in old.items():
        assert (tmp_path / ("m" + ext)).read_text() == text
    assert leftovers(tmp_path) == []


def test_sigint_on_a_timer_either_interrupts_or_completes(big_mesh, tmp_path):
    # whatever moment the signal lands at, exactly one of: KeyboardInterrupt
    # and no file, or a complete file and no exception from write()
    outcomes = set()
    for k, delay in enumerate((0.0, 0.02, 0.05, 0.1, 0.2, 0.5, 5.0)):
        target = tmp_path / ("t%d.vtu" % k)
        timer = threading.Timer(delay, os.kill, (os.getpid(), signal.SIGINT))
        try:
            try:
                timer.start()
                big_mesh.write(target)
                outcome = "written"
            except KeyboardInterrupt:
                outcome = "interrupted"
            finally:
                timer.join() if delay < 5 else timer.cancel()
        except KeyboardInterrupt:
            outcome = "after"    # landed after write() returned: not its business
        if outcome == "interrupted":
            assert not target.exists()
        elif outcome == "written":
            back = cvmesh.Mesh.read(target)
            assert back.count("triangle") == big_mesh.count("triangle")
        assert leftovers(tmp_path) == []
        outcomes.add(outcome)
    assert "interrupted" in outcomes and "written" in outcomes


def test_a_completed_write_reports_no_interrupt(big_mesh, tmp_path):
    target = tmp_path / "done.vtu"
    big_mesh.write(target)
    assert big_mesh.last_status == Status.OK
    assert cvmesh.Mesh.read(target).count("triangle") == big_mesh.count("triangle")


def test_a_cancelling_progress_callback_leaves_no_file(big_mesh, tmp_path):
    target = tmp_path / "c.vtu"
    big_mesh.set_progress(lambda stage, f: stage == Stage.WRITE and f > 0.3, every=4096)
    try:
        big_mesh.write(target)
    finally:
        big_mesh.set_progress(None)
    assert big_mesh.last_status == Status.INCOMPLETE_CANCELLED
    assert not target.exists() and leftovers(tmp_path) == []


def test_a_custom_sigint_handler_is_respected(big_mesh, tmp_path):
    class Stop(Exception):
        pass

    def handler(signum, frame):
        raise Stop()

    old = signal.signal(signal.SIGINT, handler)
    th, _ = sigint_when_writing(big_mesh)
    try:
        with pytest.raises(Stop):
            big_mesh.write(tmp_path / "h.vtu")
    finally:
        th.join()
        big_mesh.set_progress(None)
        signal.signal(signal.SIGINT, old)
    assert not (tmp_path / "h.vtu").exists() and leftovers(tmp_path) == []
