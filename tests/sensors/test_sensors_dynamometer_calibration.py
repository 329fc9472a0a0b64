"""Dynamometer chain, calibration with weights through a lever, off-effects make no call."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest

from sensors.calibration import (
    STAND_A_LEVER,
    STAND_A_WEIGHTS,
    Lever,
    WeightSet,
    fit_line,
    run_calibration,
    stacking_schedule,
)
from sensors.dynamometer import stand_a_dynamometer
from sensors.errors import InstrumentParameterError
from sensors.noise import RandomWalkDrift, WhiteNoise
from sensors.streams import effect_rng

F_Y_PER_F_DYN = 0.102 / 0.0425  # yoke lever of stand A, Equations §3.1


def test_paper_lever_number():
    # [Koziarski] section 3.1.1: weights to 0.098 N -> (102/42.5) x 0.098 = 0.235 N on F_y
    assert STAND_A_LEVER.quantity(0.098) == pytest.approx(0.2352, abs=5e-5)
    assert STAND_A_LEVER.sensor_input(1.0) == 1.0
    assert STAND_A_WEIGHTS.standard_uncertainty_N == pytest.approx(0.098 / np.sqrt(3))


def test_stacking_schedule():
    a = stacking_schedule(3)
    assert a.tolist() == [[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 1, 0], [1, 0, 0], [0, 0, 0]]


def test_ideal_dynamometer_matches_analytic_chain():
    # 50 ue/N * (full bridge: 5 V * 2 per unit strain) * gain 500 = 0.25 V/N
    dyn = stand_a_dynamometer()
    assert dyn.nominal_sensitivity_V_per_N == pytest.approx(0.25)
    force = np.linspace(-30.0, 30.0, 601)
    r = dyn.read(np.arange(force.size) * 1e-3, force)
    assert r.n_clipped == 0
    assert np.max(np.abs(r.volts - 0.25 * force)) <= dyn.adc.lsb_V / 2 * (1 + 1e-9)


def test_overrange_is_reported_and_overload_raises():
    dyn = stand_a_dynamometer()
    r = dyn.read(np.array([0.0, 1.0]), np.array([10.0, 45.0]))  # 45 N -> 11.25 V > 10 V
    assert r.clipped.tolist() == [False, True]
    with pytest.raises(InstrumentParameterError, match="force_N"):
        dyn.read(np.array([0.0]), np.array([250.0]))  # strain 1.25 % > 1 %


def test_noise_level_when_on():
    dyn = stand_a_dynamometer(noise_rng=np.random.default_rng(4))
    r = dyn.read(np.arange(20_000) * 1e-3, np.full(20_000, 3.0))
    expected = np.hypot(500 * 1e-6, dyn.adc.lsb_V / np.sqrt(12))  # gain * input noise (+) quantisation
    assert r.volts.std() == pytest.approx(expected, rel=0.05)


def test_off_effects_make_no_call():
    with mock.patch.object(WhiteNoise, "sample", side_effect=AssertionError("noise called")) as noise, \
         mock.patch.object(RandomWalkDrift, "sample", side_effect=AssertionError("drift called")) as drift:
        dyn = stand_a_dynamometer()
        dyn.read(np.arange(10.0), np.ones(10))
        run_calibration(dyn.read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    assert noise.call_count == 0 and drift.call_count == 0


def test_on_effects_are_called():
    with mock.patch.object(WhiteNoise, "sample", return_value=np.zeros(10)) as noise:
        stand_a_dynamometer(noise_rng=np.random.default_rng(0)).read(np.arange(10.0), np.ones(10))
    assert noise.call_count == 1


def test_fit_line_textbook_covariance():
    # no weight uncertainty: Cov = s^2_res (X^T X)^-1, s^2_res = RSS/(n - 2)
    q = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    y = 2.0 * q + 0.5 + np.array([0.01, -0.02, 0.0, 0.02, -0.01])
    rec = fit_line(q, y, np.zeros((5, 5)), quantity_name="F", quantity_unit="N")
    x = np.column_stack([q, np.ones(5)])
    beta, rss, *_ = np.linalg.lstsq(x, y, rcond=None)
    cov = rss[0] / 3 * np.linalg.inv(x.T @ x)
    assert rec.sensitivity == pytest.approx(beta[0]) and rec.offset == pytest.approx(beta[1])
    np.testing.assert_allclose(np.array(rec.covariance), cov, rtol=1e-10)
    assert rec.residual_std == pytest.approx(np.sqrt(rss[0] / 3))


def test_ideal_calibration_recovers_true_sensitivity_and_force():
    dyn = stand_a_dynamometer()
    rec = run_calibration(dyn.read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    true_s = dyn.nominal_sensitivity_V_per_N / F_Y_PER_F_DYN  # V per N of F_y
    assert rec.sensitivity == pytest.approx(true_s, rel=5e-4)
    # the reported uncertainty is the weights' (an ideal rig does not know its weights are exact)
    assert rec.u_sensitivity / rec.sensitivity == pytest.approx(0.01, rel=0.5)
    f_y = np.linspace(-20.0, 20.0, 81)
    reading = dyn.read(np.arange(f_y.size) * 0.01, f_y / F_Y_PER_F_DYN)
    resolution = dyn.adc.lsb_V / rec.sensitivity
    assert np.max(np.abs(rec.to_quantity(reading) - f_y)) < 2 * resolution + abs(rec.offset) / rec.sensitivity + 2e-3


def test_clipped_reading_converts_to_nan():
    dyn = stand_a_dynamometer()
    rec = run_calibration(dyn.read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    q = rec.to_quantity(dyn.read(np.array([0.0, 1.0]), np.array([1.0, 50.0])))
    assert np.isfinite(q[0]) and np.isnan(q[1])


def test_calibration_that_clips_raises():
    heavy = WeightSet((20.0,) * 3)  # 60 N on the dynamometer -> 15 V
    with pytest.raises(InstrumentParameterError, match="weights"):
        run_calibration(stand_a_dynamometer().read, STAND_A_LEVER, heavy, quantity_name="F_y")


def _coverage(make_dyn, weights, repeats, seed):
    z_s, z_o = [], []
    for i in range(repeats):
        dyn = make_dyn(i)
        rec = run_calibration(dyn.read, STAND_A_LEVER, weights, quantity_name="F_y", dwell_s=0.5,
                              weight_error_rng=effect_rng(seed, f"weights{i}", "error"))
        true_s = dyn.nominal_sensitivity_V_per_N / F_Y_PER_F_DYN
        z_s.append((rec.sensitivity - true_s) / rec.u_sensitivity)
        z_o.append(rec.offset / rec.u_offset)
    return np.abs(np.array(z_s)), np.abs(np.array(z_o))


def test_coverage_weights_dominated():
    # stand A defaults: weight errors (uniform +-0.098 N per piece) dominate the reading noise
    # Expected coverage of this linear combination of uniform errors (numpy Monte Carlo of the model
    # alone): slope 66.8 % / 95.8 %, offset 64.8 % / 96.8 %. The residual-based sigma can only add,
    # so the offset (sensitive to it, its zero-load steps carry no weight error) may over-cover.
    z_s, z_o = _coverage(lambda i: stand_a_dynamometer(noise_rng=effect_rng(1, f"dyn{i}", "noise")),
                         STAND_A_WEIGHTS, 400, 11)
    assert 0.60 <= np.mean(z_s < 1.0) <= 0.74
    assert 0.93 <= np.mean(z_s < 2.0) <= 0.985
    assert 0.58 <= np.mean(z_o < 1.0) <= 0.78
    assert 0.93 <= np.mean(z_o < 2.0) <= 1.0


def test_coverage_noise_dominated():
    # exact weights, large amplifier noise: sigma comes from the residuals (9 degrees of freedom, t-like)
    exact = WeightSet(STAND_A_WEIGHTS.nominal_N, error_bound_N=0.0)

    def make(i):
        dyn = stand_a_dynamometer()
        noise = WhiteNoise(2e-4, effect_rng(2, f"dyn{i}", "noise"))
        return type(dyn)(dyn.strain_per_newton, dyn.bridge, type(dyn.amplifier)(dyn.amplifier.gain, noise=noise),
                         dyn.adc)

    z_s, z_o = _coverage(make, exact, 400, 12)
    for z in (z_s, z_o):
        assert 0.60 <= np.mean(z < 1.0) <= 0.78
        assert 0.88 <= np.mean(z < 2.0) <= 0.98  # t_9: 92.4 %


def test_scaled_record_converts_consistently():
    dyn = stand_a_dynamometer()
    direct = run_calibration(dyn.read, Lever(0.102, 0.102, 0.102), STAND_A_WEIGHTS, quantity_name="F_dyn")
    via_yoke = run_calibration(dyn.read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    scaled = direct.scaled(F_Y_PER_F_DYN, "F_y", "N")
    assert scaled.sensitivity == pytest.approx(via_yoke.sensitivity, rel=1e-12)
    assert scaled.u_sensitivity == pytest.approx(via_yoke.u_sensitivity, rel=1e-9)
    v = np.array([0.3, 2.0])
    np.testing.assert_allclose(scaled.to_quantity(v), F_Y_PER_F_DYN * direct.to_quantity(v))
    np.testing.assert_allclose(scaled.quantity_standard_uncertainty(v),
                               F_Y_PER_F_DYN * direct.quantity_standard_uncertainty(v))


def test_rezeroing_removes_drift_offset():
    dyn = stand_a_dynamometer(drift_rng=effect_rng(5, "dyn", "drift"))
    rec = run_calibration(dyn.read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    t = 3600.0 * 4 + np.arange(200) * 0.01  # four hours later the zero has wandered
    zero = dyn.read(t, np.zeros(t.size)).volts
    loaded = dyn.read(t + 5.0, np.full(t.size, 5.0 / F_Y_PER_F_DYN))
    stale = np.mean(rec.to_quantity(loaded)) - 5.0
    fresh = np.mean(rec.with_zero(zero).to_quantity(loaded)) - 5.0
    assert abs(stale) > 0.02  # ~ gain * 0.1 uV/sqrt(s) * 120 sqrt(s) / 0.104 V/N ~ 0.06 N
    assert abs(fresh) < 0.2 * abs(stale)


def test_record_as_dict_has_units():
    rec = run_calibration(stand_a_dynamometer().read, STAND_A_LEVER, STAND_A_WEIGHTS, quantity_name="F_y")
    d = rec.as_dict()
    assert d["sensitivity"][1] == "V/N" and d["offset"][1] == "V" and d["n_steps"] == (11, "1")
