"""A stand run end to end with the fake stand: outputs, failures in the summary, effects not built.

Independent numbers: the fake stand's truth is mu = 0.3 (the scene's override) and F = mu load;
its noise has std 0.2 N, so mu from a 100-sample gate scatters by 0.02/sqrt(100)/load around 0.3.
"""

from __future__ import annotations

from unittest import mock

import numpy as np
import pandas as pd
import pytest

from rig.logbook import point_indices, read_metadata, read_reduced
from rig.logbook.truth import read_truth
from rig.runner import run_scene
from rig.runner.sweep import show_progress
from rig.scenes import parse_scene
from tests.runner import fake_stand
from tests.runner.fake_stand import NO_FIGURES, register, scene_text

FAILING = NO_FIGURES | {"mu = 0.3": "mu = 0.3\nsettle_tau_s = 1.0",  # tau = 1 s: the step 10 -> 50 N needs ln(41) s > 3 s
           "load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 10.0, 50.0, 55.0]"}


@pytest.fixture(autouse=True)
def _fake_stand(monkeypatch):
    register(monkeypatch)


def run(tmp_path, replace=None, **options):
    options.setdefault("progress", False)
    return run_scene(parse_scene(scene_text(replace), name="fake"), tmp_path, **options)


def test_outputs_reduced_table_and_summary(tmp_path):
    report = run(tmp_path)
    assert report.files == ("log.h5", "reduced.csv", "reduced_vs_truth.png", "summary.txt")
    assert (tmp_path / "reduced_vs_truth.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    table = pd.read_csv(tmp_path / "reduced.csv", index_col="point")
    assert list(table.columns[:8]) == ["l_over_a", "u_l_over_a", "c_over_a", "u_c_over_a", "mu_v", "u_mu_v",
                                       "mu_T", "u_mu_T"]
    assert list(table.columns[8:]) == ["true_l_over_a", "true_c_over_a", "true_mu_v", "true_mu_T", "z_max", "off_truth"]
    assert (table["off_truth"] == 0).all() and "off truth (z > " in report.summary and "0 point(s)" in report.summary
    assert (table["true_mu_T"] == 0.3).all()
    assert np.all(np.abs(table["mu_T"] - 0.3) < 5 * table["u_mu_T"])  # u = 0.2 N / sqrt(100) / load
    assert table["u_mu_T"].to_numpy() == pytest.approx(0.02 / np.array([5, 10, 20, 25]), rel=0.35)
    assert read_metadata(tmp_path / "log.h5").scene_toml == scene_text()  # verbatim
    stored = read_reduced(tmp_path / "log.h5")
    np.testing.assert_array_equal(stored["mu_T"].to_numpy(), table["mu_T"].to_numpy())
    truth = read_truth(tmp_path / "log.h5")
    assert truth["operator_settle_time_s"].to_numpy() == pytest.approx(0.2 * np.log1p([5, 5, 10, 5]))
    text = (tmp_path / "summary.txt").read_text()
    assert text == report.summary
    assert "planned 4, in log 4 (0 resumed from an interrupted run, 4 simulated now), failed 0" in text
    assert "settle time: min 0.358 s, median 0.358 s, max 0.48 s" in text  # 0.2 ln 6, 0.2 ln 11
    assert "calibration: dynamometer (once per run)" in text
    assert "mu_T: 4 points" in text and "within 2u:" in text
    assert "effects:     force_noise" in text


def test_points_that_do_not_settle_are_listed_and_skipped(tmp_path):
    report = run(tmp_path, FAILING)
    assert [f.index for f in report.failures] == [2] and not report.stopped
    assert point_indices(tmp_path / "log.h5") == [0, 1, 3]
    assert "failed 1" in report.summary
    assert "point 2 (load_N = 50, speed_rad_s = 10): operating point" in report.summary
    assert list(pd.read_csv(tmp_path / "reduced.csv")["point"]) == [0, 1, 3]


def test_stop_policy_ends_the_run_at_the_first_failure(tmp_path):
    report = run(tmp_path, FAILING | {"gate_time_s = 1.0": 'gate_time_s = 1.0\non_settle_timeout = "stop"'})
    assert report.stopped and point_indices(tmp_path / "log.h5") == [0, 1]
    assert "run stopped at the first failure" in report.summary


def test_effects_the_scene_does_not_name_are_not_built_nor_called(tmp_path):
    drift = mock.Mock(wraps=fake_stand.ForceDrift)
    noise = mock.Mock(wraps=fake_stand.ForceNoise)
    with mock.patch.dict(fake_stand.COMPONENTS, {"force_drift": drift, "force_noise": noise}), \
            mock.patch.object(fake_stand.ForceDrift, "apply") as drift_apply:
        scene = parse_scene(scene_text(NO_FIGURES), name="fake")
        noise.assert_not_called()  # loading a scene builds nothing
        run_scene(scene, tmp_path, progress=False)
    drift.assert_not_called()
    drift_apply.assert_not_called()
    noise.assert_called_once_with(std_N=0.2)


def test_no_effects_named_builds_none(tmp_path):
    with mock.patch.object(fake_stand.ForceNoise, "__init__") as noise, \
            mock.patch.object(fake_stand.ForceDrift, "__init__") as drift:
        report = run(tmp_path, NO_FIGURES | {"[effects.force_noise]\nstd_N = 0.2\n": ""})
    noise.assert_not_called()
    drift.assert_not_called()
    assert "effects:     none" in report.summary
    table = pd.read_csv(tmp_path / "reduced.csv")
    assert (table["mu_T"] == 0.3).all() and (table["u_mu_T"] == 0.0).all()  # exact without noise
    assert "no comparable points" in report.summary  # u = 0: no z to state


def test_progress_bar_only_on_a_terminal_unless_asked(tmp_path, capsys):
    assert show_progress(None) is False  # pytest's stderr is not a terminal
    run(tmp_path / "quiet", NO_FIGURES, progress=None)
    assert capsys.readouterr().err == ""
    run(tmp_path / "loud", NO_FIGURES, progress=True)
    assert "4/4" in capsys.readouterr().err


def test_a_run_whose_every_point_failed_says_so_and_reduces_nothing(tmp_path):
    report = run(tmp_path, NO_FIGURES | {"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [500.0]",
                                         "mu = 0.3": "mu = 0.3\nsettle_tau_s = 1.0"})  # 10 -> 500 N: no settling
    assert [f.index for f in report.failures] == [0] and report.files == ("log.h5", "summary.txt")
    assert "not reduced: the log holds no operating point (every point failed)" in report.summary
    assert not (tmp_path / "reduced.csv").exists()


def test_figure_axis_is_labelled_with_the_setting_name_and_unit():
    from rig.runner.figures import setting_label

    assert setting_label("brake_setpoint_N_m") == "brake set-point $T_{set}$ [N m]"
    assert setting_label("omega_1_set_rad_s") == r"speed set-point $\omega_1$ [rad/s]"
    assert setting_label("load_N") == "load [N]" and setting_label("speed_step") == "drive speed step [1]"


def test_the_drawn_quick_look_figure_carries_that_label(tmp_path, monkeypatch):
    """Issue 12's rough edge: the figure a run writes, not only the label function (x was the raw key load_N)."""
    import rig.plotting

    drawn, new_figure = [], rig.plotting.new_figure
    monkeypatch.setattr(rig.plotting, "new_figure", lambda **kwargs: drawn.append(new_figure(**kwargs)) or drawn[-1])
    run(tmp_path)
    panels = [ax for ax in drawn[0].axes if ax.get_visible()]
    assert [ax.get_ylabel() for ax in panels] == ["$l/a$", "$c/a$", r"$\mu_v$", r"$\mu_T$"]
    assert {ax.get_xlabel() for ax in panels} == {"load [N]"}
