"""Reading a stand-A log into rig.reduction.stand_a: readings, calibration, the law's domain, options."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rig.errors import ParameterError
from rig.logbook import LogWriter, RunMetadata, read_point, read_reduced, utc_timestamp, write_reduced
from rig.reduction.coefficients import OutsideModelDomain
from rig.stands.base import ContactSpec, DriveMode
from rig.contact.surrogate import TableDomain
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.reduction import point_readings
from tests.stands.yoke import helpers, standin


@pytest.fixture(scope="module")
def logged(tmp_path_factory):
    st = helpers.stand(("dynamometer_noise", "calibration_weight_error"), drive=DriveMode.QUASI_STATIC)
    path = tmp_path_factory.mktemp("log") / "log.h5"
    writer = LogWriter(path, RunMetadata("test", 4, "yoke", utc_timestamp()))
    s = helpers.settings(brake=0.5, force=385.0)
    _, _, out = helpers.run_point(st, s, s, seed=4, gate_time=10.0)
    writer.write_point(out.record, out.truth)
    writer.finalize()
    return st, path, out


def test_readings_come_from_the_record(logged):
    st, path, out = logged
    record = read_point(path, 0)
    g = st.params.geometry_at(1.06e-3)
    r = point_readings(record, st.params, g, "here")
    assert (r.counts_1, r.marks_1) == (record.counters.counters["wheel_1"].count, 60)
    assert r.b_over_a == 2.0  # b/a = 2 at 385 N ([Koziarski])
    assert r.normal_force.value == 385.0 and r.normal_force.u == st.params.normal_force_u_N
    # the balance's 0.049 N step at the 0.4 m arm is a rectangular bias of the mean reading
    # default balance_step_N = 0.098 N: the paper's 0.0196 N m read as a +-limit, u = 0.0196/sqrt(3)
    assert (r.brake_moment.u, r.brake_moment.u_step) == (0.0, pytest.approx(0.0196 / math.sqrt(3)))
    assert r.dynamometer.u_weights == 0.0  # the weights are inside the calibration's covariance
    cal = st.calibration(4)
    assert r.dynamometer.sensitivity == cal.sensitivity
    # calibrated force on the dynamometer x 102/42.5 is the true F_y within the calibration's accuracy
    ratio = 0.102 / 0.0425
    f_y = (r.dynamometer_signal.value - cal.offset) / cal.sensitivity * ratio
    u = float(cal.quantity_standard_uncertainty(np.array([r.dynamometer_signal.value]))[0]) * ratio
    assert f_y == pytest.approx(out.truth["F_y"].value, abs=3 * u)
    assert 0.1 < u < 2.0


def test_coefficients_outside_the_domain_say_why():
    """The reduction turns this error into NaN with the reason (rig.reduction.coefficients)."""
    f = LawCoefficients(standin.coefficients, TableDomain((-1.0, 1.0), (0.0, 0.5), (0.1, 2.0)))
    assert all(math.isfinite(x) for x in f(0.2, 0.1, 0.5))
    with pytest.raises(OutsideModelDomain, match="l/a = 1.2"):
        f(1.2, 0.1, 0.5)
    with pytest.raises(OutsideModelDomain, match="alpha"):
        f(0.2, 0.1, 3.0)


def test_reduce_log_accepts_the_own_laws_a_spec_or_a_callable(logged):
    st, path, _ = logged
    own = st.reduce_log(path)
    other = st.reduce_log(path, ContactSpec("rigid", None, 0.3))
    same = st.reduce_log(path, st.law)
    for frame in (other, same):
        assert frame["mu_v"].iloc[0] == own["mu_v"].iloc[0]
    assert own.index.name == "point" and list(own.index) == [0]
    assert own["mu_v"].iloc[0] == pytest.approx(0.4, abs=3 * own["u_mu_v"].iloc[0])
    with pytest.raises(ParameterError, match="contact_law"):
        st.reduce_log(path, 3.0)


def test_reduced_columns_carry_units_and_truth(logged):
    st, path, _ = logged
    frame = st.reduce_log(path)
    assert list(frame.columns[:8]) == ["l_over_a", "u_l_over_a", "c_over_a", "u_c_over_a", "mu_v", "u_mu_v",
                                       "mu_T", "u_mu_T"]
    assert {"F_y_N", "l_m", "true_l_over_a", "true_mu_T", "reason"} <= set(frame.columns)
    assert np.isfinite(frame["alpha_prime"].iloc[0])
    units = frame.attrs["units"]
    assert (units["l_m"], units["u_F_y_N"], units["omega_1_rad_s"], units["mu_T"], units["reason"]) == (
        "m", "N", "rad/s", "1", "1")
    write_reduced(path, frame)  # the log accepts it: every column named <name>_<unit> or dimensionless
    assert read_reduced(path)["mu_v"].iloc[0] == frame["mu_v"].iloc[0]


def test_instrument_range_problems_invalidate_the_outputs_they_feed(tmp_path):
    # a balance past full scale (25 N at the arm = 10 N m) must not be reduced silently
    st = helpers.stand(drive=DriveMode.QUASI_STATIC, parameters={"balance_arm_m": 0.05})  # 1.25 N m full scale
    path = tmp_path / "log.h5"
    writer = LogWriter(path, RunMetadata("test", 1, "yoke", utc_timestamp()))
    s = helpers.settings(brake=1.3)
    _, _, out = helpers.run_point(st, s, s, gate_time=5.0)
    assert out.record.readings["balance_over_range"].value > 0
    writer.write_point(out.record, out.truth)
    writer.finalize()
    row = st.reduce_log(path).iloc[0]
    assert np.isnan(row["mu_T"]) and np.isnan(row["u_mu_T"]) and "past full scale" in row["reason"]
    assert np.isfinite(row["mu_v"])
