"""Stand B's drive train: balances of the steady state, settling, hard cases 7 and 10."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings as hyp_settings
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.stands.base import DriveMode, SettleTimeoutError
from rig.stands.disc_roller.components import LoopCompliance
from rig.stands.disc_roller.parameters import point_settings
from rig.stands.disc_roller.steady_state import steady_state
from tests.stands.disc_roller.conftest import make_stand, settings

LOOP = {"loop_compliance": {}}


def test_steady_torques_follow_the_moment_transfer_and_the_energy_balance():
    stand = make_stand(LOOP)
    train = stand.drive_train(point_settings(settings()))
    ss = steady_state(train, 1)
    c = ss.contact
    # disc: T_Mo = -(M_C + R_c F_x) (docs/stand-b.md, Equations §3.2 transfer with the disc as body 1)
    assert ss.momentometer_torque == pytest.approx(-(c.moment_c + train.radius_c * c.force_x), rel=1e-12)
    # the worm supplies exactly the friction power: T_w w_r = P_t = T0 w_d, i.e. T_w = T0/i_g
    t_w = float(train.worm.torque(np.asarray(ss.roller_speed), train.set_speed))
    assert t_w == pytest.approx(c.resisting_moment / train.gear_ratio, rel=1e-9)
    assert ss.twist == pytest.approx(ss.momentometer_torque / train.loop.stiffness, rel=1e-12)
    assert ss.roller_speed * train.roller_radius / ss.disc_speed == pytest.approx(train.radius_c, rel=1e-12)


def test_bearing_friction_adds_to_the_momentometer_torque():
    plain = steady_state(make_stand(LOOP).drive_train(point_settings(settings())), 1)
    effects = dict(LOOP, bearing_friction={"disc_torque_N_m": 0.05, "roller_torque_N_m": 0.0})
    rubbing = steady_state(make_stand(effects).drive_train(point_settings(settings())), 1)
    assert rubbing.momentometer_torque - plain.momentometer_torque == pytest.approx(0.05, rel=1e-6)


def test_backlash_dead_zone_inverse():
    loop = LoopCompliance(3000.0, 1.0, backlash=math.radians(0.2))
    half = 0.5 * math.radians(0.2)
    for torque in (-20.0, -0.1, 1e-4, 0.3, 15.0):
        phi = loop.twist_for(torque)
        assert float(loop.torque(np.asarray(phi), 0.0)) == pytest.approx(torque, rel=1e-10)
    assert loop.twist_for(15.0) == pytest.approx(15.0 / 3000.0 + half, rel=1e-3)  # outside: shifted by ~delta


@pytest.mark.parametrize("effects", [{}, LOOP, dict(LOOP, gear_backlash={}, bearing_friction={})])
def test_dynamic_settles_on_the_quasi_static_state_from_rest(effects):
    stand = make_stand(effects)
    point = stand.start_point(0, settings(), None, 1)
    report = point.settle(10.0)
    assert report.start == "rest" and report.residual < 1e-3
    y_ss = point.target.y
    assert np.allclose(point.y, y_ss, rtol=2e-3, atol=1e-6 * np.maximum(np.abs(y_ss).max(), 1.0))


def test_reversal_from_a_forward_point_settles_with_mirrored_forces():
    """Hard case 7: both directions; c = 0 and a symmetric law -> F_T and T_Mo flip, F_V stays."""
    stand = make_stand(LOOP)
    forward = stand.start_point(0, settings(), None, 1)
    forward.settle(10.0)
    f_gate = forward.gate(0.5)
    reverse = stand.start_point(1, settings(direction=-1), settings(), 1)
    report = reverse.settle(10.0)
    r_gate = reverse.gate(0.5)
    assert report.start == "previous point" and report.duration_s > 0.1
    assert np.mean(r_gate.signals["F_T"]) == pytest.approx(-np.mean(f_gate.signals["F_T"]), rel=1e-6)
    assert np.mean(r_gate.signals["T_Mo"]) == pytest.approx(-np.mean(f_gate.signals["T_Mo"]), rel=1e-6)
    assert np.mean(r_gate.signals["F_V"]) == pytest.approx(np.mean(f_gate.signals["F_V"]), rel=1e-6)


def test_stiff_coupling_ten_times_is_finite_and_settles():
    """Hard case 10: momentometer 10x stiffer than the default."""
    stand = make_stand({"loop_compliance": {"stiffness_N_m_per_rad": 3.26e4}})
    point = stand.start_point(0, settings(normal_force_N=144.0), None, 1)
    point.settle(10.0)
    gate = point.gate(1.0)
    assert all(np.all(np.isfinite(v)) for v in gate.signals.values())
    assert np.mean(gate.signals["T_Mo"]) == pytest.approx(point.target.momentometer_torque, rel=1e-4)


def test_settle_timeout_is_reported_not_hung():
    stand = make_stand(LOOP)
    point = stand.start_point(0, settings(), None, 1)
    with pytest.raises(SettleTimeoutError, match="did not settle within 0.05 s"):
        point.settle(0.05)


def test_gate_before_settle_is_an_error():
    point = make_stand().start_point(0, settings(), None, 1)
    with pytest.raises(ParameterError, match="settle"):
        point.gate(1.0)


def test_quasi_static_drive_needs_no_time_and_gives_constant_signals():
    stand = make_stand(LOOP, drive=DriveMode.QUASI_STATIC)
    point = stand.start_point(0, settings(), None, 1)
    assert point.settle(1.0).duration_s == 0.0
    gate = point.gate(2.0)
    assert gate.t_s.size == 1001  # 500 Hz over [0, 2] s
    assert np.ptp(gate.signals["T_Mo"]) == 0.0
    assert gate.signals["T_Mo"][0] == pytest.approx(point.target.momentometer_torque)


@hyp_settings(max_examples=80, deadline=None)
@given(w_r=st.one_of(st.just(0.0), st.floats(-8.0, 8.0)), phi=st.floats(-0.02, 0.02),
       w_d=st.one_of(st.just(0.0), st.floats(-3.0, 3.0)), l=st.floats(-0.025, 0.025),
       sigma=st.floats(-0.2, 0.2), direction=st.sampled_from([-1, 1]))
def test_right_hand_side_is_finite_everywhere(w_r, phi, w_d, l, sigma, direction):
    """Hard cases 7, 10: zero and reversing speeds, any twist -> finite derivatives."""
    stand = make_stand(dict(LOOP, gear_backlash={}, bearing_friction={}, contact_relaxation={}))
    train = stand.drive_train(point_settings(settings(l_m=l, sigma_rad=sigma, direction=direction)))
    y = np.array([w_r, phi, w_d, 1.0, -2.0, 0.01])
    assert np.all(np.isfinite(train.rhs(0.0, y)))
    columns = np.repeat(y[:, None], 3, axis=1)
    assert np.allclose(train.rhs(0.0, columns), train.rhs(0.0, y)[:, None])  # vectorised = one by one


def test_swinging_drive_settles_periodically():
    stand = make_stand({"swinging_drive": {"frequency_Hz": 2.0}, "contact_relaxation": {}})
    point = stand.start_point(0, settings(l_m=0.0), None, 1)
    report = point.settle(20.0)
    assert report.duration_s == pytest.approx(round(report.duration_s * 2.0) / 2.0)  # whole periods
    gate = point.gate(0.5)
    truth = point.read(gate).truth
    # [Oscillating] S15: e = R_r 2 theta_A/(2 b) = 62.5 mm * 2 * 15 deg/(2 * 4 mm) = 4.09
    assert truth["stroke_ratio"].value == pytest.approx(62.5 * 2 * math.radians(15) / 8.0, rel=1e-3)
    assert np.all(np.isfinite(gate.signals["F_T"])) and np.max(np.abs(gate.signals["T_Mo"])) > 0.0


def test_swinging_drive_has_no_quasi_static_form():
    with pytest.raises(ParameterError, match="swinging"):
        make_stand({"swinging_drive": {}, "contact_relaxation": {}}, drive=DriveMode.QUASI_STATIC)


@pytest.mark.parametrize(
    "parameter, value",
    [("amplitude_rad", -0.1), ("amplitude_rad", math.radians(120.0)), ("frequency_Hz", 0.0),
     ("frequency_Hz", -1.0), ("frequency_Hz", 50.0), ("amplitude_rad", math.nan)],
)
def test_invalid_swinging_amplitudes_and_frequencies_are_named_errors(parameter, value):
    """Issue 6, acceptance 4: the swinging drive's amplitude and frequency are range-checked."""
    with pytest.raises(ParameterError, match=parameter):
        make_stand({"swinging_drive": {parameter: value}, "contact_relaxation": {}})
