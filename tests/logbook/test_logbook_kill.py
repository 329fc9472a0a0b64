"""A process killed (SIGKILL) during a write leaves the previous file intact, or no file; the
resumed run's log equals an uninterrupted one."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import h5py
import logbook_samples as samples
import pytest

from rig.logbook import LogWriter, point_indices, read_point, staging_dir

pytestmark = pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="needs POSIX SIGKILL")
SCRIPT = Path(samples.__file__)
GIVE_UP_S = 60.0  # a safety net against a hung child, not a timing assertion


def _run_and_kill(mode: str, log: Path, marker: Path, *, ready=None) -> None:
    """Start the child in ``mode``, wait until it signals (or ``ready()``), then SIGKILL it."""
    child = subprocess.Popen([sys.executable, str(SCRIPT), mode, str(log), str(marker)])
    try:
        waited = 0.0
        while not (marker.exists() and (ready is None or ready())):
            assert child.poll() is None, f"child ended early with code {child.returncode}"
            assert waited < GIVE_UP_S, "child never reached the point to kill it at"
            time.sleep(0.01)
            waited += 0.01
        os.kill(child.pid, signal.SIGKILL)
    finally:
        if child.poll() is None:
            child.kill()
        child.wait()
    assert child.returncode == -signal.SIGKILL


def _finish(log: Path) -> None:
    samples.write_run(log)


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("reference") / "run.h5"
    samples.write_run(path)
    return path


def test_kill_while_writing_a_point(reference: Path, tmp_path: Path) -> None:
    log = tmp_path / "run.h5"
    _run_and_kill("point", log, tmp_path / "marker")
    assert not log.exists()  # no file rather than a half-written one
    journal = staging_dir(log) / "points.journal"
    torn = journal.stat().st_size
    assert samples.journal_frames(log) == [0, 1, 2]  # the half-written frame of point 3 is not one
    assert LogWriter(log, samples.metadata()).done == {0, 1, 2}  # resumes at point 3
    assert journal.stat().st_size < torn  # the torn frame is cut off
    _finish(log)
    assert log.read_bytes() == reference.read_bytes()


def test_kill_while_finalizing_keeps_previous_log(reference: Path, tmp_path: Path) -> None:
    log = tmp_path / "run.h5"
    samples.write_run(log, [0], seed=99)  # the previous log at this path
    previous = log.read_bytes()
    _run_and_kill("finalize", log, tmp_path / "marker")
    assert log.read_bytes() == previous
    assert LogWriter(log, samples.metadata()).done == set(range(samples.N_POINTS))
    _finish(log)
    assert log.read_bytes() == reference.read_bytes()


def test_kill_while_writing_reduced_keeps_log(reference: Path, tmp_path: Path) -> None:
    log = tmp_path / "run.h5"
    log.write_bytes(reference.read_bytes())
    _run_and_kill("reduced", log, tmp_path / "marker")
    assert log.read_bytes() == reference.read_bytes()
    with h5py.File(log, "r") as f:
        assert "reduced" not in f


def test_kill_at_an_arbitrary_moment(tmp_path: Path) -> None:
    log = tmp_path / "run.h5"
    _run_and_kill("free", log, tmp_path / "marker", ready=lambda: len(samples.journal_frames(log)) >= 2)
    assert not log.exists()
    writer = LogWriter(log, samples.metadata())
    assert len(writer.done) >= 2 and writer.done == set(range(len(writer.done)))
    writer.finalize()
    for k in point_indices(log):  # every point that survived is complete and exact
        assert read_point(log, k) == samples.point(k, n_samples=20_000)
