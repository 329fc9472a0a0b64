"""Stand-level kinematics (rig.wheel_kinematics) against the Equations page's arithmetic (sections 1.2, 2, 3)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.contact.kinematics import spin
from rig.errors import ParameterError
from rig.wheel_kinematics import (
    AxisSides,
    SpinTooSmallError,
    c_for_l,
    dl_dratio,
    pair_spin,
    ratio_for_l,
    rolling_point,
    signed_normal_speeds,
    stand_a_rolling_point,
    stand_b_offset,
    stand_b_twist,
)

# Equations §3.1 "Derived", stand A at l = 0 (four-digit hand numbers).
IK, ALPHA1, L1, L2, DH = 0.8115, math.radians(73.4), 42.76e-3, -50.50e-3, 1.06e-3


def test_stand_a_hand_numbers_at_l_zero():
    c, l = stand_a_rolling_point(IK, ALPHA1, L1, L2, DH)
    # Rounding of the 4-digit inputs moves l by |dl/di_k| 5e-5 + 0.005 mm sin(a1)/(...) ~ 4 um.
    assert abs(l) < 5e-6
    assert c == pytest.approx(0.486e-3, abs=0.5e-6)
    assert c == pytest.approx(c_for_l(l, L1, L2, DH), rel=1e-12)  # eq. (32) == eq. (31)


def test_spin_of_stand_a_is_1_77_w1():
    w1 = 25.13  # 240 rpm
    w0 = pair_spin(w1, ALPHA1, IK * w1, math.pi / 2, AxisSides.OPPOSITE)
    assert w0 == pytest.approx(1.77 * w1, rel=2e-4)  # text: w0/w1 = 1.77, w0 = 44 rad/s
    assert w0 == pytest.approx(spin(w1, ALPHA1, -IK * w1, math.pi / 2))
    w01, w02 = signed_normal_speeds(w1, ALPHA1, IK * w1, math.pi / 2, AxisSides.OPPOSITE)
    assert w01 + w02 == pytest.approx(w0)
    w01, w02 = signed_normal_speeds(w1, ALPHA1, IK * w1, math.pi / 2, AxisSides.SAME)
    assert w01 + w02 == pytest.approx(pair_spin(w1, ALPHA1, IK * w1, math.pi / 2, AxisSides.SAME))
    assert w01 + w02 == pytest.approx(w1 * (math.sin(ALPHA1) - IK))


def test_dl_dratio_is_minus_28_5_mm_and_matches_a_difference():
    assert dl_dratio(IK, ALPHA1, L1, L2) == pytest.approx(-28.5e-3, abs=0.1e-3)  # Equations §2
    h = 1e-6
    def l_of(ratio):
        return stand_a_rolling_point(ratio, ALPHA1, L1, L2, DH)[1]

    fd = (l_of(IK + h) - l_of(IK - h)) / (2 * h)
    assert dl_dratio(IK, ALPHA1, L1, L2) == pytest.approx(fd, rel=1e-6)


def test_fig_11_caption_slope():
    # Fig. 11: c/a = 0.4 - l/(87.7 a) for Delta h = 1.06 mm  => dc/dl = -Dh/(l1 - l2) = -1/87.7 (0.3 %).
    slope = (c_for_l(1e-3, L1, L2, DH) - c_for_l(0.0, L1, L2, DH)) / 1e-3
    assert slope == pytest.approx(-1 / 87.7, rel=4e-3)


@given(st.floats(-0.99, 0.99), st.floats(0.0, 2e-3))
def test_ratio_for_l_inverts_eq_30(l_over_a, dh):
    a = 1.215e-3
    ratio = ratio_for_l(l_over_a * a, ALPHA1, L1, L2)
    c, l = stand_a_rolling_point(ratio, ALPHA1, L1, L2, dh)
    assert l == pytest.approx(l_over_a * a, abs=1e-15)
    assert c == pytest.approx(c_for_l(l, L1, L2, dh), abs=1e-15)
    assert 0.0 <= c <= dh  # Equations §2: c <= Delta h always


def test_weighted_centroid_general_points_and_rotation_about_c():
    w01, w02 = 3.0, -1.0  # same-side axes: signed speeds of opposite signs
    a1, a2 = (0.2, 1.0), (-0.5, 4.0)
    c, l = rolling_point(w01, w02, a1, a2)
    # the in-plane velocities w01 z x (P - A1) and -w02 z x (P - A2) agree at C
    v1 = (-w01 * (l - a1[1]), w01 * (c - a1[0]))
    v2 = (w02 * (l - a2[1]), -w02 * (c - a2[0]))
    assert v1 == pytest.approx(v2, abs=1e-12)


@pytest.mark.parametrize("w01, w02", [(1.0, -1.0), (0.0, 0.0), (1.0, -1.0 + 1e-12), (math.nan, 1.0)])
def test_vanishing_spin_raises_named_error(w01, w02):
    with pytest.raises(SpinTooSmallError, match=r"w01 \+ w02"):
        rolling_point(w01, w02, (0.0, 0.0), (0.0, 1.0))
    assert issubclass(SpinTooSmallError, ValueError)


def test_ratio_for_l_outside_the_axes_raises():
    with pytest.raises(ParameterError, match="l = "):
        ratio_for_l(L1, ALPHA1, L1, L2)
    with pytest.raises(ParameterError, match="l1 - l2"):
        c_for_l(0.0, L1, L1, DH)


def test_stand_b_eq_36():
    e = 70.2e-3
    assert stand_b_offset(e, math.radians(6.54)) == pytest.approx(8.0e-3, abs=5e-6)  # Equations §3.2
    assert stand_b_twist(e, 8.0e-3) == pytest.approx(math.radians(6.54), abs=1e-4)
    assert stand_b_offset(e, stand_b_twist(e, -8e-3)) == pytest.approx(-8e-3, rel=1e-12)
    with pytest.raises(ParameterError, match="c = "):
        stand_b_twist(e, 0.08)
