"""rig.wheel_kinematics on numpy arrays (known problem 5): one implementation of eqs. (29)-(31) for the
reduction (scalars) and the stand simulator (arrays), element-wise equal to the scalar path."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.stands.yoke import contact_forces
from rig.wheel_kinematics import (
    AxisSides,
    SpinTooSmallError,
    c_for_l,
    centroid_moments,
    dl_dratio,
    pair_spin,
    ratio_for_l,
    rolling_point,
    signed_normal_speeds,
    stand_a_rolling_point,
    stand_b_offset,
    stand_b_twist,
)

ALPHA1, L1, L2, DH = math.radians(73.4), 42.76e-3, -50.50e-3, 1.06e-3


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(0.05, 3.0), min_size=1, max_size=20))
def test_array_results_equal_the_scalar_path_elementwise(ratios):
    ratio = np.array(ratios)
    c, l = stand_a_rolling_point(ratio, ALPHA1, L1, L2, DH)
    assert isinstance(c, np.ndarray) and c.shape == ratio.shape
    for k, r in enumerate(ratios):
        cs, ls = stand_a_rolling_point(r, ALPHA1, L1, L2, DH)
        assert isinstance(cs, float) and (c[k], l[k]) == (cs, ls)
        assert dl_dratio(ratio, ALPHA1, L1, L2)[k] == dl_dratio(r, ALPHA1, L1, L2)
    assert ratio_for_l(l, ALPHA1, L1, L2) == pytest.approx(ratio, rel=1e-12)
    assert c_for_l(l, L1, L2, DH) == pytest.approx(c, rel=1e-12, abs=1e-18)


def test_centroid_moments_are_finite_at_zero_spin_where_the_rolling_point_raises():
    w01 = np.array([1.0, 2.0, 0.5])
    w02 = np.array([0.8, -2.0, 0.0])
    p_c, p_l = centroid_moments(w01, w02, (0.0, L1), (DH, L2))
    assert np.all(np.isfinite(p_c)) and p_l[1] == pytest.approx(2.0 * L1 - 2.0 * L2)
    with pytest.raises(SpinTooSmallError, match=r"w01 \+ w02 = 0.0"):
        rolling_point(w01, w02, (0.0, L1), (DH, L2))  # the second element has zero spin


def test_speeds_and_spin_accept_arrays():
    w1 = np.array([25.13, 20.0])
    w01, w02 = signed_normal_speeds(w1, ALPHA1, 0.8 * w1, math.pi / 2, AxisSides.OPPOSITE)
    assert np.allclose(w01 + w02, pair_spin(w1, ALPHA1, 0.8 * w1, math.pi / 2, AxisSides.OPPOSITE))
    assert isinstance(pair_spin(25.13, ALPHA1, 20.0, math.pi / 2, AxisSides.SAME), float)


def test_array_range_errors_name_the_first_bad_value():
    with pytest.raises(ParameterError, match="l = 0.05"):
        ratio_for_l(np.array([0.0, 0.05]), ALPHA1, L1, L2)
    with pytest.raises(ParameterError, match="c = 0.08"):
        stand_b_twist(0.0702, np.array([0.0, 0.08]))
    sigma = np.array([0.0, math.radians(6.54)])
    assert stand_b_offset(0.0702, sigma)[1] == pytest.approx(8.0e-3, abs=5e-6)  # Equations §3.2


def test_the_stand_simulator_has_no_copy_of_the_formula():
    # the vectorised contact of stand A takes w0 C from rig.wheel_kinematics.centroid_moments
    source = contact_forces.__loader__.get_source(contact_forces.__name__)
    assert "centroid_moments(" in source and "w01 * g.l1 + w2 * g.l2" not in source
