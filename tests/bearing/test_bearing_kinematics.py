"""Ball kinematics (S4)-(S11) of [Oscillating], checked with 3-D vector algebra in the cage frame."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.bearing.ball_raceway import Ring
from rig.bearing.fag7208 import FAG_7208
from rig.bearing.kinematics import (
    ball_angular_speed,
    ball_centre_speed,
    cage_speed,
    contact_spin,
    raceway_speed,
    relative_rolling_speed,
)
from rig.errors import ParameterError

speeds = st.floats(-500.0, 500.0)


def test_cage_speed_with_fixed_outer_ring_is_textbook():
    """Outer ring fixed: w_C = w_IR (1 - gamma)/2 (standard bearing kinematics)."""
    assert cage_speed(FAG_7208, 100.0, 0.0) == pytest.approx(100.0 * (1.0 - FAG_7208.gamma) / 2.0, rel=1e-12)
    assert ball_centre_speed(FAG_7208, 100.0, 0.0) == pytest.approx(
        cage_speed(FAG_7208, 100.0, 0.0) * FAG_7208.pitch_radius
    )


@settings(max_examples=50, deadline=None)
@given(w_in=speeds, w_out=speeds)
def test_s9_equals_s10(w_in, w_out):
    """(S9) v_r = (w_OR - w_C) r_o (printed w_RE read as w_C) equals (S10)."""
    s9 = (w_out - cage_speed(FAG_7208, w_in, w_out)) * FAG_7208.contact_radius(Ring.OUTER)
    assert relative_rolling_speed(FAG_7208, w_in, w_out) == pytest.approx(s9, rel=1e-9, abs=1e-12)


@settings(max_examples=50, deadline=None)
@given(w_in=speeds, w_out=speeds)
def test_rolling_without_slip_and_spin_by_vector_algebra(w_in, w_out):
    """Cage frame at the ball: e_r = X, e_theta = Y, bearing axis = Z. Ball axis t perpendicular to
    the contact line n (the assumption of (S11)); both contacts must roll without slip, and the
    spin = (w_ring,rel - w_ball).n must equal contact_spin."""
    alpha = FAG_7208.contact_angle
    r_c, r_b = FAG_7208.pitch_radius, FAG_7208.ball_radius
    n = np.array([math.cos(alpha), 0.0, math.sin(alpha)])
    t = np.array([-math.sin(alpha), 0.0, math.cos(alpha)])
    w_c = cage_speed(FAG_7208, w_in, w_out)
    w_ball = ball_angular_speed(FAG_7208, w_in, w_out) * t
    centre = np.array([r_c, 0.0, 0.0])
    z = np.array([0.0, 0.0, 1.0])
    for ring, sign, w_ring in ((Ring.OUTER, 1.0, w_out), (Ring.INNER, -1.0, w_in)):
        point = centre + sign * r_b * n
        ring_rate = (w_ring - w_c) * z
        ball_velocity = np.cross(w_ball, point - centre)
        ring_velocity = np.cross(ring_rate, point)
        np.testing.assert_allclose(ball_velocity, ring_velocity, atol=1e-9 * (1 + abs(w_in) + abs(w_out)))
        assert np.hypot(point[0], point[1]) == pytest.approx(FAG_7208.contact_radius(ring))
        spin = float(np.dot(ring_rate - w_ball, n))
        assert contact_spin(FAG_7208, ring, w_in, w_out) == pytest.approx(spin, rel=1e-9, abs=1e-12)


def test_spin_split_between_the_contacts():
    w_in, w_out = 50.0, 0.0
    s_in = contact_spin(FAG_7208, Ring.INNER, w_in, w_out)
    s_out = contact_spin(FAG_7208, Ring.OUTER, w_in, w_out)
    assert s_in * s_out < 0
    assert abs(s_in) * FAG_7208.contact_radius(Ring.INNER) == pytest.approx(abs(s_out) * FAG_7208.contact_radius(Ring.OUTER))
    assert raceway_speed(FAG_7208, Ring.INNER, w_in) == pytest.approx(w_in * FAG_7208.contact_radius(Ring.INNER))


def test_invalid_speeds_raise():
    with pytest.raises(ParameterError, match="omega_outer"):
        relative_rolling_speed(FAG_7208, 1.0, math.nan)
    with pytest.raises(ParameterError, match="ring"):
        contact_spin(FAG_7208, "outer", 1.0, 0.0)
