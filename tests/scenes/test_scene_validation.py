"""Scene validation: unknown keys and names with suggestions, ranges named, no silent physical defaults.

Independent numbers: the ranges are the fake stand's declared specs (tests/runner/fake_stand.py)
and rig.contact's documented ones (poisson in [0, 0.5], n in [4, 512], psi >= 1); the plan order
is the Cartesian product written out by hand.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.errors import ParameterError, UnknownNameError
from rig.scenes import StandScene, TimeoutPolicy, parse_scene
from rig.stands.base import DriveMode
from tests.runner.fake_stand import FakeStand, register, scene_text


@pytest.fixture(autouse=True)
def _fake_stand(monkeypatch):
    register(monkeypatch)


def parse(replace: dict[str, str] | None = None) -> StandScene:
    return parse_scene(scene_text(replace), name="fake")


def test_valid_scene_is_read_completely():
    scene = parse()
    assert scene.stand_class is FakeStand and scene.seed == 7 and scene.drive is DriveMode.QUASI_STATIC
    assert scene.parameters == {"mu": 0.3}
    assert scene.effects == {"force_noise": {"std_N": 0.2}}  # force_drift not named: absent
    assert (scene.contact.model, scene.contact.poisson, scene.contact.n) == ("rigid", 0.3, None)
    p = scene.procedure
    assert (p.settle_timeout_s, p.gate_time_s, p.repeats, p.on_settle_timeout) == (3.0, 1.0, 1, TimeoutPolicy.SKIP)
    assert [pt.settings["load_N"] for pt in p.points()] == [5.0, 10.0, 20.0, 25.0]
    assert scene.text == scene_text()  # verbatim, for the log


def test_effect_parameters_not_given_take_the_declared_defaults():
    scene = parse({"[effects.force_noise]\nstd_N = 0.2": "[effects.force_noise]\n\n[effects.force_drift]"})
    assert scene.effects == {"force_noise": {"std_N": 0.5}, "force_drift": {"rate_N_per_s": 0.01}}


@pytest.mark.parametrize("old, new, kind, suggestion", [
    ("[procedure]\n", "[procedur]\n", "top-level table", "procedure"),
    ("gate_time_s = 1.0", "gate_tme_s = 1.0", "key in [procedure]", "gate_time_s"),
    ("[effects.force_noise]", "[effects.force_nois]", "effect", "force_noise"),
    ("std_N = 0.2", "std_n = 0.2", "key in [effects.force_noise]", "std_N"),
    ("mu = 0.3", "muu = 0.3", "key in [parameters]", "mu"),
    ("load_N = [", "load = [", "key in [procedure.sweep]", "load_N"),
    ('model = "rigid"', 'model = "rigd"', "contact.model", "rigid"),
    ('drive = "quasi_static"', 'drive = "quasi-static"', "scene.drive", "quasi_static"),
    ('stand = "fake"', 'stand = "yok"', "stand", "yoke"),
    ("settle_timeout_s = 3.0", 'settle_timeout_s = 3.0\non_settle_timeout = "stpo"', "procedure.on_settle_timeout",
     "stop"),
])
def test_unknown_names_are_errors_with_a_suggestion(old, new, kind, suggestion):
    with pytest.raises(UnknownNameError) as info:
        parse({old: new})
    assert info.value.name == kind
    assert f"did you mean {suggestion!r}?" in str(info.value)


@pytest.mark.parametrize("old, new, name, valid", [
    ("mu = 0.3", "mu = 5.0", "parameters.mu", "[0.01, 2]"),
    ("load_N = [5.0, 10.0, 20.0, 25.0]", "load_N = [5.0, 2000.0]", "procedure.sweep.load_N[1]", "[1, 1000] N"),
    ("load_N = [5.0, 10.0, 20.0, 25.0]", "load_N = { start = 0.5, stop = 10, num = 3 }",
     "procedure.sweep.load_N.start", "[1, 1000] N"),
    ("speed_rad_s = 10.0", "speed_rad_s = 0.0", "procedure.fixed.speed_rad_s", "[0.1, 100] rad/s"),
    ("gate_time_s = 1.0", "gate_time_s = 0", "procedure.gate_time_s", "(0, inf) s"),
    ("poisson = 0.3", "poisson = 0.6", "contact.poisson", "[0, 0.5]"),
    ('model = "rigid"', 'model = "kinematic"\nn = 2', "contact.n", "[4, 512]"),
    ('model = "rigid"', 'model = "kinematic"\neffects = { psi = 0.5 }', "contact.effects.psi", "[1, inf)"),
    ("seed = 7", "seed = -1", "scene.seed", "[0, 9.22337e+18]"),  # 2**63 - 1, formatted by rig.validate
])
def test_out_of_range_values_name_the_key_and_the_range(old, new, name, valid):
    with pytest.raises(ParameterError) as info:
        parse({old: new})
    assert info.value.name == name
    assert valid in info.value.valid


def test_the_error_budget_is_named_or_off_and_misspelt_is_an_error():
    assert parse().contact.error_budget is False  # not named: the reduction adds nothing, costs nothing
    assert parse({"poisson = 0.3": "poisson = 0.3\nerror_budget = true"}).contact.error_budget is True
    with pytest.raises(UnknownNameError, match="did you mean 'error_budget'"):
        parse({"poisson = 0.3": "poisson = 0.3\nerror_budjet = true"})
    with pytest.raises(ParameterError) as info:
        parse({"poisson = 0.3": 'poisson = 0.3\nerror_budget = "yes"'})
    assert info.value.name == "contact.error_budget"


def test_contact_effect_the_model_cannot_represent_is_an_error():
    with pytest.raises(ParameterError, match="not available for model 'rigid'"):
        parse({'poisson = 0.3': 'poisson = 0.3\neffects = { psi = 1.5 }'})


@pytest.mark.parametrize("old, name", [
    ("gate_time_s = 1.0\n", "procedure.gate_time_s"),
    ("settle_timeout_s = 3.0\n", "procedure.settle_timeout_s"),
    ("seed = 7\n", "scene.seed"),
    ("poisson = 0.3\n", "contact.poisson"),
    ('drive = "quasi_static"\n', "scene.drive"),
    ("speed_rad_s = 10.0\n", "procedure.fixed.speed_rad_s"),  # a stand setting nobody set
    ('[contact]\nmodel = "rigid"\npoisson = 0.3\n', "contact"),
])
def test_missing_physical_input_is_an_error_not_a_default(old, name):
    with pytest.raises(ParameterError) as info:
        parse({old: ""})
    assert info.value.name == name and info.value.value == "missing"
    assert "required" in info.value.valid


def test_a_setting_both_fixed_and_swept_is_an_error():
    with pytest.raises(ParameterError, match="either fixed or swept"):
        parse({"speed_rad_s = 10.0": "speed_rad_s = 10.0\nload_N = 3.0"})


def test_invalid_toml_names_the_file():
    with pytest.raises(ParameterError, match="scene file <text>.*TOML"):
        parse({"seed = 7": "seed = = 7"})


def test_whole_numbers_stay_whole_for_count_parameters():
    assert parse({"mu = 0.3": "marks_1 = 30"}).parameters == {"marks_1": 30}
    assert isinstance(parse({"mu = 0.3": "marks_1 = 30"}).parameters["marks_1"], int)


def test_plan_is_the_cartesian_product_first_sweep_outermost_with_repeats():
    scene = parse({"[procedure.fixed]\nspeed_rad_s = 10.0": "[procedure.fixed]",
                   "load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 10.0]\nspeed_rad_s = [1.0, 2.0, 3.0]",
                   "gate_time_s = 1.0": "gate_time_s = 1.0\nrepeats = 2"})
    points = scene.procedure.points()
    expected = [(load, speed) for load in (5.0, 10.0) for speed in (1.0, 2.0, 3.0) for _ in range(2)]
    assert [(p.settings["load_N"], p.settings["speed_rad_s"]) for p in points] == expected
    assert [p.index for p in points] == list(range(12)) and [p.repeat for p in points[:4]] == [0, 1, 0, 1]
    assert points[0].previous is None
    assert all(points[k].previous == points[k - 1].settings for k in range(1, 12))


def test_log_spaced_values_are_exact_decades():
    scene = parse({"load_N = [5.0, 10.0, 20.0, 25.0]": 'load_N = { start = 1, stop = 100, num = 3, spacing = "log" }'})
    values = dict(scene.procedure.sweep)["load_N"]
    assert values == pytest.approx((1.0, 10.0, 100.0), rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e4, max_value=1e4))
def test_a_load_is_accepted_exactly_inside_its_declared_range(load):
    text = {"load_N = [5.0, 10.0, 20.0, 25.0]": f"load_N = [{load!r}]"}
    if 1.0 <= load <= 1000.0:
        assert dict(parse(text).procedure.sweep)["load_N"] == (load,)
    else:
        with pytest.raises(ParameterError) as info:
            parse(text)
        assert info.value.name == "procedure.sweep.load_N[0]" and "[1, 1000] N" in info.value.valid


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(1, 4), min_size=1, max_size=2), st.integers(1, 3))
def test_plan_size_and_chain_for_any_sweep_shape(lengths, repeats):
    axes = ["load_N", "speed_rad_s"][: len(lengths)]
    sweep = "\n".join(f"{name} = {{ start = 2, stop = 50, num = {n} }}" for name, n in zip(axes, lengths))
    fixed = "" if len(axes) == 2 else "speed_rad_s = 10.0"
    scene = parse({"[procedure.fixed]\nspeed_rad_s = 10.0": f"[procedure.fixed]\n{fixed}",
                   "load_N = [5.0, 10.0, 20.0, 25.0]": sweep,
                   "gate_time_s = 1.0": f"gate_time_s = 1.0\nrepeats = {repeats}"})
    points = scene.procedure.points()
    assert len(points) == scene.procedure.n_points == math.prod(lengths) * repeats
    assert [p.index for p in points] == list(range(len(points)))
    assert all(p.previous == q.settings for q, p in zip(points, points[1:]))
