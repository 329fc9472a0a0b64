"""The Stand contract for stand A: validation, operator order, independence of points, instruments, log."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest

from rig.errors import ParameterError, UnknownNameError
from rig.logbook import LogWriter, RunMetadata, check_log, read_counters, utc_timestamp
from rig.stands.base import DriveMode
from rig.stands.yoke.stand import YokeStand
from sensors import RandomWalkDrift, WhiteNoise
from tests.stands.yoke import helpers


def test_unknown_effect_and_bad_settings_are_named_errors():
    with pytest.raises(UnknownNameError, match="did you mean 'brake_dynamics'"):
        helpers.stand(("brake_dynamic",))
    st = helpers.stand()
    with pytest.raises(ParameterError, match=r"normal_force_N = 5.0 is not valid; valid: \[10, 500\]"):
        st.start_point(0, helpers.settings(force=5.0), None, 1)
    missing = helpers.settings()
    del missing["delta_h_m"]
    with pytest.raises(ParameterError, match="delta_h_m"):
        st.start_point(0, missing, None, 1)
    with pytest.raises(ParameterError, match=r"mu = 2.0 is not valid; valid: \[0.1, 1.2\]"):
        helpers.stand(parameters={"mu": 2.0})


def test_operator_order_is_enforced():
    point = helpers.stand().start_point(0, helpers.settings(), None, 1)
    with pytest.raises(ParameterError, match="settle"):
        point.gate(1.0)


def test_points_are_pure_in_their_arguments():
    # same (index, settings, previous, seed) -> identical records, whichever order or stand instance
    effects = helpers.EFFECTS_ALL
    a, b = helpers.stand(effects), helpers.stand(effects)
    s1, s2 = helpers.settings(brake=0.3), helpers.settings(brake=0.6)
    _, _, second_first = helpers.run_point(b, s2, s1, index=1, seed=5, gate_time=2.0)
    _, _, first = helpers.run_point(a, s1, None, index=0, seed=5, gate_time=2.0)
    _, _, second = helpers.run_point(a, s2, s1, index=1, seed=5, gate_time=2.0)
    assert second.record.readings == second_first.record.readings
    assert second.record.counters == second_first.record.counters
    assert dict(second.truth) == dict(second_first.truth)
    assert first.record.readings != second.record.readings


def test_instrument_effects_off_are_never_called_and_on_change_the_readings():
    s = helpers.settings()
    with mock.patch.object(WhiteNoise, "sample", side_effect=AssertionError("called")), \
            mock.patch.object(RandomWalkDrift, "sample", side_effect=AssertionError("called")):
        st = helpers.stand()
        st.calibrate(1)
        _, _, ideal = helpers.run_point(st, s, s, gate_time=2.0)
    _, _, noisy = helpers.run_point(helpers.stand(helpers.INSTRUMENT_EFFECTS), s, s, gate_time=2.0)
    assert noisy.record.readings["dynamometer_signal"] != ideal.record.readings["dynamometer_signal"]
    assert noisy.truth["F_y"] == ideal.truth["F_y"]  # the truth does not see the instruments


def test_counts_measure_the_true_speeds_within_one_count():
    _, gate, out = helpers.run_point(helpers.stand(), helpers.settings(), helpers.settings(), gate_time=20.0)
    for name, omega in (("wheel_1", "omega_1"), ("wheel_2", "omega_2")):
        expected = out.truth[omega].value * 20.0 * 60 / (2 * np.pi)  # f T, 60 marks per disc [assumed]
        assert abs(out.record.counters.counters[name].count - expected) <= 1.0


def test_zero_counts_in_a_gate_are_reported_not_divided_by(tmp_path):
    # hard case 2: a gate too short for one pulse -> count 0 in the log; the reduction reports NaN + reason
    st = helpers.stand(parameters={"marks_1": 1, "marks_2": 1})
    path = tmp_path / "log.h5"
    writer = LogWriter(path, RunMetadata("test", 1, "yoke", utc_timestamp()))
    _, _, out = helpers.run_point(st, helpers.settings(), helpers.settings(), gate_time=0.01)
    writer.write_point(out.record, out.truth)
    writer.finalize()
    assert read_counters(path)["wheel_2_count"].iloc[0] == 0
    row = st.reduce_log(path).iloc[0]
    assert np.isnan(row["l_over_a"]) and np.isnan(row["mu_T"])
    assert "min_counts" in row["reason"]
    assert np.isfinite(row["F_y_N"])


def test_log_of_a_short_sweep_meets_the_stands_schema(tmp_path):
    st = helpers.stand(helpers.INSTRUMENT_EFFECTS, drive=DriveMode.QUASI_STATIC)
    path = tmp_path / "log.h5"
    writer = LogWriter(path, RunMetadata("test", 2, "yoke", utc_timestamp()))
    previous = None
    for k, brake in enumerate((0.2, 0.5)):
        s = helpers.settings(brake=brake)
        _, _, out = helpers.run_point(st, s, previous, index=k, seed=2, gate_time=5.0)
        writer.write_point(out.record, out.truth)
        previous = s
    writer.finalize()
    assert check_log(path, YokeStand.LOG_SCHEMA) == [0, 1]
    assert set(st.calibrate(2)) == {"dynamometer_10"}
