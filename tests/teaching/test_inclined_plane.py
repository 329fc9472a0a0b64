"""The inclined plane ([Zhao] slides 15-16, 20-21): rest iff tan(alpha) <= mu_s; a = g (sin - mu_k cos)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.teaching.coulomb import STANDARD_GRAVITY as G
from rig.teaching.inclined_plane import at_rest, critical_angle, reaction, sliding_acceleration


def test_threshold_is_tan_alpha_equal_mu_s():
    assert not at_rest(math.radians(30.0), 0.5)  # tan 30 deg = 0.577 > 0.5
    assert at_rest(math.radians(30.0), 0.6)
    star = critical_angle(0.8)
    assert star == pytest.approx(0.674740942, abs=1e-9)  # atan(0.8), steel-steel dry
    assert at_rest(star - 1e-9, 0.8) and not at_rest(star + 1e-9, 0.8)
    assert at_rest(0.0, 0.0) and not at_rest(math.pi / 2, 3.0)


def test_sliding_acceleration_worked_values():
    assert sliding_acceleration(math.radians(30.0), 0.0) == pytest.approx(G / 2)  # frictionless g sin 30
    expected = 9.80665 * (0.5 - 0.2 * math.sqrt(3.0) / 2.0)
    assert sliding_acceleration(math.radians(30.0), 0.2) == pytest.approx(expected, rel=1e-12)
    assert sliding_acceleration(math.atan(0.3), 0.3) == pytest.approx(0.0, abs=1e-12)  # steady sliding
    assert sliding_acceleration(math.pi / 2, 0.9) == pytest.approx(G)  # free fall along a wall


def test_reaction_balances_the_weight():
    n, t = reaction(2.0, math.radians(25.0))
    assert math.hypot(n, t) == pytest.approx(2.0 * G)
    assert t / n == pytest.approx(math.tan(math.radians(25.0)))


@given(st.floats(0.0, math.pi / 2), st.floats(0.0, 3.0), st.floats(0.0, 3.0))
def test_friction_only_lowers_the_acceleration(alpha, mu_1, mu_2):
    a1, a2 = sliding_acceleration(alpha, mu_1), sliding_acceleration(alpha, mu_2)
    assert math.isfinite(a1) and a1 <= G * math.sin(alpha) + 1e-12
    assert (a1 - a2) * (mu_1 - mu_2) <= 1e-12  # non-increasing in mu_k


@pytest.mark.parametrize("alpha", [-0.1, 1.6, math.nan])
def test_angle_outside_zero_to_right_angle_is_an_error(alpha):
    with pytest.raises(ParameterError, match="alpha"):
        at_rest(alpha, 0.5)
