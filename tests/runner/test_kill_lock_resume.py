"""A run killed (SIGKILL) at any moment resumes to the same log and reduced.csv; one run per folder.

The child (tests/runner/run_child.py) runs the fake stand's scene and stops at a chosen moment;
the parent kills it, runs the scene again in this process and compares every object of log.h5
(all datasets and attributes but the start time) and the text of reduced.csv with an
uninterrupted run. The lock tests let a child hold the folder and try a second run into it.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

import rig.cli
from rig.logbook import staging_dir
from rig.runner import run_scene
from rig.runner.folder_lock import LOCK_NAME, FolderLockedError
from tests.runner import run_child
from tests.runner.fake_stand import register

pytestmark = pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="needs POSIX SIGKILL and flock")
REPO = Path(__file__).resolve().parents[2]
GIVE_UP_S = 60.0  # a safety net against a hung child, not a timing assertion


@pytest.fixture(autouse=True)
def _fake_stand(monkeypatch):
    register(monkeypatch)


def _start(moment: str, folder: Path, marker: Path) -> subprocess.Popen:
    child = subprocess.Popen([sys.executable, "-m", "tests.runner.run_child", moment, str(folder), str(marker)],
                             cwd=REPO)
    waited = 0.0
    while not marker.exists():
        assert child.poll() is None, f"child ended early with code {child.returncode}"
        assert waited < GIVE_UP_S, "child never reached the moment"
        time.sleep(0.01)
        waited += 0.01
    return child


def _kill(child: subprocess.Popen) -> None:
    os.kill(child.pid, signal.SIGKILL)
    child.wait()
    assert child.returncode == -signal.SIGKILL


def content(log: Path) -> dict:
    """Every object of an HDF5 file but the run's start time: {path: (attrs, data)}."""
    out = {}
    with h5py.File(log, "r") as handle:
        def visit(name, obj):
            attrs = {k: np.asarray(v).tolist() for k, v in sorted(obj.attrs.items()) if k != "created_utc"}
            data = np.asarray(obj[()]).tolist() if isinstance(obj, h5py.Dataset) else None
            out[name] = (attrs, data)
        visit("/", handle)
        handle.visititems(visit)
    return out


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    import rig.stands

    rig.stands.STANDS["fake"] = "tests.runner.fake_stand:FakeStand"
    try:
        folder = tmp_path_factory.mktemp("reference")
        run_scene(run_child.scene(), folder, progress=False)
    finally:
        del rig.stands.STANDS["fake"]
    return folder


@pytest.mark.parametrize("moment", ["before_point_2", "torn_frame", "finalize", "outputs", "reduced"])
def test_killed_run_resumes_to_the_uninterrupted_result(moment, reference, tmp_path):
    folder = tmp_path / "run"
    _kill(_start(moment, folder, tmp_path / "marker"))
    assert (folder / LOCK_NAME).exists()  # the killed holder's file, unlocked: no obstacle
    report = run_scene(run_child.scene(), folder, progress=False)
    assert content(folder / "log.h5") == content(reference / "log.h5")
    assert (folder / "reduced.csv").read_text() == (reference / "reduced.csv").read_text()
    assert not staging_dir(folder / "log.h5").exists() and not (folder / LOCK_NAME).exists()
    assert sorted(p.name for p in folder.iterdir()) == sorted(p.name for p in reference.iterdir())
    if moment in ("outputs", "reduced"):  # the log was complete: nothing is simulated again
        assert report.resumed == report.planned == 4 and "0 simulated now" in report.summary


def test_second_run_into_a_held_folder_is_refused_and_the_first_is_unchanged(reference, tmp_path, capsys):
    folder, marker = tmp_path / "same", tmp_path / "marker"
    first = _start("pause", folder, marker)
    try:
        with pytest.raises(FolderLockedError, match=rf"{folder} is in use by process {first.pid} \(rig run fake"):
            run_scene(run_child.scene(), folder, progress=False)
        (tmp_path / "scene.toml").write_text(run_child.scene().text)
        assert rig.cli.main(["run", str(tmp_path / "scene.toml"), "-o", str(folder)]) == 2
        assert f"in use by process {first.pid}" in capsys.readouterr().err
        assert rig.cli.main(["reduce", str(folder / "log.h5")]) == 2  # the log being written is not read
        assert "being written" in capsys.readouterr().err
        marker.with_name(marker.name + ".go").touch()
        assert first.wait(timeout=GIVE_UP_S) == 0
    finally:
        if first.poll() is None:
            first.kill()
            first.wait()
    assert content(folder / "log.h5") == content(reference / "log.h5")
    assert (folder / "reduced.csv").read_text() == (reference / "reduced.csv").read_text()
    run_scene(run_child.scene(), folder, progress=False)  # the lock went with its holder
