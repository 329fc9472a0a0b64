"""Procedures with several series of points ([[procedure.series]]): a sweep whose range depends
on another setting, e.g. the brake range of stand A at each load."""

import pytest

from rig.errors import ParameterError
from rig.scenes import parse_scene
from tests.runner.fake_stand import register, scene_text

SERIES = {
    "[procedure.fixed]\nspeed_rad_s = 10.0\n\n[procedure.sweep]\nload_N = [5.0, 10.0, 20.0, 25.0]\n": """\
[[procedure.series]]
fixed = { speed_rad_s = 10.0 }
sweep = { load_N = [5.0, 10.0] }

[[procedure.series]]
fixed = { speed_rad_s = 40.0 }
sweep = { load_N = [100.0, 200.0, 300.0] }
""",
}


def _procedure(replace):
    return parse_scene(scene_text(replace), name="series").procedure


def test_series_run_one_after_the_other_each_with_its_own_range(monkeypatch):
    register(monkeypatch)
    procedure = _procedure(SERIES)
    points = procedure.points()
    assert [p.settings for p in points] == [
        {"load_N": 5.0, "speed_rad_s": 10.0}, {"load_N": 10.0, "speed_rad_s": 10.0},
        {"load_N": 100.0, "speed_rad_s": 40.0}, {"load_N": 200.0, "speed_rad_s": 40.0},
        {"load_N": 300.0, "speed_rad_s": 40.0}]
    assert [p.index for p in points] == list(range(5)) and points[2].previous == points[1].settings
    assert procedure.n_points == 5 and procedure.series_settings == ["speed_rad_s"] and procedure.fixed == {}
    assert procedure.sweep == (("load_N", (5.0, 10.0, 100.0, 200.0, 300.0)),)


def test_thinning_keeps_the_ends_of_every_series(monkeypatch):
    register(monkeypatch)
    thin = _procedure(SERIES).thinned(2)
    assert [p.settings["load_N"] for p in thin.points()] == [5.0, 10.0, 100.0, 300.0] and thin.repeats == 1


@pytest.mark.parametrize(
    "old, new, match",
    [
        ("sweep = { load_N = [100.0, 200.0, 300.0] }", "sweep = { speed_rad_s = [1.0] }\nfixed2 = 1",
         "did you mean 'fixed'"),
        ("fixed = { speed_rad_s = 40.0 }\nsweep = { load_N = [100.0, 200.0, 300.0] }",
         "fixed = { load_N = 40.0 }\nsweep = { speed_rad_s = [1.0] }", r"series\[1\].sweep"),
        ("fixed = { speed_rad_s = 40.0 }", "fixed = { speed_rad_s = 400.0 }", r"series\[1\].fixed.speed_rad_s"),
        ("fixed = { speed_rad_s = 40.0 }\n", "", r"series\[1\].fixed.speed_rad_s"),
    ],
)
def test_bad_series_name_what_is_wrong(monkeypatch, old, new, match):
    register(monkeypatch)
    text = scene_text(SERIES)
    assert old in text
    with pytest.raises(ParameterError, match=match):
        parse_scene(text.replace(old, new), name="bad")


def test_a_top_level_sweep_and_series_together_is_an_error(monkeypatch):
    register(monkeypatch)
    text = scene_text(SERIES) + "\n[procedure.sweep]\nload_N = [1.0]\n"
    with pytest.raises(ParameterError, match=r"procedure.sweep .* absent when \[\[procedure.series\]\]"):
        parse_scene(text, name="bad")
