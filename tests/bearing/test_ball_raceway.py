"""Ball-raceway Hertz contacts of the FAG 7208 ([Oscillating] Tables 1-2, Equations §5.1)."""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.bearing.ball_raceway import BearingGeometry, Ring, raceway_contact
from rig.bearing.fag7208 import FAG_7208, TABLE_2, reproduce_table_2
from rig.contact.materials import contact_modulus
from rig.errors import ParameterError

# Equations §5.1, computed independently there: (force N, P_IR GPa, P_OR GPa, b_IR mm, a_IR mm, b_OR mm, a_OR mm)
SEED_NOTES = [
    (1270.0, 2.105, 2.019, 0.1811, 1.590, 0.2325, 1.292),
    (790.0, 1.797, 1.723, 0.1546, 1.357, 0.1985, 1.103),
    (3170.0, 2.856, 2.738, 0.2457, 2.157, 0.3154, 1.753),
]


def test_table_1_derived_quantities():
    assert FAG_7208.pitch_diameter == pytest.approx(0.060)
    assert FAG_7208.gamma == pytest.approx(0.15142, abs=5e-6)
    assert FAG_7208.groove_radius(Ring.INNER) * 1e3 == pytest.approx(6.177, abs=5e-4)
    assert FAG_7208.groove_radius(Ring.OUTER) * 1e3 == pytest.approx(6.322, abs=5e-4)
    assert contact_modulus(FAG_7208.material, FAG_7208.material) == pytest.approx(115385e6, rel=1e-5)
    r_i, r_o = FAG_7208.contact_radius(Ring.INNER), FAG_7208.contact_radius(Ring.OUTER)
    assert r_i + r_o == pytest.approx(FAG_7208.pitch_diameter)
    assert r_i == pytest.approx(FAG_7208.pitch_radius * (1.0 - FAG_7208.gamma))


def test_rolling_curvature_matches_harris_form():
    """Raceway curvature in the rolling direction = (2/D_w) gamma/(1 -/+ gamma) (Equations §5.1)."""
    g, d_w = FAG_7208.gamma, FAG_7208.ball_diameter
    inner = FAG_7208.contact_geometry(Ring.INNER)
    outer = FAG_7208.contact_geometry(Ring.OUTER)
    assert 1.0 / inner.r2x == pytest.approx(2.0 / d_w * g / (1.0 - g), rel=1e-12)
    assert 1.0 / outer.r2x == pytest.approx(-2.0 / d_w * g / (1.0 + g), rel=1e-12)


@pytest.mark.parametrize("case", TABLE_2)
def test_acceptance_hertz_pressures_within_3_percent_of_table_2(case):
    """ACCEPTANCE (issue 6, item 3): P_IR 2.05/1.76/2.79 and P_OR 2.00/1.71/2.72 GPa within 3 %."""
    inner = raceway_contact(FAG_7208, Ring.INNER, case.force_N)
    outer = raceway_contact(FAG_7208, Ring.OUTER, case.force_N)
    assert inner.p0 == pytest.approx(case.p_inner_Pa, rel=0.03)
    assert outer.p0 == pytest.approx(case.p_outer_Pa, rel=0.03)
    assert inner.p0 > case.p_inner_Pa and outer.p0 > case.p_outer_Pa  # +0.7 ... +2.7 % (Equations §5.1)


@pytest.mark.parametrize(("force", "p_ir", "p_or", "b_ir", "a_ir", "b_or", "a_or"), SEED_NOTES)
def test_contacts_match_the_equations_page_arithmetic(force, p_ir, p_or, b_ir, a_ir, b_or, a_or):
    inner = raceway_contact(FAG_7208, Ring.INNER, force)
    outer = raceway_contact(FAG_7208, Ring.OUTER, force)
    assert inner.p0 / 1e9 == pytest.approx(p_ir, abs=6e-4)
    assert outer.p0 / 1e9 == pytest.approx(p_or, abs=6e-4)
    assert inner.b * 1e3 == pytest.approx(b_ir, abs=6e-5) and inner.a * 1e3 == pytest.approx(a_ir, abs=6e-4)
    assert outer.b * 1e3 == pytest.approx(b_or, abs=6e-5) and outer.a * 1e3 == pytest.approx(a_or, abs=6e-4)
    assert inner.a / inner.b == pytest.approx(8.78, abs=0.01)  # long across the groove


def test_fitted_osculations_reproduce_the_published_pressures():
    """Equations §5.1: osculations 96.48 % / 94.05 % give the published pressures within 0.6 %."""
    fitted = dataclasses.replace(FAG_7208, osculation_inner=0.9648, osculation_outer=0.9405)
    for case in TABLE_2:
        assert raceway_contact(fitted, Ring.INNER, case.force_N).p0 == pytest.approx(case.p_inner_Pa, rel=0.006)
        assert raceway_contact(fitted, Ring.OUTER, case.force_N).p0 == pytest.approx(case.p_outer_Pa, rel=0.006)


def test_reproduced_table_has_units_in_columns():
    table = reproduce_table_2()
    assert list(table["force_N"]) == [1270.0, 790.0, 3170.0]
    assert {"p_inner_GPa", "p_inner_GPa_published", "theta_e1_deg", "theta_e1_deg_published"} <= set(table.columns)


@settings(max_examples=40, deadline=None)
@given(force=st.floats(1e-6, 1e5))
def test_contact_is_finite_for_any_positive_load(force):
    c = raceway_contact(FAG_7208, Ring.OUTER, force)
    assert all(math.isfinite(v) and v > 0 for v in (c.a, c.b, c.p0))
    assert c.b_over_a == pytest.approx(raceway_contact(FAG_7208, Ring.OUTER, 1000.0).b_over_a, rel=1e-9)


def test_invalid_geometry_raises_named_errors():
    base = dataclasses.asdict(FAG_7208)
    base["material"] = FAG_7208.material
    for name, value in [
        ("inner_diameter", 0.09),
        ("ball_radius", 0.011),
        ("contact_angle", math.pi / 2),
        ("osculation_inner", 1.0),
        ("osculation_outer", 0.0),
        ("outer_diameter", -1.0),
        ("material", "steel"),
    ]:
        with pytest.raises(ParameterError, match=name):
            BearingGeometry(**dict(base, **{name: value}))
    with pytest.raises(ParameterError, match="ring"):
        raceway_contact(FAG_7208, "inner", 1000.0)
    with pytest.raises(ParameterError, match="normal_force"):
        raceway_contact(FAG_7208, Ring.INNER, 0.0)
