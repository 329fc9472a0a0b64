"""One writer per folder for every kind of run, and no run replaces another kind's outputs.

Two contact-characteristics runs (and two oscillation runs) into one folder: the first, paused
inside its sweep in a child process, holds the folder's lock; the second exits 2 at once with
one line naming the folder and the holder, and the first then finishes normally. A
characteristics (or oscillation) run into a stand run's folder is refused by name and leaves
the stand run's files as they were; a stand run into a characteristics folder likewise.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

import rig.cli
from tests.runner.fake_stand import NO_FIGURES, register, scene_text
from tests.scenes.test_oscillation_scene import TINY as TINY_OSCILLATION
from tests.scenes.test_scene_files import TINY_CHARACTERISTICS

ROOT = Path(__file__).resolve().parents[2]
SCENES = {"characteristics": (TINY_CHARACTERISTICS, "characteristics.csv"),
          "oscillation": (TINY_OSCILLATION, "oscillation_sweep.csv")}


def _wait_for(path: Path, child: subprocess.Popen, timeout_s: float = 120.0) -> None:
    deadline = time.monotonic() + timeout_s
    while not path.exists():
        assert child.poll() is None, child.communicate()
        assert time.monotonic() < deadline, "the child did not reach its sweep"
        time.sleep(0.02)


@pytest.mark.parametrize("kind", sorted(SCENES))
def test_two_runs_of_a_kind_into_one_folder_one_runs_the_other_is_refused(kind, tmp_path, capsys):
    text, csv = SCENES[kind]
    scene = tmp_path / f"{kind}.toml"
    scene.write_text(text)
    folder, marker = tmp_path / "out", tmp_path / "marker"
    child = subprocess.Popen([sys.executable, "-m", "tests.runner.kind_child", str(scene), str(folder), str(marker)],
                             cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        _wait_for(marker, child)
        assert rig.cli.main(["run", str(scene), "-o", str(folder)]) == 2
        err = capsys.readouterr().err.splitlines()
        assert len(err) == 1 and f"is in use by process {child.pid} (rig run {kind}" in err[0], err
    finally:
        marker.with_name(marker.name + ".go").touch()
        out, errors = child.communicate(timeout=300)
    assert child.returncode == 0, errors[-2000:]
    assert (folder / csv).is_file() and (folder / "summary.txt").is_file() and not (folder / "rig.lock").exists()


@pytest.mark.parametrize("kind", sorted(SCENES))
def test_a_run_into_another_kinds_folder_is_refused_and_deletes_nothing(kind, tmp_path, monkeypatch, capsys):
    register(monkeypatch)
    text, csv = SCENES[kind]
    stand_scene, other_scene = tmp_path / "fake.toml", tmp_path / f"{kind}.toml"
    stand_scene.write_text(scene_text(NO_FIGURES))
    other_scene.write_text(text)
    stand_folder = tmp_path / "stand"
    assert rig.cli.main(["run", str(stand_scene), "-o", str(stand_folder)]) == 0
    before = {p.name: p.read_bytes() for p in stand_folder.iterdir()}
    capsys.readouterr()
    assert rig.cli.main(["run", str(other_scene), "-o", str(stand_folder)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err == [f"rig run: error: {stand_folder} holds the outputs of a stand run (log.h5, reduced.csv); "
                   f"a {'contact-characteristics' if kind == 'characteristics' else kind} run there would replace "
                   "them: choose another output folder"]
    assert {p.name: p.read_bytes() for p in stand_folder.iterdir()} == before

    other_folder = tmp_path / kind
    assert rig.cli.main(["run", str(other_scene), "-o", str(other_folder)]) == 0
    before = {p.name: p.read_bytes() for p in other_folder.iterdir()}
    capsys.readouterr()
    assert rig.cli.main(["run", str(stand_scene), "-o", str(other_folder)]) == 2
    assert f"holds the outputs of a {'contact-characteristics' if kind == 'characteristics' else kind} run ({csv})" \
        in capsys.readouterr().err
    assert {p.name: p.read_bytes() for p in other_folder.iterdir()} == before
