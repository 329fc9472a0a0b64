"""``rig run``, ``rig scenes``, ``rig reduce`` through rig.cli.main, and ``python -m rig`` once.

Scenes come from a temporary RIG_SCENES_DIR: the fake stand's scene and a tiny characteristics
scene (rigid model: nu_0 of pure spin of a Hertz circle in full sliding is 3 pi / 16, Equations
§1.10(a), whatever alpha'; the grid of n = 64 cells gets within 6e-4 of it).
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

import rig.cli
import rig.cli.run
from rig.logbook import read_reduced
from rig.scenes.locate import ENV_VAR
from tests.runner.fake_stand import NO_FIGURES, register, scene_text
from tests.runner.test_run import FAILING
from tests.scenes.test_scene_files import TINY_CHARACTERISTICS

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture
def scenes(tmp_path, monkeypatch):
    register(monkeypatch)
    folder = tmp_path / "scenes"
    folder.mkdir()
    (folder / "fake.toml").write_text(scene_text())
    (folder / "failing.toml").write_text(scene_text(FAILING))
    (folder / "quick.toml").write_text(scene_text(NO_FIGURES))
    (folder / "contact_characteristics.toml").write_text(TINY_CHARACTERISTICS)
    monkeypatch.setenv(ENV_VAR, str(folder))
    monkeypatch.chdir(tmp_path)
    return folder


def test_rig_scenes_lists_one_line_each(scenes, capsys):
    assert rig.cli.main(["scenes"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "contact_characteristics  rigid pure spin, three alpha'",
        "failing                  fake stand load sweep",
        "fake                     fake stand load sweep",
        "quick                    fake stand load sweep",
    ]


def test_rig_run_builtin_scene_into_a_folder(scenes, tmp_path, capsys):
    assert rig.cli.main(["run", "fake", "-o", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "planned 4, in log 4" in out and "wrote log.h5, reduced.csv, reduced_vs_truth.png, summary.txt" in out
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["log.h5", "reduced.csv", "reduced_vs_truth.png",
                                                                      "summary.txt"]


def test_rig_run_accepts_a_path_and_defaults_to_out_name(scenes, tmp_path):
    assert rig.cli.main(["run", str(scenes / "quick.toml")]) == 0
    assert (tmp_path / "out" / "quick" / "log.h5").is_file()


def test_rig_run_exit_status_1_when_points_did_not_settle(scenes, tmp_path, capsys):
    assert rig.cli.main(["run", "failing", "-o", str(tmp_path / "f"), "--jobs", "1"]) == 1
    assert "failures (did not settle):" in capsys.readouterr().out


def test_rig_run_bad_scene_name_is_exit_2_with_a_suggestion(scenes, capsys):
    assert rig.cli.main(["run", "fak"]) == 2
    assert "did you mean 'fake'?" in capsys.readouterr().err


def test_rig_run_without_scene_runs_the_default_scene(scenes, tmp_path):
    (scenes / "default.toml").write_text(TINY_CHARACTERISTICS)
    assert rig.cli.run.DEFAULT_SCENE == "default"
    assert rig.cli.main(["run", "-o", str(tmp_path / "cc")]) == 0
    table = pd.read_csv(tmp_path / "cc" / "characteristics.csv")
    assert len(table) == 3 and table["nu_0"].to_numpy() == pytest.approx(3 * math.pi / 16, rel=1e-3)
    assert (tmp_path / "cc" / "characteristics.png").is_file()
    assert "3 contact solves" in (tmp_path / "cc" / "summary.txt").read_text()


def test_rig_reduce_rewrites_the_reduced_table_from_the_log(scenes, tmp_path, capsys):
    assert rig.cli.main(["run", "quick", "-o", str(tmp_path / "run")]) == 0
    log = tmp_path / "run" / "log.h5"
    assert rig.cli.main(["reduce", str(log), "-o", str(tmp_path / "again")]) == 0
    assert "reduced 4 points" in capsys.readouterr().out
    assert (tmp_path / "again" / "reduced.csv").read_text() == (tmp_path / "run" / "reduced.csv").read_text()
    assert list(read_reduced(log).columns[:2]) == ["l_over_a", "u_l_over_a"]


def test_rig_reduce_of_a_missing_log_is_exit_2(scenes, tmp_path, capsys):
    assert rig.cli.main(["reduce", str(tmp_path / "absent.h5")]) == 2
    assert "no such log file" in capsys.readouterr().err


def test_python_m_rig_is_the_rig_command(scenes):
    env = dict(os.environ, **{ENV_VAR: str(scenes)})
    done = subprocess.run([sys.executable, "-m", "rig", "scenes"], capture_output=True, text=True, env=env,
                          cwd=REPO, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[0].startswith("contact_characteristics  rigid pure spin")


def test_a_subcommand_imports_only_itself_and_help_lists_them_all():
    """rig run of a large study does not pay for the lab's web server or the fit engine (issue 12)."""
    probe = ("import sys\nfrom rig.cli import build_parser\nbuild_parser('scenes')\n"
             "print(sorted(m for m in ('rig.cli.lab', 'rig.cli.fit', 'rig.cli.run', 'flask') if m in sys.modules))")
    loaded = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "[]"
    helped = subprocess.run([sys.executable, "-m", "rig", "--help"], capture_output=True, text=True, check=True).stdout
    assert all(name in helped for name in ("run", "scenes", "reduce", "compare", "accuracy", "lab", "fit"))
