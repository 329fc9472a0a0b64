"""Tangent balance, torsion-shaft momentometer and the signal recorder."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest

from sensors.balance import STAND_A_ARM_M, STEP_IF_ACCURACY_IS_STEP_N, TangentBalance, stand_a_balance
from sensors.calibration import TorqueArm, WeightSet, run_calibration
from sensors.momentometer import stand_b_momentometer
from sensors.noise import RandomWalkDrift, WhiteNoise
from sensors.recorder import Recorder
from sensors.streams import effect_rng


def test_balance_arm_and_resolution_from_paper():
    # [Koziarski] section 3.1.1: 0.049 N at the arm <-> 0.0196 N m  =>  arm 0.400 m
    assert STAND_A_ARM_M == pytest.approx(0.400)
    b = stand_a_balance()
    # default: "accuracy 0.049 N" read as a +-limit -> step 0.098 N, u(T2) = 0.0196/sqrt(3) = 0.0113 N m
    assert b.resolution_N_m == pytest.approx(2 * 0.0196)
    assert b.resolution_standard_uncertainty_N_m == pytest.approx(0.0196 / np.sqrt(3))
    assert b.resolution_standard_uncertainty_N_m == pytest.approx(0.0113, abs=1e-4)
    step = TangentBalance(resolution_N=STEP_IF_ACCURACY_IS_STEP_N)  # read as the scale step
    assert step.resolution_standard_uncertainty_N_m == pytest.approx(0.0057, abs=1e-4)


def test_balance_reading_hand_number():
    # T = 1 N m -> 2.5 N at 0.4 m -> 25.51 steps of 0.098 N -> 26 steps -> 1.0192 N m
    r = stand_a_balance().read(1.0)
    assert r.moment_N_m[0] == pytest.approx(26 * 0.098 * 0.4)
    assert not r.over_range[0]


def test_ideal_balance_within_half_step_and_uniform_error():
    b = stand_a_balance()
    true = np.random.default_rng(3).uniform(-7.0, 7.0, 50_000)
    err = b.read(true).moment_N_m - true
    assert np.max(np.abs(err)) <= b.resolution_N_m / 2 * (1 + 1e-9)
    assert err.std() == pytest.approx(b.resolution_standard_uncertainty_N_m, rel=0.02)


def test_balance_over_range_flagged():
    r = stand_a_balance().read(np.array([9.0, 11.0, -12.0]))  # full scale 25 N * 0.4 m = 10 N m
    assert r.over_range.tolist() == [False, True, True]
    assert r.moment_N_m[1] == pytest.approx(np.rint(25.0 / 0.098) * 0.098 * 0.4)


def test_balance_noise_off_no_call_on_scatter():
    with mock.patch.object(WhiteNoise, "sample", side_effect=AssertionError("called")):
        stand_a_balance().read(np.ones(4))
    noisy = stand_a_balance(noise_rng=np.random.default_rng(8)).read(np.full(20_000, 2.0))
    # 0.01 N scatter (+) the step's uniform error, in moment
    assert noisy.moment_N_m.std() > 0.0
    assert noisy.moment_N_m.mean() == pytest.approx(2.0, abs=0.0196 / 2)


def test_momentometer_strain_and_stiffness():
    m = stand_b_momentometer()
    # tau = 16 T/(pi d^3), eps45 = tau/(2G): 10 N m on d = 12 mm, G = 80 GPa -> 1.8420e-4
    assert m.strain(np.array([10.0]))[0] == pytest.approx(80.0 / (np.pi * 0.012**3 * 80e9), rel=1e-12)
    assert m.strain(np.array([10.0]))[0] == pytest.approx(1.8420e-4, rel=1e-4)
    # k_m = G pi d^4/(32 L) = 3257 N m/rad, inside Equations §4.2's 2e3...1e4 N m/rad
    assert m.torsional_stiffness_N_m_per_rad == pytest.approx(3257.2, rel=1e-4)
    assert 2e3 <= m.torsional_stiffness_N_m_per_rad <= 1e4
    assert m.nominal_sensitivity_V_per_N_m == pytest.approx(1.8420e-5 * 10 * 2000, rel=1e-4)


def test_recorder_sample_times_and_ideal_record():
    rec = Recorder(sample_rate_Hz=500.0)
    assert rec.sample_times(0.0, 1.0).size == 501
    m = stand_b_momentometer()
    t = np.linspace(0.0, 2.0, 2001)
    torque = 15.0 * np.sin(2 * np.pi * 0.7 * t)
    r = rec.record(t, torque, m)
    assert r.time_s.size == 1001 and r.n_clipped == 0
    expected = m.nominal_sensitivity_V_per_N_m * np.interp(r.time_s, t, torque)
    assert np.max(np.abs(r.volts - expected)) <= rec.adc.lsb_V / 2 * (1 + 1e-9)


def test_momentometer_calibration_with_torque_arm():
    m = stand_b_momentometer(noise_rng=effect_rng(3, "momentometer_8", "noise"))
    rec = Recorder()
    weights = WeightSet((9.80665,) * 4, error_bound_N=0.0098)  # 1 kg pieces to 1 gf on a 0.5 m arm
    cal = run_calibration(rec.reader(m), TorqueArm(0.5), weights, quantity_name="T_Mo",
                          sample_rate_Hz=rec.sample_rate_Hz)
    assert cal.quantity_unit == "N m"
    assert abs(cal.sensitivity - m.nominal_sensitivity_V_per_N_m) < 3 * cal.u_sensitivity
    assert cal.u_sensitivity / cal.sensitivity < 1e-3


def test_momentometer_off_effects_make_no_call():
    with mock.patch.object(WhiteNoise, "sample", side_effect=AssertionError), \
         mock.patch.object(RandomWalkDrift, "sample", side_effect=AssertionError):
        Recorder().record(np.array([0.0, 1.0]), np.array([1.0, 2.0]), stand_b_momentometer())


def test_balance_is_a_parameter_set():
    b = TangentBalance(arm_m=0.25, resolution_N=0.01)
    assert b.resolution_N_m == pytest.approx(0.0025)
