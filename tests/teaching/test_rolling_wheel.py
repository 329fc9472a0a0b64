"""A wheel pulled at its centre ([Zhao] slides 22-24, 33-40; Equations §6)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.teaching.coulomb import STANDARD_GRAVITY as G
from rig.teaching.rolling_resistance import steady_pull
from rig.teaching.rolling_wheel import Wheel, max_rolling_pull, pulled_wheel

DISC = Wheel.solid_disc(10.0, 0.3)
N = 10.0 * G


def test_solid_disc_textbook_values_without_rolling_resistance():
    motion = pulled_wheel(DISC, 30.0, N, 0.0, 0.8, 0.6)
    assert motion.rolls
    assert motion.acceleration_m_s2 == pytest.approx(2.0 * 30.0 / (3.0 * 10.0))  # a = 2F/(3m)
    assert motion.friction_N == pytest.approx(30.0 / 3.0)  # T = F/3
    assert motion.angular_acceleration_rad_s2 * 0.3 == pytest.approx(motion.acceleration_m_s2)  # a = omega' r
    assert max_rolling_pull(DISC, N, 0.0, 0.8) == pytest.approx(3.0 * 0.8 * N)  # F_max = 3 mu_s N


def test_thin_ring_and_rolling_resistance():
    ring = Wheel(2.0, 2.0 * 0.5**2, 0.5)  # J = m r^2
    assert pulled_wheel(ring, 8.0, 2.0 * G, 0.0, 1.0, 1.0).acceleration_m_s2 == pytest.approx(8.0 / 4.0)  # F/(2m)
    motion = pulled_wheel(DISC, 30.0, N, 0.015, 0.8, 0.6)
    assert motion.acceleration_m_s2 == pytest.approx((30.0 - 0.015 * N) / 15.0)  # (F - f_v N)/(m + J/r^2)
    assert motion.friction_N == pytest.approx(DISC.inertia_kg_m2 * motion.acceleration_m_s2 / 0.09 + 0.015 * N)


def test_the_steady_pull_keeps_the_speed():
    motion = pulled_wheel(DISC, steady_pull(N, 0.015), N, 0.015, 0.8, 0.6)
    assert motion.acceleration_m_s2 == pytest.approx(0.0, abs=1e-12)
    assert motion.friction_N == pytest.approx(0.015 * N)  # T = f_v N: the reaction tilted backwards


def test_beyond_the_maximum_pull_the_wheel_slips():
    f_max = max_rolling_pull(DISC, N, 0.015, 0.8)
    assert f_max == pytest.approx(3.0 * 0.8 * N - 2.0 * 0.015 * N)
    below = pulled_wheel(DISC, f_max * (1 - 1e-9), N, 0.015, 0.8, 0.6)
    above = pulled_wheel(DISC, f_max * (1 + 1e-9), N, 0.015, 0.8, 0.6)
    assert below.rolls and not above.rolls
    assert above.friction_N == pytest.approx(0.6 * N)
    assert above.acceleration_m_s2 == pytest.approx((f_max - 0.6 * N) / 10.0, rel=1e-6)
    assert above.acceleration_m_s2 > above.angular_acceleration_rad_s2 * 0.3  # the centre outruns the rim


@given(st.floats(0.0, 1.0), st.floats(0.0, 0.05), st.floats(0.2, 1.5))
def test_with_equal_coefficients_the_motion_is_continuous_at_the_threshold(fraction, f_v, mu):
    f_max = max_rolling_pull(DISC, N, f_v, mu)
    below = pulled_wheel(DISC, f_max * (1 - 1e-9), N, f_v, mu, mu)
    above = pulled_wheel(DISC, f_max * (1 + 1e-9), N, f_v, mu, mu)
    assert above.acceleration_m_s2 == pytest.approx(below.acceleration_m_s2, rel=1e-6, abs=1e-9)
    assert above.friction_N == pytest.approx(below.friction_N, rel=1e-6)
    inside = pulled_wheel(DISC, fraction * f_max, N, f_v, mu, mu)
    assert inside.rolls and abs(inside.friction_N) <= mu * N * (1 + 1e-12) and math.isfinite(inside.acceleration_m_s2)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: Wheel(0.0, 1.0, 1.0), "mass_kg"),
        (lambda: pulled_wheel(DISC, 1.0, 0.0, 0.0, 0.5, 0.5), "vertical_load"),
        (lambda: pulled_wheel(DISC, 1.0, N, 1.0, 0.5, 0.5), "f_v"),
        (lambda: pulled_wheel(DISC, 1.0, N, 0.01, 0.5, 0.7), "mu_k"),
        (lambda: max_rolling_pull(DISC, N, 0.6, 0.5), "f_v"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name
