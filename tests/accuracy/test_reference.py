"""The contact axis's converged reference, unavailable quantities and the build-cost front, on
``rig accuracy default``'s design with made-up run results (no simulation; < 1 s).

Independent facts: reduced outputs that follow f(n) = f0 + C/n exactly extrapolate to f0 (the
analytic limit), so each grid's error is C/n; the rigid law gives no mu_v (it has no lateral force
coefficient), so it cannot be on the front however small its other differences are.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from rig.accuracy.design import Axis, StudyOptions, reference_grids, study_design
from rig.accuracy.markdown import report_markdown
from rig.accuracy.schedule import Measurement
from rig.accuracy.table import COLUMNS, result_table
from rig.scenes import load_scene

POINTS = pd.Index([0, 1, 2, 3], name="point")
LIMIT = np.array([0.10, 0.35, 0.60, 0.85])  # converged l/a at the four points
C = 0.3  # first-order grid error coefficient of the made-up kinematic law


def _reduced(l_over_a, mu_v):
    return pd.DataFrame({"l_over_a": l_over_a, "mu_v": mu_v, "mu_T": 0.4 + 0.0 * l_over_a,
                         "true_l_over_a": l_over_a, "u_l_over_a": 0.002, "u_mu_T": 0.003,
                         "true_mu_v": 0.4, "true_mu_T": 0.4}, index=POINTS)


def _measurement(setting):
    c = setting.contact
    n = c.n or 32
    if c.model == "kinematic":
        reduced, build = _reduced(LIMIT + C / n, 0.4 + C / n), 0.02 * n * n
    elif c.model == "rigid":  # nearly the converged l/a, but no mu_v at all
        reduced, build = _reduced(LIMIT + 2.6e-4, np.nan), 0.5
    else:
        reduced, build = _reduced(LIMIT + 0.06, 0.46), 1.0
    return Measurement(reduced, build + 1.0, (1.0, 1.1, 0.9), 10.0, 4, 0, True)


@pytest.fixture(scope="module")
def study():
    design = study_design(load_scene("default"), StudyOptions())
    measurements = {s.key(): _measurement(s) for s in design.settings()}
    table = result_table(design, measurements)
    return design, table


def test_reference_grids():
    assert reference_grids(32) == (8, 16, 32)
    assert reference_grids(24) == (6, 12, 24)
    assert reference_grids(6) is None and reference_grids(12) is None  # N/4 below 4, or not a multiple of 4


def test_the_contact_axis_adds_the_coarse_grid_its_extrapolation_needs(study):
    design, _ = study
    plan = next(p for p in design.axes if p.axis is Axis.CONTACT)
    assert [plan.entries[i].label for i in plan.extrapolated] == ["kinematic n=6", "kinematic n=12", "kinematic n=24"]


def test_errors_are_against_the_converged_value_not_the_finest_grid(study):
    _, table = study
    assert tuple(table.columns) == COLUMNS
    contact = table[table["axis"] == Axis.CONTACT.value].set_index("setting")
    for n in (6, 8, 12, 16, 24):  # l/a and mu_v are C/n off the limit at every point
        assert contact.loc[f"kinematic n={n}", "d_l_over_a"] == pytest.approx(C / n, rel=1e-9)
        assert contact.loc[f"kinematic n={n}", "d_mu_v"] == pytest.approx(C / n, rel=1e-9)
    assert not contact["reference"].any()  # the finest grid stays a setting with its own error
    # Roache's uncertainty: a quarter of the correction from n = 24 to the limit
    assert contact.loc["kinematic n=24", "u_reference"] == pytest.approx(0.25 * C / 24, rel=1e-9)


def test_a_law_without_mu_v_is_unavailable_and_never_on_the_front(study):
    _, table = study
    contact = table[table["axis"] == Axis.CONTACT.value].set_index("setting")
    rigid = contact[contact.index.str.startswith("rigid")]
    assert (rigid["unavailable"] == "mu_v").all()
    assert rigid["error"].isna().all() and not rigid["on_front"].any()
    # its l/a differs from the converged one by only 2.6e-4, less than any kinematic grid's 0.0125
    assert (rigid["d_l_over_a"] < contact.loc["kinematic n=24", "d_l_over_a"]).all()


def test_the_front_uses_the_table_build_cost(study):
    _, table = study
    for axis in (Axis.CONTACT.value, Axis.TABLE.value):
        rows = table[table["axis"] == axis]
        np.testing.assert_array_equal(rows["cost_s"], rows["cpu_first_s"])
    contact = table[table["axis"] == Axis.CONTACT.value].set_index("setting")
    # per run every setting costs ~1 s; the build ranks the grids: every kinematic grid is on the front
    assert contact.loc[[f"kinematic n={n}" for n in (6, 8, 12, 16, 24)], "on_front"].all()


def test_the_report_names_the_reference_and_says_what_to_choose(study):
    design, table = study
    text = report_markdown("t", [], design, table, None, 1.0)
    assert "kinematic n=6, kinematic n=12, kinematic n=24 extrapolated point by point to zero cell size" in text
    assert "unavailable" in text and "### Which setting to choose" in text
    choice = next(line for line in text.splitlines() if line.startswith("* contact model x grid: choose"))
    assert "rigid" not in choice and "kinematic n=24" in choice
