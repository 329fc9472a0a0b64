"""The Python API for scripts walked end to end: load, change, run, read, reopen (docs: the API reference).

Independent facts used: the default scene's file says mu = 0.4 and n = 16; the stand's parameter
range of mu is [0.1, 1.2] (rig.stands.yoke PARAMETERS, the paper's laminate range); a rigid
contact (no slip, no contact solve) keeps the run to about a second; the truth a run stores is the
scene's mu, which the test sets itself.
"""

from __future__ import annotations

import tomllib

import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rig
from rig.errors import ParameterError, UnknownNameError

FAST = {  # the default scene made fast: rigid contact, no noise, 3 points, short gates, no figure
    "contact.model": "rigid", "contact.n": None, "contact.table_points": None, "contact.surrogate": None,
    "effects.dynamometer_noise": None, "effects.balance_noise": None,
    "procedure.gate_time_s": 0.5, "procedure.sweep.brake_setpoint_N_m": {"start": -1.0, "stop": 1.0, "num": 3},
    "outputs.figures": False,
}


def test_load_change_and_round_trip():
    assert "default" in rig.list_scenes() and "fig10" in rig.list_scenes()
    scene = rig.load_scene("default")
    assert scene.kind == "stand" and scene["parameters.mu"] == 0.4 and scene["contact.n"] == 16
    changed = scene.with_(mu=0.35, contact__n=12).with_({"procedure.gate_time_s": 2.0})
    assert (changed["parameters.mu"], changed["contact.n"], changed["procedure.gate_time_s"]) == (0.35, 12, 2.0)
    assert scene["parameters.mu"] == 0.4  # immutable: the original is unchanged
    with pytest.raises(AttributeError):
        scene.name = "other"
    assert changed.validated.parameters["mu"] == 0.35 and changed.validated.contact.n == 12
    assert rig.Scene.from_toml(changed.to_toml(), name="default") == changed
    assert tomllib.loads(changed.to_toml()) == changed.to_dict()
    assert rig.Scene.from_dict(changed.to_dict(), name="default") == changed
    assert scene.with_({"effects.balance_noise": None}).validated.effects.keys() == {"dynamometer_noise",
                                                                                     "load_device"}


@pytest.mark.parametrize(("change", "error", "words"), [
    ({"mu": 5.0}, ParameterError, ["parameters.mu", "5.0", "[0.1, 1.2]"]),
    ({"contact.n": 0}, ParameterError, ["contact.n", "0", "whole number"]),
    ({"contact.modle": "rigid"}, UnknownNameError, ["modle", "did you mean 'model'?"]),
    ({"muu": 0.3}, UnknownNameError, ["muu", "did you mean 'mu'?"]),
    ({"procedure.gate_time_s": "long"}, ParameterError, ["procedure.gate_time_s", "'long'"]),
])
def test_a_bad_change_is_the_scene_files_named_error(change, error, words):
    scene = rig.load_scene("default")
    with pytest.raises(error) as raised:
        scene.with_(**change) if "." not in next(iter(change)) else scene.with_(change)
    assert isinstance(raised.value, ValueError)
    for word in words:
        assert word in str(raised.value)


def test_same_error_as_the_file(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(rig.load_scene("default").to_toml().replace("n = 16", "n = 0"), encoding="utf-8")
    with pytest.raises(ParameterError) as from_file:
        rig.load_scene(path)
    with pytest.raises(ParameterError) as from_python:
        rig.load_scene("default").with_({"contact.n": 0})
    assert str(from_file.value) == str(from_python.value)
    with pytest.raises(UnknownNameError, match="did you mean 'default'"):
        rig.load_scene("defualt")


def test_run_read_and_reopen(tmp_path):
    scene = rig.load_scene("default").with_(FAST, mu=0.3)
    result = rig.run(scene, tmp_path / "run")
    assert result.report.failures == () and result.scene is scene
    reduced = result.reduced
    assert isinstance(reduced, pd.DataFrame) and list(reduced.index) == [0, 1, 2]
    assert {"mu_v", "u_mu_v", "mu_T", "l_over_a", "true_mu_v"} <= set(reduced.columns)
    assert reduced.attrs["units"]["F_y_N"] == "N"
    assert (reduced["true_mu_v"] == 0.3).all()  # the truth is the mu the scene set
    table = pd.read_csv(tmp_path / "run" / "reduced.csv", index_col="point")
    assert list(table.columns) == list(reduced.columns)
    assert (result.truth["mu"] == 0.3).all() and len(result.truth) == 3
    assert set(result.log) == {"settings", "readings", "calibration", "counters"}
    settings = result.log["settings"]
    assert isinstance(settings, pd.DataFrame)
    assert settings["brake_setpoint_N_m"].tolist() == pytest.approx([-1.0, 0.0, 1.0])
    assert settings["normal_force_N"].tolist() == pytest.approx([96.2] * 3)
    assert "planned 3, in log 3" in result.summary

    again = rig.open_run(tmp_path / "run")
    assert again.report is None and again.scene.to_dict() == scene.to_dict()
    pd.testing.assert_frame_equal(again.reduced, reduced)
    figure = again.plot()
    assert len([ax for ax in figure.axes if ax.get_visible()]) == 4  # l/a, c/a, mu_v, mu_T


def test_open_run_of_a_folder_that_is_not_a_run(tmp_path):
    with pytest.raises(ParameterError, match="run folder"):
        rig.open_run(tmp_path)
    with pytest.raises(ParameterError, match="run folder"):
        rig.open_run(tmp_path / "missing")


def test_a_contact_characteristics_run_has_its_table_and_no_log(tmp_path):
    scene = rig.load_scene("contact_characteristics").with_(
        {"characteristics.models": ["rigid"], "characteristics.alpha": [0.5, 5.0], "characteristics.n": 8})
    result = rig.run(scene, tmp_path / "char")
    table = result.table
    assert set(table["model"]) == {"rigid"} and sorted(set(table["alpha"])) == [0.5, 5.0]
    assert len(table) == 2 * len(scene["characteristics.cases"])
    again = rig.open_run(tmp_path / "char")
    assert again.scene is None  # such a folder stores no scene
    with pytest.raises(ParameterError, match="log.h5"):
        again.reduced


KEYS = ["parameters.mu", "contact.n", "contact.model", "contact.poisson", "contact.effects", "scene.seed",
        "scene.drive", "procedure.gate_time_s", "procedure.sweep.brake_setpoint_N_m", "procedure.fixed",
        "effects.balance_noise", "outputs.figures", "outputs.paper_figure"]
HOSTILE = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=8),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(min_size=1, max_size=6), inner, max_size=3),
    max_leaves=6)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(key=st.sampled_from(KEYS) | st.text(min_size=1, max_size=12), value=HOSTILE)
def test_any_change_gives_a_scene_or_a_named_value_error(key, value):
    """Hard case: hostile keys and values never escape as anything but a named ValueError."""
    try:
        changed = rig.load_scene("default").with_({key: value})
    except ParameterError as error:  # UnknownNameError included
        assert str(error)
    else:
        assert rig.Scene.from_toml(changed.to_toml(), name="default") == changed
