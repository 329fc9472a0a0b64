"""Oscillation scenes ([Oscillating]): validation and a tiny run through rig.runner."""

import pandas as pd
import pytest

from rig.errors import ParameterError, UnknownNameError
from rig.runner import run_scene
from rig.scenes import OscillationScene, parse_scene

TINY = """
[scene]
kind = "oscillation"
description = "tiny ball-raceway sweep"

[oscillation]
contact = "ball_raceway"
ring = "inner"
force_N = 1270.0
mu = [0.1, 0.2]
n = 8
stroke_ratio = [0.5, 1.5]
map_stroke_ratio = 1.0
"""


def test_an_oscillation_scene_builds_one_contact_per_mu():
    scene = parse_scene(TINY, name="tiny")
    assert isinstance(scene, OscillationScene)
    assert [c.mu for c in scene.contacts] == [0.1, 0.2] and scene.stroke_ratios == (0.5, 1.5)
    assert scene.contacts[1].alpha == pytest.approx(2 * scene.contacts[0].alpha), "alpha' (eq. 21) is linear in mu"


@pytest.mark.parametrize(
    "change, error, match",
    [
        (("force_N = 1270.0", "forse_N = 1270.0"), UnknownNameError, "did you mean 'force_N'"),
        (('contact = "ball_raceway"', 'contact = "ball_bearing"'), UnknownNameError, "ball_raceway"),
        (("mu = [0.1, 0.2]", "mu = [0.1, -0.2]"), ParameterError, "oscillation.mu"),
        (("stroke_ratio = [0.5, 1.5]", "stroke_ratio = [0.5, 15.0]"), ParameterError, "stroke_ratio"),
        (('ring = "inner"\n', ""), ParameterError, "ring"),
    ],
)
def test_bad_oscillation_scenes_name_what_is_wrong(change, error, match):
    with pytest.raises(error, match=match):
        parse_scene(TINY.replace(*change), name="bad")


def test_a_tiny_oscillation_run_writes_the_sweep_the_figures_and_the_mu_comparison(tmp_path):
    report = run_scene(parse_scene(TINY, name="tiny"), tmp_path)
    assert set(report.files) == {"oscillation_sweep.csv", "oscillation_sweep.png", "work_map.png", "summary.txt"}
    sweep = pd.read_csv(tmp_path / "oscillation_sweep.csv")
    assert list(sweep.columns[:3]) == ["mu", "alpha", "stroke_ratio"] and len(sweep) == 4
    assert (sweep["max_work_J_m2"] > 0).all()
    assert "mu 0.2 vs 0.1: max W x" in report.summary
