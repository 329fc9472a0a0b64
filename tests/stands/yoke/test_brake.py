"""Brake 12 with mechanical feedback: finite stability limit (Routh-Hurwitz), 2 % settling, disturbance."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest

from rig.errors import ParameterError
from rig.stands.yoke import brake
from rig.stands.yoke.brake import BrakeFrictionFluctuation, BrakeLoop, characteristic_roots, critical_gain
from tests.stands.yoke import helpers


def test_three_equal_lags_have_the_textbook_limit_8():
    # (1 + tau s)^3 + g = 0 is stable for g < 8 (classic Routh-Hurwitz result), for any tau
    for tau in (0.01, 0.1, 2.0):
        assert critical_gain((tau, tau, tau)) == pytest.approx(8.0, rel=1e-12)
    assert critical_gain((0.1, 0.02, 0.005)) == pytest.approx(31.5, rel=1e-12)  # 0.125 * 0.0026 / 1e-5 - 1


@pytest.mark.parametrize("taus", [(0.1, 0.02, 0.005), (0.2, 0.05, 0.05), (0.05, 0.01, 0.001)])
def test_the_limit_is_where_the_poles_cross_the_imaginary_axis(taus):
    g = critical_gain(taus)
    assert np.max(characteristic_roots(0.99 * g, taus).real) < 0.0
    assert np.max(characteristic_roots(1.01 * g, taus).real) > 0.0


def test_gain_past_the_stable_range_is_an_error_naming_gain_and_range():
    with pytest.raises(ParameterError, match=r"brake_loop_gain = 40 .*\(0, 31.5\)"):
        BrakeLoop(40, (0.1, 0.02, 0.005), 0.5)
    with pytest.raises(ParameterError, match=r"effects.brake_dynamics.loop_gain = 40.0 .*\(0, 31.5\)"):
        helpers.stand(brake_dynamics={"loop_gain": 40.0})


def test_set_point_scale_removes_the_static_error_at_nominal_lining_friction():
    loop = BrakeLoop(10.0, (0.1, 0.02, 0.005), 0.5)
    x = loop.steady_states(0.5)
    assert loop.moment(0.0, x[2]) == pytest.approx(0.5)
    assert loop.derivatives(*x, measured=0.5) == pytest.approx((0.0, 0.0, 0.0), abs=1e-15)


def test_step_of_the_set_point_settles_within_2_percent():
    # acceptance (4): a step 0.3 -> 0.6 N m; the operator's settle detection includes |T_B - T_set| <= 2 %
    st = helpers.stand(("brake_dynamics",))
    report, gate, outcome = helpers.run_point(st, helpers.settings(brake=0.6), helpers.settings(brake=0.3),
                                              gate_time=2.0)
    assert report.residual <= 1.0 and report.start == "previous point"
    assert np.max(np.abs(gate.signals["brake_moment"] / 0.6 - 1.0)) <= 0.02
    assert outcome.truth["T2"].value == pytest.approx(0.6, rel=1e-3)
    assert 0.2 < report.duration_s < 5.0  # lags of 0.1 s: the loop needs several tenths of a second


def test_fluctuation_has_the_stated_rms_and_is_rejected_by_the_loop():
    f = BrakeFrictionFluctuation(0.05, 0.05, 0.5, np.random.default_rng(3))
    t = np.linspace(0.0, 2000.0, 200_001)
    assert np.sqrt(np.mean((f.factor(t) - 1.0) ** 2)) == pytest.approx(0.05, rel=0.05)
    st = helpers.stand(("brake_dynamics", "brake_friction_fluctuation"))
    _, gate, _ = helpers.run_point(st, helpers.settings(brake=0.6), helpers.settings(brake=0.6), gate_time=20.0)
    deviation = gate.signals["brake_moment"] / 0.6 - 1.0
    # slow disturbances are reduced by about 1/(1 + g) = 1/11: a 5 % rms lining change -> well below 1 %
    assert 0.0005 < np.std(deviation) < 0.01


def test_brake_effects_off_are_never_called():
    with mock.patch.object(BrakeFrictionFluctuation, "factor", side_effect=AssertionError("called")), \
            mock.patch.object(brake.BrakeLoop, "derivatives", side_effect=AssertionError("called")):
        helpers.run_point(helpers.stand(), helpers.settings(), helpers.settings(), gate_time=1.0)


def test_fluctuation_needs_the_loop_and_a_dynamic_drive():
    with pytest.raises(ParameterError, match="brake_friction_fluctuation"):
        helpers.stand(("brake_friction_fluctuation",))
