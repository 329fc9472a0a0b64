"""Outputs are whole and belong to the log beside them (issue 14 item 2).

A run's outputs are staged and renamed into the folder (rig.runner.outputs). A process killed
(SIGKILL) while drawing or between the renames leaves no truncated file, and no output of the
previous scene beside the new log; a rerun completes the folder.
"""

from __future__ import annotations

import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

from rig.logbook import read_metadata
from rig.runner import run_scene
from rig.runner.outputs import OUTPUT_NAMES, STAGING_NAME
from rig.scenes import parse_scene
from tests.runner.fake_stand import NO_FIGURES, register, scene_text

CHILD = Path(__file__).with_name("outputs_child.py")
PNG_END = b"IEND\xaeB`\x82"


def _child(out_dir: Path, variant: str, kill: str) -> int:
    return subprocess.run([sys.executable, str(CHILD), str(out_dir), variant, kill], timeout=300).returncode


def _outputs(folder: Path) -> set[str]:
    return {name for name in OUTPUT_NAMES if (folder / name).exists()}


def _check_consistent(folder: Path) -> None:
    """Every output whole; reduced.csv and summary.txt describe the log beside them."""
    log_mu = 0.25 if "mu = 0.25" in read_metadata(folder / "log.h5").scene_toml else 0.3
    for name in _outputs(folder):
        if name.endswith(".png"):
            assert (folder / name).read_bytes().endswith(PNG_END), f"{name} truncated"
    if (folder / "reduced.csv").exists():
        table = pd.read_csv(folder / "reduced.csv", index_col="point")
        assert len(table) == 4 and (table["true_mu_T"] == log_mu).all()
    if (folder / "summary.txt").exists():
        listed = (folder / "summary.txt").read_text().rsplit("outputs:", 1)[1].strip().split(", ")
        assert _outputs(folder) == set(listed) - {"log.h5"}


@pytest.fixture(scope="module")
def scene_a_folder(tmp_path_factory) -> Path:
    """A folder with the complete run of scene variant "a" (copied by each test)."""
    folder = tmp_path_factory.mktemp("a") / "run"
    assert _child(folder, "a", "none") == 0
    assert _outputs(folder) == {"reduced.csv", "reduced_vs_truth.png", "summary.txt"}
    return folder


@pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="needs POSIX SIGKILL")
@pytest.mark.parametrize("kill", ["draw:1", "rename:3"])  # while drawing; before summary.txt moves in
def test_kill_in_the_output_phase_leaves_whole_matching_outputs(tmp_path, kill, scene_a_folder):
    folder = tmp_path / "run"
    shutil.copytree(scene_a_folder, folder)
    assert _child(folder, "b", kill) == -signal.SIGKILL  # another scene into the used folder, killed
    _check_consistent(folder)
    assert _outputs(folder) != {"reduced.csv", "reduced_vs_truth.png", "summary.txt"}  # not the old set
    assert _child(folder, "b", "none") == 0  # the rerun completes the folder
    _check_consistent(folder)
    assert _outputs(folder) == {"reduced.csv", "reduced_vs_truth.png", "summary.txt"}
    assert not (folder / STAGING_NAME).exists()


def test_another_scene_leaves_no_stale_output(tmp_path, monkeypatch):
    register(monkeypatch)
    run_scene(parse_scene(scene_text(), name="fake"), tmp_path, progress=False)
    assert (tmp_path / "reduced_vs_truth.png").exists()
    report = run_scene(parse_scene(scene_text(NO_FIGURES | {"mu = 0.3": "mu = 0.25"}), name="fake"), tmp_path,
                       progress=False)
    assert report.files == ("log.h5", "reduced.csv", "summary.txt")
    assert _outputs(tmp_path) == {"reduced.csv", "summary.txt"}  # the old figure is gone
    _check_consistent(tmp_path)
