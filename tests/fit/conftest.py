"""A small stand-A run shared by the fit tests: the fig10 procedure at R_x = 20 mm (alpha' ~ 4-8,
where the contact effects show), mu = 0.35, static_ratio = 1.4 in the contact, 5 points per load,
3 s gates, n = 8 (about 10-30 s to simulate once per session)."""

from __future__ import annotations

import re
from importlib import resources

import pytest

SMALL_STATIC_RATIO_RUN = dict(mu=0.35, static_ratio=1.4, radius_x=0.02, seed=17)


def small_stand_a_scene(*, mu: float, radius_x: float, seed: int, effects: str = "") -> str:
    """fig10.toml with R_x [m], mu, seed, 5 points per series, 3 s gates, n = 8, a 13 x 3 x 5 table and
    the contact effects ``effects`` (TOML inline-table body, e.g. "static_ratio = 1.4")."""
    text = resources.files("rig.scenes.builtin").joinpath("fig10.toml").read_text(encoding="utf-8")
    for pattern, new in (
        (r"(?m)^mu = [0-9.]+", f"radius_x_m = {radius_x!r}\nmu = {mu!r}"),
        (r"(?m)^seed = [0-9]+", f"seed = {seed}"),
        (r"(?m)^n = [0-9]+ ", "n = 8 "),
        (r"(?m)^table_points = \[21, 3, 5\]", "table_points = [13, 3, 5]" + (f"\neffects = {{ {effects} }}"
                                                                              if effects else "")),
        (r"(?m)^gate_time_s = [0-9.]+", "gate_time_s = 3.0"),
        (r"num = 24", "num = 5"),
    ):
        text, count = re.subn(pattern, new, text)
        assert count >= 1, f"fig10.toml changed: {pattern!r} not found"
    return text


@pytest.fixture(scope="session")
def static_ratio_run(tmp_path_factory):
    """Folder of a finished small stand-A run (log.h5, reduced.csv) whose contact has static_ratio 1.4."""
    from rig.runner import run_scene
    from rig.scenes.load import parse_scene

    c = SMALL_STATIC_RATIO_RUN
    text = small_stand_a_scene(mu=c["mu"], radius_x=c["radius_x"], seed=c["seed"],
                               effects=f"static_ratio = {c['static_ratio']}")
    folder = tmp_path_factory.mktemp("static_ratio_run")
    (folder / "scene.toml").write_text(text)
    run_scene(parse_scene(text, name="small_static_ratio", source="tests/fit/conftest.py"), folder / "run",
              progress=False)
    return folder / "run"
