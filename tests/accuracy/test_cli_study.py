"""``rig accuracy`` end to end on a tiny stand-A scene (rigid law, 2 set-points, 1 s gates; ~10 s).

Independent facts checked: the reference of each axis has zero error against itself; the
counters' +-1 count dominates u(l/a), so u(l/a) halves when the gate doubles (counts grow with
the gate time); with the quasi-static drive the lab time is points x gate (settling takes no
simulated time); the dynamic drive settles to the quasi-static steady state within the stand's
settle tolerance (2e-4 in speed, ~0.005 a in l: rig.stands.yoke.integration); the front marked in
the table is the Pareto front of its own cost and error columns.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from rig.accuracy import ACCURACY_CSV, ACCURACY_MD, PARETO_PNG, StudyOptions, pareto_front
from rig.accuracy.table import COLUMNS
from rig.cli import accuracy as cli_accuracy
from rig.cli import main

TINY = """
[scene]
kind = "stand"
description = "tiny stand A scene for the accuracy tests"
stand = "yoke"
seed = 7
drive = "quasi_static"

[parameters]
mu = 0.4

[contact]
model = "rigid"
n = 4
poisson = 0.3
surrogate = true
table_points = [5, 2, 3]

[effects.dynamometer_noise]
[effects.load_device]

[procedure]
settle_timeout_s = 10.0
gate_time_s = 1.0

[procedure.fixed]
normal_force_N = 96.2
delta_h_m = 0.0
omega_1_set_rad_s = 25.13

[procedure.sweep]
brake_setpoint_N_m = [-1.2, 0.0, 1.2]
"""


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    folder = tmp_path_factory.mktemp("accuracy")
    scene = folder / "tiny.toml"
    scene.write_text(TINY, encoding="utf-8")
    out = folder / "out"
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("RIG_CACHE_DIR", str(folder / "cache"))
        # fewer factors than the command's defaults keep the test short (7 settings, 2 runs each)
        patch.setattr(cli_accuracy, "DEFAULTS", StudyOptions(table_factors=(0.5, 1.0), tolerance_factors=(10.0, 1.0),
                                                             gate_factors=(0.5, 1.0, 2.0)))
        status = main(["accuracy", str(scene), "-o", str(out), "-j", "1", "--repeats", "1", "--max-values", "2",
                       "--models", "rigid", "--grids", "4,6"])
    return status, out, pd.read_csv(out / ACCURACY_CSV)


def test_writes_the_table_the_report_and_the_plot(study):
    status, out, table = study
    assert status == 0
    assert tuple(table.columns) == COLUMNS
    assert (out / PARETO_PNG).stat().st_size > 10_000
    report = (out / ACCURACY_MD).read_text(encoding="utf-8")
    assert "--models rigid --grids 4,6" in report and "### Where the time goes" in report
    assert "brake_setpoint_N_m 2 of 3 values (-1.2, 1.2)" in report
    assert set(table["axis"]) == {"contact model x grid", "surrogate table", "drive / ODE tolerance", "gate time"}
    assert (table["runs"] == 1).all() and (table["cpu_median_s"] > 0).all() and (table["failed"] == 0).all()
    assert (table["cpu_first_s"] > 0).all() and (table["points"] == 2).all()


def test_references_have_zero_error_and_the_scene_is_marked_once_per_axis(study):
    _, _, table = study
    refs = table[table["reference"]]
    assert len(refs) == 3  # no reference on the gate axis
    assert (refs[["d_l_over_a", "d_mu_T", "d_true_l_over_a"]] == 0.0).all().all()
    assert table.groupby("axis")["scene_choice"].sum().eq(1).all()


def test_gate_axis_uncertainty_halves_when_the_gate_doubles_and_lab_time_is_points_x_gate(study):
    _, _, table = study
    gate = table[table["axis"] == "gate time"].sort_values("lab_time_s")
    assert gate["setting"].tolist() == ["gate 0.5 s", "gate 1 s", "gate 2 s"]
    np.testing.assert_allclose(gate["lab_time_s"], [1.0, 2.0, 4.0], rtol=1e-12)  # 2 points, no settling
    u = gate["u_l_over_a"].to_numpy()
    np.testing.assert_allclose(u[:-1] / u[1:], 2.0, rtol=0.05)


def test_dynamic_drive_settles_to_the_quasi_static_state(study):
    _, _, table = study
    drive = table[table["axis"] == "drive / ODE tolerance"]
    quasi = drive[drive["setting"] == "quasi-static"].iloc[0]
    assert quasi["d_true_l_over_a"] < 0.01


def test_marked_front_is_the_front_of_cost_and_error(study):
    _, _, table = study
    for _, rows in table.groupby("axis"):
        np.testing.assert_array_equal(rows["on_front"].to_numpy(), pareto_front(rows["cost_s"], rows["error"]))


def test_not_a_stand_scene_and_bad_lists_exit_2(capsys):
    assert main(["accuracy", "contact_characteristics", "--repeats", "1"]) == 2
    assert "stand scene" in capsys.readouterr().err
    assert main(["accuracy", "default", "--grids", "8,x"]) == 2
    assert "--grids" in capsys.readouterr().err
