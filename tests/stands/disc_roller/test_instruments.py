"""Stand B's measuring chain: calibrations, seeded streams per (seed, point), independence of points."""

from __future__ import annotations

import numpy as np
import pytest

from rig.stands.disc_roller.instruments import CHANNELS
from sensors import stand_b_dynamometer, stand_b_momentometer
from tests.stands.disc_roller.conftest import make_stand, settings

NOISY = {"loop_compliance": {}, "recorder_noise": {}, "dynamometer_drift": {}}


def test_ideal_calibration_recovers_the_design_sensitivities():
    records = make_stand().calibrate(0)
    assert set(records) == set(CHANNELS)
    # docs/instruments.md: dynamometers 5 -> 25 mV/N, momentometer 8 -> 0.368 V/(N m)
    design = {"F_T": stand_b_dynamometer().nominal_sensitivity_V_per_N,
              "F_V": stand_b_dynamometer().nominal_sensitivity_V_per_N,
              "T_Mo": stand_b_momentometer().nominal_sensitivity_V_per_N_m}
    assert design["F_T"] == pytest.approx(0.025, rel=1e-3) and design["T_Mo"] == pytest.approx(0.368, rel=2e-3)
    for name, record in records.items():
        assert record.sensitivity == pytest.approx(design[name], rel=5e-4), name
        assert abs(record.offset) < 1e-3, name
        assert record.u_sensitivity / record.sensitivity < 0.01  # weights' +-0.098 N on 98 N pieces


def test_calibration_is_once_per_run_and_seeded():
    stand = make_stand(NOISY)
    first = stand.calibrate(3)
    assert stand.calibrate(3)["F_T"] is first["F_T"]  # cached: once per run
    other = make_stand(NOISY).calibrate(4)
    assert other["F_T"].offset != first["F_T"].offset  # another seed, other noise


def read_point(stand, index, previous, seed=9):
    point = stand.start_point(index, settings(l_m=2e-3 * index), previous, seed)
    point.settle(10.0)
    return point.read(point.gate(0.2)).record


def test_a_point_does_not_depend_on_the_points_run_before_it():
    """rig.stands.base: streams from (seed, point index), start from the previous steady state."""
    in_sequence = make_stand(NOISY)
    read_point(in_sequence, 0, None)
    record_seq = read_point(in_sequence, 1, settings(l_m=0.0))
    alone = read_point(make_stand(NOISY), 1, settings(l_m=0.0))
    for name in CHANNELS:
        assert np.array_equal(record_seq.channels[name].samples, alone.channels[name].samples), name
    assert record_seq.calibration == alone.calibration


def test_noise_differs_between_points_and_drift_follows_the_run_clock():
    stand = make_stand(NOISY)
    a = read_point(stand, 1, settings(l_m=0.0))
    b = read_point(stand, 2, settings(l_m=0.0))
    assert b.channels["F_T"].start_time_s - a.channels["F_T"].start_time_s == pytest.approx(60.0, abs=0.5)
    noise_a = np.diff(a.channels["F_V"].samples)
    noise_b = np.diff(b.channels["F_V"].samples)
    assert not np.array_equal(noise_a, noise_b)
    # white noise of 1 uV at the input -> 0.5 mV at the output (docs/instruments.md), ~20 mN of F_V
    assert np.std(a.channels["F_V"].samples) == pytest.approx(5e-4, rel=0.2)
