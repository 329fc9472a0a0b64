"""Every failure named, every output whole (issue 14): a hostile but fair tester's cases, each an exit
status 2 with one named line (no traceback, no staging folder left), a correct result, or 130 for Ctrl-C.

Scenes are small (n = 8, coarse tables, 0.1 s gates) so that each run takes a few seconds.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import h5py
import pandas as pd
import pytest

from rig.cli import main
from rig.logbook import layout as L
from rig.logbook import staging_dir

GIVE_UP_S = 120.0  # a safety net against a hung child, not a timing assertion

STAND_A = """
[scene]
kind = "stand"
description = "stand A, small"
stand = "yoke"
seed = 1
drive = "quasi_static"
[parameters]
mu = 0.4
[contact]
model = "kinematic"
n = 8
poisson = 0.3
surrogate = true
table_points = [9, 3, 5]
[effects.load_device]
[procedure]
settle_timeout_s = 10.0
gate_time_s = 0.1
[procedure.fixed]
normal_force_N = 96.2
delta_h_m = 0.0
omega_1_set_rad_s = 25.13
[procedure.sweep]
brake_setpoint_N_m = [-0.5, 0.5]
"""

STAND_B = """
[scene]
kind = "stand"
description = "stand B, small"
stand = "disc_roller"
seed = 1
drive = "quasi_static"
[parameters]
mu = 0.8
[contact]
model = "kinematic"
n = 8
poisson = 0.5
surrogate = true
table_points = [9, 3, 5]
[procedure]
settle_timeout_s = 20.0
gate_time_s = 0.1
[procedure.fixed]
sigma_rad = 0.0
speed_step = 1
direction = 1
normal_force_N = 36.0
[procedure.sweep]
l_m = [-0.003, 0.003]
"""


SIDECAR = 'figure = "f"\n[x]\ncolumn = "x"\nunits = "1"\n[datasets.d]\ncolumn = "y"\nunits = "1"\n'


def scene(tmp_path: Path, text: str, changes: dict[str, str] | None = None, name: str = "s") -> Path:
    for old, new in (changes or {}).items():
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def run_cli(capsys, *argv: object) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_named(code: int, err: str, command: str, *words: str) -> None:
    """Exit 2 and one line 'rig COMMAND: error: ...' holding ``words``; no traceback."""
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"rig {command}: error: "), err
    assert "Traceback" not in err
    for word in words:
        assert word in lines[0], (word, lines[0])


# ---------------------------------------------------------------- item 1: errors inside a point stay named


def test_a_stall_inside_a_point_is_named_and_leaves_no_staging_folder(tmp_path, capsys):
    path = scene(tmp_path, STAND_A, {"[-0.5, 0.5]": "[0.5, 8.0]"})
    code, _, err = run_cli(capsys, "run", path, "-o", tmp_path / "out")
    assert_named(code, err, "run", "brake_setpoint_N_m = 8.0", "stall")
    assert not staging_dir(tmp_path / "out" / "log.h5").exists() and not (tmp_path / "out" / "log.h5").exists()


def test_stand_a_at_the_lowest_mu_reduces_with_true_reasons(tmp_path, capsys):
    # mu = 0.1 is the end of stand A's range: the reduction's perturbed evaluations left the
    # contact law's alpha' domain (u = NaN, "within 2 u = nan"); the domain now has a margin
    path = scene(tmp_path, STAND_A, {"mu = 0.4": "mu = 0.1", "[-0.5, 0.5]": "[-0.3, 0.3]"})
    code, _, err = run_cli(capsys, "run", path, "-o", tmp_path / "out")
    assert code == 0, err
    table = pd.read_csv(tmp_path / "out" / "reduced.csv", index_col="point")
    assert table["l_over_a"].notna().all() and table["u_l_over_a"].notna().all()
    for name in ("mu_v", "mu_T"):
        for value, u, reason in zip(table[name], table[f"u_{name}"], table["reason"].fillna("")):
            assert (pd.notna(value) and pd.notna(u)) or f"{name}:" in reason or f"{name} " in reason
    assert not table["reason"].fillna("").str.contains("nan|not finite|domain").any(), table["reason"].tolist()


@pytest.mark.parametrize(("change", "words"), [
    ({"direction = 1": "direction = 0"}, ("procedure.fixed.direction = 0.0", "one of -1, 1")),
    ({"direction = 1": "direction = 0.5"}, ("procedure.fixed.direction = 0.5", "one of -1, 1")),
    ({"speed_step = 1": "speed_step = 1.5"}, ("procedure.fixed.speed_step = 1.5", "one of 1, 2, 3")),
])
def test_stand_b_settings_with_few_values_are_checked_at_load(tmp_path, capsys, change, words):
    code, _, err = run_cli(capsys, "run", scene(tmp_path, STAND_B, change), "-o", tmp_path / "out")
    assert_named(code, err, "run", *words)
    assert not (tmp_path / "out").exists()  # rejected before anything is written


def test_a_swept_setting_is_checked_value_by_value(tmp_path, capsys):
    changed = scene(tmp_path, STAND_B, {"direction = 1\n": "", "l_m = [-0.003, 0.003]": "direction = [1, -0.5]"})
    code, _, err = run_cli(capsys, "run", changed, "-o", tmp_path / "out")
    assert_named(code, err, "run", "procedure.sweep.direction[1] = -0.5")


# ---------------------------------------------------------------- item 3: errors building the stand


@pytest.mark.parametrize(("effects", "words"), [
    ("[effects.brake_dynamics]\nloop_gain = 40.0\n", ("effects.brake_dynamics.loop_gain = 40.0",)),
    ("[effects.brake_dynamics]\n", ("effects.brake_dynamics", "scene.drive = 'dynamic'")),
])
def test_errors_building_the_stand_leave_nothing(tmp_path, capsys, effects, words):
    drive = {} if "loop_gain" not in effects else {'drive = "quasi_static"': 'drive = "dynamic"'}
    text = STAND_A.replace("[procedure]\n", effects + "[procedure]\n")
    code, _, err = run_cli(capsys, "run", scene(tmp_path, text, drive), "-o", tmp_path / "out")
    assert_named(code, err, "run", *words)
    assert "DriveMode" not in err
    assert list((tmp_path / "out").iterdir()) == []


# ---------------------------------------------------------------- item 4: the gate fits the recorder


@pytest.mark.parametrize(("text", "gate", "limit"), [(STAND_A, "1e300", "2500"), (STAND_A, "1e8", "2500"),
                                                      (STAND_B, "1e4", "500")])
def test_a_gate_longer_than_the_recorder_holds_is_named(tmp_path, capsys, text, gate, limit):
    path = scene(tmp_path, text, {"gate_time_s = 0.1": f"gate_time_s = {gate}"})
    code, _, err = run_cli(capsys, "run", path, "-o", tmp_path / "out")
    assert_named(code, err, "run", "procedure.gate_time_s", f"(0, {limit}] s", "samples per channel")


# ---------------------------------------------------------------- item 5: stand B over its whole mu range


@pytest.mark.parametrize("mu", [0.05, 1.2, 2.0])  # 1.2: the old domain ended at the start alpha'
def test_stand_b_reduces_at_the_ends_of_its_mu_range(tmp_path, capsys, mu):
    path = scene(tmp_path, STAND_B, {"mu = 0.8": f"mu = {mu}"})
    code, _, err = run_cli(capsys, "run", path, "-o", tmp_path / "out")
    assert code == 0, err
    table = pd.read_csv(tmp_path / "out" / "reduced.csv", index_col="point")
    for name in ("mu_v", "mu_T"):  # l = +-3.2 mm: both coefficients measurable; truth = the scene's mu
        assert (abs(table[name] - mu) <= 3 * table[f"u_{name}"]).all(), table[[name, f"u_{name}", "reason"]]


# ---------------------------------------------------------------- item 7: Ctrl-C


def test_ctrl_c_is_one_line_and_exit_130(monkeypatch, capsys):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr("rig.cli.run.run_scene", interrupted)
    code, _, err = run_cli(capsys, "run")
    assert code == 130
    assert err == "rig run: interrupted (run it again to resume)\n"


@pytest.mark.skipif(os.name != "posix", reason="needs POSIX signals")
def test_ctrl_c_during_a_run_is_one_line_and_keeps_the_staging_folder(tmp_path):
    path = scene(tmp_path, STAND_A, {"[-0.5, 0.5]": "{ start = -0.5, stop = 0.5, num = 400 }"})
    out = tmp_path / "out"
    child = subprocess.Popen([sys.executable, "-m", "rig", "run", str(path), "-o", str(out)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        waited = 0.0
        journal = staging_dir(out / "log.h5") / "points.journal"
        while not (journal.exists() and journal.stat().st_size > 0):  # interrupt while the points run
            assert child.poll() is None and waited < GIVE_UP_S, child.stderr.read() if child.poll() else "slow"
            time.sleep(0.05)
            waited += 0.05
        child.send_signal(signal.SIGINT)
        _, err = child.communicate(timeout=GIVE_UP_S)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 130
    assert err == "rig run: interrupted (run it again to resume)\n"
    assert staging_dir(out / "log.h5").is_dir()  # kept: running the scene again resumes


# ---------------------------------------------------------------- item 8: OS errors


def test_run_into_an_existing_file_is_named(tmp_path, capsys):
    target = tmp_path / "taken"
    target.write_text("x")
    code, _, err = run_cli(capsys, "run", scene(tmp_path, STAND_A), "-o", target)
    assert_named(code, err, "run", "output folder", str(target), "a file of that name exists")


def read_only(monkeypatch, folder: Path) -> None:
    """Make ``folder`` refuse new files and folders, as a read-only folder does (also for root, whom
    chmod does not bind): os.mkdir and os.open with O_CREAT inside it raise PermissionError."""
    real_mkdir, real_open = os.mkdir, os.open

    def inside(path) -> bool:
        return Path(path).resolve().parent == folder.resolve()

    def mkdir(path, *args, **kwargs):
        if inside(path):
            raise PermissionError(13, "Permission denied", str(path))
        return real_mkdir(path, *args, **kwargs)

    def open_(path, flags, *args, **kwargs):
        if flags & os.O_CREAT and inside(path):
            raise PermissionError(13, "Permission denied", str(path))
        return real_open(path, flags, *args, **kwargs)

    monkeypatch.setattr(os, "mkdir", mkdir)
    monkeypatch.setattr(os, "open", open_)


def test_run_into_a_read_only_folder_is_named(tmp_path, capsys, monkeypatch):
    folder = tmp_path / "ro"
    folder.mkdir()
    read_only(monkeypatch, folder)
    code, _, err = run_cli(capsys, "run", scene(tmp_path, STAND_A), "-o", folder / "out")
    assert_named(code, err, "run", "output folder", "Permission denied")


@pytest.fixture(scope="module")
def stand_a_log(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("stand_a")
    assert main(["run", str(scene(folder, STAND_A)), "-o", str(folder / "out")]) == 0
    return folder / "out" / "log.h5"


def test_reduce_of_a_log_in_a_read_only_folder(tmp_path, capsys, monkeypatch, stand_a_log):
    folder = tmp_path / "ro"
    folder.mkdir()
    log = folder / "log.h5"
    log.write_bytes(stand_a_log.read_bytes())
    read_only(monkeypatch, folder)
    code, out, err = run_cli(capsys, "reduce", log)  # outputs into the read-only folder: named
    assert_named(code, err, "reduce", "output folder", "Permission denied", "-o DIR", "printed above")
    assert "mu_T" in out and len(out.strip().splitlines()) == 3  # the values are reported: header + 2 points
    code, out, err = run_cli(capsys, "reduce", log, "-o", tmp_path / "elsewhere")
    assert code == 0, err
    assert "reduced table not stored in log.h5" in out  # the values are still reported, in reduced.csv
    assert len(pd.read_csv(tmp_path / "elsewhere" / "reduced.csv")) == 2


def test_compare_into_an_existing_file_is_named(tmp_path, capsys):
    result = tmp_path / "result.csv"
    result.write_text("x,y\n0,0\n1,1\n2,2\n")
    digitised = tmp_path / "fig.csv"
    digitised.write_text("0.5,0.5\n1.5,1.5\n")
    (tmp_path / "fig.toml").write_text(SIDECAR)
    taken = tmp_path / "taken"
    taken.write_text("x")
    code, _, err = run_cli(capsys, "compare", result, digitised, "-o", taken)
    assert_named(code, err, "compare", str(taken))


# ---------------------------------------------------------------- item 9: damaged scene text in a log


def test_damaged_scene_text_in_a_log_is_named(tmp_path, capsys, stand_a_log):
    log = tmp_path / "log.h5"
    log.write_bytes(stand_a_log.read_bytes())
    with h5py.File(log, "r+") as handle:
        del handle[L.SCENE_DATASET]
        handle.create_dataset(L.SCENE_DATASET, data=b"[scene]\n\xff\xfe kind", dtype=h5py.string_dtype("utf-8"))
    code, _, err = run_cli(capsys, "reduce", log)
    assert_named(code, err, "reduce", str(log), "not UTF-8")


# ---------------------------------------------------------------- item 11: smaller ones


def test_a_gate_too_short_for_a_mark_says_so_not_stall(tmp_path, capsys):
    path = scene(tmp_path, STAND_A, {"gate_time_s = 0.1": "gate_time_s = 1e-3"})
    code, _, err = run_cli(capsys, "run", path, "-o", tmp_path / "out")
    assert code == 0, err
    table = pd.read_csv(tmp_path / "out" / "reduced.csv", index_col="point")
    assert table["mu_T"].isna().all()
    assert table["reason"].str.contains("the gate of 0.001 s is too short for wheel 1's marks").all()
    assert not table["reason"].str.contains("stall").any()


def test_a_log_without_points_is_named(tmp_path, capsys):
    """A format-1 log (one group per point) whose points were all removed."""
    log = tmp_path / "log.h5"
    log.write_bytes((Path(__file__).resolve().parents[1] / "logbook" / "data" / "old_layout_v1.h5").read_bytes())
    with h5py.File(log, "r+") as handle:
        for group in (L.POINTS_GROUP, L.TRUTH_GROUP):
            for name in list(handle[group]):
                del handle[group][name]
    code, _, err = run_cli(capsys, "reduce", log)
    assert_named(code, err, "reduce", str(log), "no operating point")


def test_an_empty_scene_file_is_named(tmp_path, capsys):
    empty = tmp_path / "empty.toml"
    empty.write_text("")
    code, _, err = run_cli(capsys, "run", empty, "-o", tmp_path / "out")
    assert_named(code, err, "run", str(empty), "empty")


def test_digitised_numbers_beyond_a_float_and_repeated_x_are_named_with_the_line(tmp_path, capsys):
    result = tmp_path / "result.csv"
    result.write_text("x,y\n0,0\n1,1\n2,2\n")
    (tmp_path / "fig.toml").write_text(SIDECAR)
    digitised = tmp_path / "fig.csv"
    digitised.write_text("0.5,0.5\n1.5,1e400\n")
    code, _, err = run_cli(capsys, "compare", result, digitised)
    assert_named(code, err, "compare", f"{digitised}, line 2", "'1e400'", "beyond the range of a float")
    digitised.write_text("0.5,0.5\n1.5,1.5\n0.5,0.7\n")
    code, _, err = run_cli(capsys, "compare", result, digitised)
    assert_named(code, err, "compare", f"{digitised}, line 3", "x = 0.5 repeats line 1")
